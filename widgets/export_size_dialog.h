#pragma once
// Export Image's question: how many pixels wide and high (the viewport's size to start with).

#include <QDialog>
#include <QSize>

class QSpinBox;

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

private:
    QSpinBox *m_width;
    QSpinBox *m_height;
};

} // namespace lb
