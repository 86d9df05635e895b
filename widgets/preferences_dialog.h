#pragma once
// Edit > Preferences: the import helper's memory and time limits, the frame budget a user's
// program must keep (program_trial.h), and whether a lesson's steps move the camera and the
// lights smoothly.

#include "import_process.h"
#include "number_box.h"

#include <QDialog>

class QCheckBox;

namespace lb {

class PreferencesDialog : public QDialog
{
    Q_OBJECT
public:
    static constexpr double kDefaultFrameBudgetSeconds = 1.0;
    PreferencesDialog(const ImportLimits &limits, double frameBudgetSeconds,
                      QWidget *parent = nullptr);
    ImportLimits limits() const;
    double frameBudgetSeconds() const;
    QSpinBox *memoryBox() const { return m_memory; }
    QSpinBox *timeBox() const { return m_time; }
    // A lesson's step glides the camera and the lights to their places (~400 ms) or jumps.
    void setAnimateLessons(bool on);
    bool animateLessons() const;
    QCheckBox *animateLessonsCheck() const { return m_animateLessons; }

    void accept() override; // not while a box holds a number it would not take

private:
    void showLimits(const ImportLimits &limits);

    IntegerBox *m_memory;
    IntegerBox *m_time;
    NumberBox *m_budget;
    QCheckBox *m_animateLessons;
};

} // namespace lb
