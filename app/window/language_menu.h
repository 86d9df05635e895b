#pragma once
// View > Language (the languages themselves: common/language.h).

#include <QSettings>

class QMenu;
class QWidget;

namespace lb {

// View > Language: the four choices, the current one checked. Choosing another keeps it in
// the settings and offers to restart; when accepted, `window` is closed (asking about
// unsaved work as always) and restartRequested() turns true, for main() to start a new one.
void addLanguageMenu(QMenu *view, QSettings &settings, QWidget *window);
bool restartRequested();
// Starts lightbench again, detached, with no arguments: the new one restores the session.
bool restartApplication();

} // namespace lb
