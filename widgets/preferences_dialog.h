#pragma once
// Edit > Preferences: the import helper's memory and time limits.

#include "import_process.h"

#include <QDialog>

class QSpinBox;

namespace lb {

class PreferencesDialog : public QDialog
{
    Q_OBJECT
public:
    explicit PreferencesDialog(const ImportLimits &limits, QWidget *parent = nullptr);
    ImportLimits limits() const;
    QSpinBox *memoryBox() const { return m_memory; }
    QSpinBox *timeBox() const { return m_time; }

private:
    void showLimits(const ImportLimits &limits);

    QSpinBox *m_memory;
    QSpinBox *m_time;
};

} // namespace lb
