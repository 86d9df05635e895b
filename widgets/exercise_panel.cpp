#include "exercise_panel.h"

#include "choice_labels.h"
#include "message_text.h"
#include "program_trial.h"

#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QTreeWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace lb {

namespace {

// The hint's box: yellow and bold, greyed with the cases once the program is edited.
QString hintStyle(bool outOfDate)
{
    return outOfDate ? QStringLiteral("background-color: #f2f2f2; color: #808080; "
                                      "border: 1px solid #c8c8c8;")
                     : QStringLiteral("background-color: #fff4c2; color: #3d3000; "
                                      "border: 1px solid #d9b84a; font-weight: bold;");
}

// What a case may vary, in the panel's words (exercise.h's Vary, in its order).
QString variedText(unsigned vary)
{
    // The panel's context (not QObject's): a translator finds them beside the sentence
    // they go into ("The cases vary: %6.").
    const QStringList words{
        ExercisePanel::tr("light position"), ExercisePanel::tr("point or directional"),
        ExercisePanel::tr("light frame"),    ExercisePanel::tr("light colours"),
        ExercisePanel::tr("material"),       ExercisePanel::tr("camera"),
        ExercisePanel::tr("projection"),     ExercisePanel::tr("non-uniform scale")};
    QStringList varied;
    for (int i = 0; i < words.size(); ++i)
        if (vary & (1u << i))
            varied << words[i];
    return varied.isEmpty() ? ExercisePanel::tr("nothing (every case is the scene as it is)")
                            : varied.join(", ");
}

QString percent(double share)
{
    // Rounded down: 98.96% is not 99.0%, nor 99.96% 100% (a failed case must not read as
    // reaching its pass share).
    return QString("%1%").arg(std::floor(1000.0 * std::clamp(share, 0.0, 1.0)) / 10.0, 0, 'f', 1);
}

} // namespace

ExercisePanel::ExercisePanel(QWidget *parent) : QWidget(parent)
{
    auto *layout = new QVBoxLayout(this);
    m_title = new QLabel(this);
    m_title->setWordWrap(true);
    m_title->setTextFormat(Qt::PlainText);
    QFont bold = m_title->font();
    bold.setBold(true);
    m_title->setFont(bold);
    m_task = new QLabel(this);
    m_task->setWordWrap(true);
    m_task->setTextFormat(Qt::PlainText);
    m_task->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_about = new QLabel(this);
    m_about->setWordWrap(true);
    m_about->setTextFormat(Qt::PlainText);
    m_about->setForegroundRole(QPalette::PlaceholderText);
    m_check = new QPushButton(tr("Check my work"), this);
    m_check->setToolTip(tr("Draws the exercise's cases with the program in the editor and with "
                           "the reference, as the teacher's grading does, and lists each case "
                           "(F9)"));
    connect(m_check, &QPushButton::clicked, this,
            [this] { emit(m_checking ? cancelRequested() : checkRequested()); });
    m_summary = new QLabel(this);
    m_summary->setWordWrap(true);
    m_summary->setTextFormat(Qt::PlainText);
    m_summary->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_stale = new QLabel(tr("Out of date: the program in the editor has changed since this "
                            "check. Check my work (F9) checks it as it is now."),
                         this);
    m_stale->setWordWrap(true);
    m_stale->setStyleSheet("color: #b35900; font-weight: bold;");
    m_stale->hide();
    // Above the cases, where a student looks first: what their picture matches, in words.
    m_hint = new QLabel(this);
    m_hint->setWordWrap(true);
    m_hint->setTextFormat(Qt::PlainText);
    m_hint->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_hint->setMargin(6);
    m_hint->setStyleSheet(hintStyle(false));
    m_hint->hide();
    m_cases = new QTreeWidget(this);
    m_cases->setColumnCount(4);
    m_cases->setHeaderLabels({tr("Case"), tr("Result"), tr("Largest"), tr("Within")});
    m_cases->headerItem()->setToolTip(2, tr("The largest difference of a channel, out of 255"));

    m_cases->setRootIsDecorated(false);
    m_cases->setUniformRowHeights(true);
    m_cases->setMinimumWidth(10); // the dock's width decides; the columns scroll
    // Eight cases in view at least: in a short dock the panel scrolls, not the list alone.
    m_cases->setMinimumHeight(m_cases->fontMetrics().height() * 11);
    m_cases->header()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_cases->setToolTip(tr("Click a case to see it in the difference view"));
    connect(m_cases, &QTreeWidget::itemClicked, this, [this](QTreeWidgetItem *item) {
        emit caseChosen(item->data(0, Qt::UserRole).toInt());
    });
    connect(m_cases, &QTreeWidget::itemActivated, this, [this](QTreeWidgetItem *item) {
        emit caseChosen(item->data(0, Qt::UserRole).toInt());
    });
    m_back = new QPushButton(tr("Back to my scene"), this);
    m_back->setToolTip(tr("The scene as it was before a case was shown"));
    m_back->setEnabled(false);
    connect(m_back, &QPushButton::clicked, this, &ExercisePanel::backRequested);

    layout->addWidget(m_title);
    layout->addWidget(m_task);
    layout->addWidget(m_about);
    layout->addWidget(m_check);
    layout->addWidget(m_summary);
    layout->addWidget(m_stale);
    layout->addWidget(m_hint);
    layout->addWidget(m_cases, 1);
    layout->addWidget(m_back);
    setExercise(std::nullopt);
}

