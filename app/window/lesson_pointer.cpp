#include "lesson_pointer.h"

#include "color_edit.h"
#include "editor_panel.h"
#include "light_panel.h"
#include "main_window.h"
#include "material_panel.h"
#include "object_panel.h"
#include "shading_panel.h"
#include "texture_controls.h"

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QMap>
#include <QRegularExpression>
#include <QSlider>

namespace lb {

QDockWidget *lessonPanelDock(const MainWindow &window, const QString &panel)
{
    if (panel == "editor")
        return window.editorDock();
    static const QMap<QString, QString> docks{
        {"light", "lightDock"},       {"material", "materialDock"}, {"shading", "shadingDock"},
        {"object", "objectDock"},     {"scene", "objectDock"},      {"probe", "probeDock"},
        {"exercise", "exerciseDock"}, {"uniforms", "uniformDock"},  {"bindings", "bindingDock"},
        {"plots", "plotsDock"}};
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

namespace {

// A label as it reads: its mnemonic marks gone ("Chec&k" is "Check", "&&" one "&").
QString shownText(QString text)
{
    text.replace(QLatin1String("&&"), QChar(0x1));
    text.remove(QLatin1Char('&'));
    return text.replace(QChar(0x1), QLatin1Char('&'));
}

QString controlName(const MainWindow &window, const QString &name)
{
    if (const QDockWidget *dock = lessonPanelDock(window, name))
        return dock->windowTitle();
    if (name == "check") {
        const QAction *check = window.checkAction();
        if (!check)
            return {};
        const QString key = check->shortcut().toString(QKeySequence::NativeText);
        return key.isEmpty() ? shownText(check->text())
                             : QString("%1 (%2)").arg(shownText(check->text()), key);
    }
    const QCheckBox *box = nullptr;
    if (name == "object.texture")
        box = window.objectPanel()->texture()->textureCheck();
    else if (name == "shading.normalsByModelView")
        box = window.shadingPanel()->normalsByModelViewCheck();
    else if (name == "shading.lighting")
        box = window.shadingPanel()->lightingCheck();
    else if (name == "shading.vertexColors")
        box = window.shadingPanel()->vertexColorsCheck();
    return box ? shownText(box->text()) : QString();
}

} // namespace

QString withControlNames(const MainWindow &window, const QString &caption)
{
    static const QRegularExpression placeholder(QStringLiteral("\\{ui:([A-Za-z.]+)\\}"));
    QString out;
    qsizetype from = 0;
    for (QRegularExpressionMatchIterator it = placeholder.globalMatch(caption); it.hasNext();) {
        const QRegularExpressionMatch m = it.next();
        const QString name = controlName(window, m.captured(1));
        out += caption.mid(from, m.capturedStart() - from);
        out += name.isEmpty() ? m.captured(0) : name;
        from = m.capturedEnd();
    }
    return out + caption.mid(from);
}

} // namespace lb
