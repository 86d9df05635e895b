#include "lesson_pointer.h"

#include "color_edit.h"
#include "editor_panel.h"
#include "light_panel.h"
#include "main_window.h"
#include "material_panel.h"
#include "object_panel.h"
#include "shading_panel.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QMap>
#include <QSlider>

namespace lb {

QDockWidget *lessonPanelDock(const MainWindow &window, const QString &panel)
{
    if (panel == "editor")
        return window.editorDock();
    static const QMap<QString, QString> docks{
        {"light", "lightDock"},      {"material", "materialDock"}, {"shading", "shadingDock"},
        {"object", "objectDock"},    {"scene", "objectDock"},      {"probe", "probeDock"},
        {"exercise", "exerciseDock"}};
    const QString name = docks.value(panel);
    for (QDockWidget *dock : window.panelDocks())
        if (!name.isEmpty() && dock->objectName() == name)
            return dock;
    return nullptr;
}

QString lessonHighlightPanel(const QString &highlight)
{
    return highlight.section('.', 0, 0).replace("compare", "shading");
}

std::vector<QWidget *> lessonHighlightControls(const MainWindow &window, const QString &highlight)
{
    const LightPanel *light = window.lightPanel();
    const MaterialPanel *material = window.materialPanel();
    const ShadingPanel *shading = window.shadingPanel();
    const ObjectPanel *object = window.objectPanel();
    if (highlight == "light.position")
        return {light->coordinate(0), light->coordinate(1), light->coordinate(2)};
    if (highlight == "light.w")
        return {light->wCombo()};
    if (highlight == "light.frame")
        return {light->frameCombo()};
    if (highlight == "light.colours")
        return {light->colorEdit(0), light->colorEdit(1), light->colorEdit(2)};
    if (highlight == "material")
        return {window.materialPanel()};
    if (highlight == "material.shininess")
        return {material->shininessSlider(), material->shininessBox()};
    if (highlight == "shading.shading")
        return {shading->shadingCombo()};
    if (highlight == "shading.specular")
        return {shading->specularCombo()};
    if (highlight == "shading.projection")
        return {shading->projectionCombo()};
    if (highlight == "shading.terms")
        return {shading->termCheck(0), shading->termCheck(1), shading->termCheck(2)};
    if (highlight == "compare")
        return {shading->compareModeCombo()};
    if (highlight == "object.transform") {
        std::vector<QWidget *> boxes;
        for (int i = 0; i < 3; ++i)
            boxes.insert(boxes.end(),
                         {object->rotation(i), object->scale(i), object->translation(i)});
        return boxes;
    }
    if (highlight == "editor")
        return {window.editorPanel()};
    return {};
}

} // namespace lb