void ExercisePanel::setOutOfDate(bool outOfDate)
{
    m_outOfDate = outOfDate && m_cases->topLevelItemCount() > 0;
    m_stale->setVisible(m_outOfDate);
    m_summary->setForegroundRole(m_outOfDate ? QPalette::PlaceholderText : QPalette::WindowText);
    m_hint->setStyleSheet(hintStyle(m_outOfDate)); // the hint was for the program checked
    const QColor text =
        palette().color(m_outOfDate ? QPalette::Disabled : QPalette::Active, QPalette::Text);
    for (int i = 0; i < m_cases->topLevelItemCount(); ++i) {
        QTreeWidgetItem *item = m_cases->topLevelItem(i);
        for (int c : {0, 2, 3})
            item->setForeground(c, text);
        const bool passed = item->data(1, Qt::UserRole).toBool();
        item->setForeground(1, m_outOfDate ? text : passed ? QColor(0, 128, 0) : QColor(192, 0, 0));
    }
}

void ExercisePanel::setExercise(const std::optional<Exercise> &exercise)
{
    setOutOfDate(false);
    m_cases->clear();
    m_summary->clear();
    m_cases->hide();
    m_hint->hide();
    m_mistakeHints.clear();
    markShownCase(-1);
    if (!exercise) {
        m_title->setText(tr("No exercise is open"));
        m_task->setText(tr("An exercise is a scene file with a task, the teacher's reference "
                           "program and how it is graded. File > Examples > \"Exercise: "
                           "per-fragment lighting\" is one; File > Open Scene opens others."));
        m_about->clear();
        m_check->setEnabled(false);
        return;
    }
    m_passShare = exercise->grading.passShare;
    m_tolerance = exercise->grading.tolerance;
    m_size = exercise->grading.size;
    for (const ExerciseMistake &m : exercise->mistakes)
        m_mistakeHints.push_back(m.hint);
    m_cases->headerItem()->setToolTip(
        3, tr("The share of the pixels either program draws that are within %1/255 of the "
              "reference, at %2 x %3: the difference view counts a case alike (at its own size)")
               .arg(m_tolerance)
               .arg(m_size.width())
               .arg(m_size.height()));
    // A title is one line: a line break or a control in it is shown, not obeyed.
    // In the window's language, as lessons are (localized_text.h), else English.
    const QString title = localized(exercise->title, lessonLanguage());
    m_title->setText(title.isEmpty() ? tr("Exercise") : escapedName(title));
    m_task->setText(localized(exercise->task, lessonLanguage()));
    const ExerciseReference &ref = exercise->reference;
    const QString reference =
        !exercise->unread.isUndefined()
            ? tr("This exercise cannot be checked: its reference is missing or unusable.")
        : ref.builtIn()
            //: %1 the shading (gouraud, phong, flat); %2 the specular term (phong, blinn)
            ? tr("Reference: the built-in program, %1 shading, %2 specular.")
                  .arg(shadingLabel(ref.shading), specularLabel(ref.specular))
            : tr("Reference: the teacher's program (not shown; it is side B of the compare "
                 "views, key C).");
    const GradingSpec &g = exercise->grading;
    m_about->setText(reference + "\n" +
                     tr("%1 cases at %2 x %3 pixels; a case passes when %4 of its pixels are "
                        "within %5/255. The cases vary: %6.")
                         .arg(g.cases)
                         .arg(g.size.width())
                         .arg(g.size.height())
                         .arg(percent(g.passShare))
                         .arg(g.tolerance)
                         .arg(variedText(g.vary)) +
                     " " +
                     //: %1 a duration ("2.0 s"): the exercise's frame budget
                     tr("One frame of your program may take at most %1; a program that would "
                        "take longer is refused.")
                         .arg(durationText(g.frameBudgetMs())));
    m_check->setEnabled(exercise->unread.isUndefined());
}

