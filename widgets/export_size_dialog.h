#pragma once
// Export Image's question: how many pixels wide and high (the viewport's size to start with).

#include "number_box.h"

#include <QDialog>
#include <QSize>

namespace lb {

class ExportSizeDialog : public QDialog
{
    Q_OBJECT
public:
    static constexpr int kMaxSide = 8192;
    ExportSizeDialog(QSize initial, QWidget *parent = nullptr);
    QSize size() const;
    QSpinBox *widthBox() const { return m_width; }
    QSpinBox *heightBox() const { return m_height; }
    void accept() override; // not while a box holds a number it would not take

private:
    IntegerBox *m_width;
    IntegerBox *m_height;
};

} // namespace lb
