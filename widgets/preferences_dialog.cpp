#include "preferences_dialog.h"

#include <QCheckBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QPushButton>

namespace lb {

PreferencesDialog::PreferencesDialog(const ImportLimits &limits, double frameBudgetSeconds,
                                     QWidget *parent)
    : QDialog(parent)
{
    setWindowTitle(tr("Preferences"));
    auto *form = new QFormLayout(this);
    auto *intro = new QLabel(tr("Mesh files are read by a helper process (lightbench-import). "
                                "When it needs more memory or time than this, it is stopped "
                                "and the file gets a message; the workbench carries on."),
                             this);
    intro->setWordWrap(true);
    form->addRow(intro);

    m_memory = new IntegerBox(this);
    m_memory->setRange(64, int(std::min<qint64>(ImportLimits::defaultMemoryMB() * 2, 1 << 30)));
    m_memory->setSingleStep(256);
    //: megabytes, after the number
    m_memory->setSuffix(tr(" MB"));
    m_memory->setToolTip(tr("The helper's address-space limit. Default: half of this machine's "
                            "memory (%1 MB). Also --import-memory-limit MB")
                             .arg(ImportLimits::defaultMemoryMB()));
    form->addRow(tr("Import memory limit"), m_memory);

    m_time = new IntegerBox(this);
    m_time->setRange(1, 3600);
    //: seconds, after the number
    m_time->setSuffix(tr(" s"));
    m_time->setToolTip(
        tr("A load that takes longer is stopped. Default: %1 s").arg(ImportLimits{}.seconds));
    form->addRow(tr("Import time limit"), m_time);

    m_budget = new NumberBox(this);
    m_budget->setRange(0.05, 60.0);
    m_budget->setDecimals(2);
    m_budget->setSingleStep(0.25);
    m_budget->setSuffix(tr(" s"));
    m_budget->setToolTip(tr("Your shader program is tried on tiny frames before it draws; when "
                            "one frame at the view's size would take longer than this, it is "
                            "refused and the last good program keeps drawing. Default: %1 s. "
                            "Also --frame-budget SECONDS")
                             .arg(kDefaultFrameBudgetSeconds));
    m_budget->setValue(frameBudgetSeconds);
    form->addRow(tr("Frame budget"), m_budget);

    m_animateLessons = new QCheckBox(tr("Move the camera and the lights smoothly between a "
                                        "lesson's steps"),
                                     this);
    m_animateLessons->setChecked(true);
    m_animateLessons->setToolTip(tr("So the class sees where they go; off: each step jumps"));
    form->addRow(m_animateLessons);

    auto *buttons = new QDialogButtonBox(
        QDialogButtonBox::Ok | QDialogButtonBox::Cancel | QDialogButtonBox::RestoreDefaults, this);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(buttons->button(QDialogButtonBox::RestoreDefaults), &QPushButton::clicked, this,
            [this] {
                showLimits(ImportLimits{});
                m_budget->setValue(kDefaultFrameBudgetSeconds);
                m_animateLessons->setChecked(true);
            });
    form->addRow(buttons);
    showLimits(limits);
}

void PreferencesDialog::accept()
{
    if (m_memory->takeTyped() && m_time->takeTyped() && m_budget->takeTyped())
        QDialog::accept();
}

void PreferencesDialog::showLimits(const ImportLimits &limits)
{
    m_memory->setValue(int(limits.memoryMB));
    m_time->setValue(limits.seconds);
}

void PreferencesDialog::setAnimateLessons(bool on)
{
    m_animateLessons->setChecked(on);
}

bool PreferencesDialog::animateLessons() const
{
    return m_animateLessons->isChecked();
}

double PreferencesDialog::frameBudgetSeconds() const
{
    return m_budget->value();
}

ImportLimits PreferencesDialog::limits() const
{
    ImportLimits l;
    l.memoryMB = m_memory->value();
    l.seconds = m_time->value();
    return l;
}

} // namespace lb