void ExercisePanel::setChecking(bool checking)
{
    m_checking = checking;
    m_check->setText(checking ? tr("Cancel the check") : tr("Check my work"));
    if (checking) {
        m_summary->setText(tr("Checking: the cases are drawn with your program and the "
                              "reference..."));
        m_cases->clear();
        m_cases->hide();
        m_hint->hide();
    }
}

void ExercisePanel::showProblem(const QString &text)
{
    setOutOfDate(false);
    m_summary->setText(text);
    m_cases->clear();
    m_cases->hide();
    m_hint->hide();
}

QString ExercisePanel::problemText(const GradingReport &report)
{
    // The status words are the report's data (its CSV and JSON): compared, never shown as
    // they are, except one this panel does not know. Each sentence is whole, with and
    // without the reason after it.
    const QString &why = report.diagnostic;
    const bool said = !why.isEmpty();
    if (report.status == "does not compile")
        //: %1 the compiler's messages
        return said ? tr("Your program does not compile:\n%1").arg(why)
                    : tr("Your program does not compile");
    if (report.status == "does not link")
        //: %1 the linker's messages
        return said ? tr("Your program does not link:\n%1").arg(why)
                    : tr("Your program does not link");
    if (report.status == "refused")
        //: %1 why it was refused (a loop that never ends, a frame too slow)
        return said ? tr("Your program was refused:\n%1").arg(why) : tr("Your program was refused");
    if (report.status == "mistake does not build" || report.status == "mistake refused")
        //: %1 which of the exercise's known mistakes, and why (the driver's words)
        return tr("This exercise cannot check your work: one of the known mistakes it lists "
                  "cannot be drawn. Tell your teacher:\n%1")
            .arg(why);
    if (report.status == "timed out")
        //: %1 how long it was given
        return tr("The check took too long (%1) and was stopped").arg(why);
    if (report.status == "could not start")
        //: %1 why the checking process did not start
        return said ? tr("The check could not start:\n%1").arg(why)
                    : tr("The check could not start");
    //: %1 the grading's status word (English, as the report has it); %2 its reason
    return said ? tr("Not checked: %1:\n%2").arg(report.status, why)
                : tr("Not checked: %1").arg(report.status);
}

