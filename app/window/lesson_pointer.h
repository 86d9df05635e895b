#pragma once
// Where a lesson's step points: the dock its "panel" brings forward, and the controls its
// "highlight" frames (lesson.h lists both as files write them).

#include <QString>

#include <vector>

class QDockWidget;
class QWidget;

namespace lb {

class MainWindow;

// The dock of `panel` (light, material, shading, object, scene, editor, probe, exercise);
// null for none or an unknown one. "scene" is the Object dock: the scene's list of objects.
QDockWidget *lessonPanelDock(const MainWindow &window, const QString &panel);
// The controls `highlight` names (light.position, material.shininess, ...); empty when unknown.
std::vector<QWidget *> lessonHighlightControls(const MainWindow &window, const QString &highlight);
// The panel a highlight lives in, brought forward with it ("light.frame": light).
QString lessonHighlightPanel(const QString &highlight);
// A caption with each {ui:NAME} written as the window labels that control now, in the
// window's language, so that a caption names what is on screen: a panel (light, material,
// shading, object, uniforms, bindings, probe, plots, exercise, editor: the dock's title),
// "check" (Check My Work with its key), "object.texture", "shading.normalsByModelView",
// "shading.lighting", "shading.vertexColors". An unknown NAME is left as it is written.
QString withControlNames(const MainWindow &window, const QString &caption);

} // namespace lb
