#include "message_box.h"

namespace lb {

void showFileMessage(QPointer<QMessageBox> &box, QWidget *parent, QMessageBox::Icon icon,
                     const QString &title, const QString &text, const QString &details)
{
    if (box)
        box->close();
    box = new QMessageBox(icon, title, text, QMessageBox::Ok, parent);
    box->setInformativeText(details);
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->setWindowModality(Qt::NonModal);
    box->show();
}

} // namespace lb