void ExercisePanel::showReport(const GradingReport &report)
{
    setOutOfDate(false);
    m_cases->clear();
    if (!report.graded()) {
        showProblem(problemText(report));
        return;
    }
    const int passed = report.passedCount();
    const int cases = int(report.cases.size());
    m_summary->setText((passed == cases
                            ? tr("Passed: all %1 cases (in each, at least %2 of the pixels within "
                                 "%3/255); largest difference %4/255")
                                  .arg(cases)
                                  .arg(percent(m_passShare))
                                  .arg(m_tolerance)
                                  .arg(report.largest())
                            : tr("Not yet: %1 of %2 cases pass; largest difference %3/255")
                                  .arg(passed)
                                  .arg(cases)
                                  .arg(report.largest())) +
                       "\n" + tr("Click a case to see it in the difference view."));
    m_results = report.cases;
    for (int k = 0; k < cases; ++k) {
        const CaseResult &r = report.cases[std::size_t(k)];
        auto *item = new QTreeWidgetItem(m_cases);
        //: case 0 of the list: the exercise's scene as it is, not varied
        item->setText(0, k == 0 ? tr("%1 (as given)").arg(k) : QString::number(k));
        item->setText(1, r.passed ? tr("passed") : tr("failed"));
        item->setText(2, QString("%1/255").arg(r.largest));
        item->setText(3, r.compared > 0 ? percent(r.shareWithin) : tr("nothing drawn"));
        item->setData(0, Qt::UserRole, k);
        item->setData(1, Qt::UserRole, r.passed);
        item->setForeground(1, r.passed ? QColor(0, 128, 0) : QColor(192, 0, 0));
        item->setToolTip(
            0, r.at.x() >= 0
                   ? tr("Largest difference at (%1, %2) of the %3 x %4 frame; %5 pixels drawn")
                         .arg(r.at.x())
                         .arg(r.at.y())
                         .arg(m_size.width())
                         .arg(m_size.height())
                         .arg(r.compared)
                   : tr("%1 pixels drawn").arg(r.compared));
    }
    showHint(report);
    m_cases->show();
}

void ExercisePanel::showHint(const GradingReport &report)
{
    // Never for a submission that passes (the child gives none then, nor is it shown).
    if (!report.mistake || report.passedCount() == int(report.cases.size())) {
        m_hint->hide();
        return;
    }
    const int index = report.mistake->index;
    // The exercise's own words in the window's language; the report's English when the
    // exercise shown is not the one checked (its list changed meanwhile).
    const QString hint = index >= 0 && index < int(m_mistakeHints.size())
                             ? localized(m_mistakeHints[std::size_t(index)], lessonLanguage())
                             : report.mistake->hint;
    m_hint->setText(hint);
    //: %1 the mistake's name as the exercise gives it (data, English); %2 a share ("98.5%")
    m_hint->setToolTip(
        tr("Your failing cases match the exercise's known mistake \"%1\" in %2 "
           "of their pixels, far more than they match the reference")
            .arg(escapedName(report.mistake->name), percent(report.mistake->shareWithin)));
    m_hint->show();
}

QString ExercisePanel::caseMeasured(int index) const
{
    // The list goes with its exercise (cleared): its results with it.
    if (index < 0 || index >= m_cases->topLevelItemCount() || index >= int(m_results.size()))
        return {};
    const CaseResult &r = m_results[std::size_t(index)];
    //: the difference view's caption for a case of the list; %1 x %2 the check's frame
    return r.compared > 0 ? tr("Check My Work, at %1 x %2: largest %3/255, %4 within %5/255")
                                .arg(m_size.width())
                                .arg(m_size.height())
                                .arg(r.largest)
                                .arg(percent(r.shareWithin))
                                .arg(m_tolerance)
                          : tr("Check My Work, at %1 x %2: nothing drawn")
                                .arg(m_size.width())
                                .arg(m_size.height());
}

void ExercisePanel::markShownCase(int index)
{
    m_back->setEnabled(index >= 0);
    for (int i = 0; i < m_cases->topLevelItemCount(); ++i) {
        QTreeWidgetItem *item = m_cases->topLevelItem(i);
        QFont f = item->font(0);
        f.setBold(item->data(0, Qt::UserRole).toInt() == index);
        for (int c = 0; c < 4; ++c)
            item->setFont(c, f);
    }
}

} // namespace lb
