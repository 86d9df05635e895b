#pragma once
// The window's messages about files (scenes, lessons, meshes): not modal, so the window stays
// usable behind them, and one of each kind at a time (a new one replaces the one shown).
#include <QMessageBox>
#include <QPointer>

namespace lb {

// Closes `box` if it is shown and puts a new message there; it deletes itself when closed.
void showFileMessage(QPointer<QMessageBox> &box, QWidget *parent, QMessageBox::Icon icon,
                     const QString &title, const QString &text, const QString &details);

} // namespace lb
