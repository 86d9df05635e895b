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

} // namespace lb
