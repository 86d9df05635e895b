#include "export_size_dialog.h"

#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QPushButton>

namespace lb {

ExportSizeDialog::ExportSizeDialog(QSize initial, QWidget *parent) : QDialog(parent)
{
    setWindowTitle(tr("Export Image"));
    auto *form = new QFormLayout(this);
    auto spin = [this](int value) {
        auto *box = new IntegerBox(this);
        box->setRange(1, kMaxSide);
        //: pixels, after the number
        box->setSuffix(tr(" px"));
        box->setValue(value);
        return box;
    };
    m_width = spin(initial.width());
    m_height = spin(initial.height());
    form->addRow(tr("Width"), m_width);
    form->addRow(tr("Height"), m_height);
    form->addRow(new QLabel(tr("The view is drawn again at this size, not scaled."), this));
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    buttons->button(QDialogButtonBox::Ok)->setText(tr("Choose File..."));
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    form->addRow(buttons);
}

void ExportSizeDialog::accept()
{
    if (m_width->takeTyped() && m_height->takeTyped())
        QDialog::accept();
}

QSize ExportSizeDialog::size() const
{
    return QSize(m_width->value(), m_height->value());
}

} // namespace lb
