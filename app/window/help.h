#pragma once
// Help: every shortcut of the window (read from its menus, so the list cannot go stale),
// the keys of the editor and the view's mouse, the About box, and the README's features.

#include <QString>

class QMenuBar;
class QWidget;

namespace lb {

// The shortcuts as an HTML table: each menu's actions with their keys, then the editor's and
// the view's own keys and mouse.
QString shortcutsHtml(const QMenuBar *menus);
// Non-modal windows that stay open beside the workbench.
void showShortcuts(QWidget *parent, const QMenuBar *menus);
void showFeatures(QWidget *parent); // README.md, as built into the program
void showAbout(QWidget *parent, const QString &glInfo);

} // namespace lb
