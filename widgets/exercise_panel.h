#pragma once
// The Exercise panel: the open exercise's title and task, what its reference is and how it
// grades, and Check my work: the cases the student's program was checked on, each passed or
// not with its largest difference and its share of pixels within tolerance. A click on a case
// asks for it in the difference view. The checking itself is the window's (it runs in a
// grading child); this panel shows and asks.

#include "exercise.h"
#include "grading_report.h"

#include <QWidget>

#include <vector>

class QLabel;
class QPushButton;
class QTreeWidget;

namespace lb {

class ExercisePanel : public QWidget
{
    Q_OBJECT
public:
    explicit ExercisePanel(QWidget *parent = nullptr);

    // The exercise to show; none: a word on what an exercise is. The cases listed go.
    void setExercise(const std::optional<Exercise> &exercise);
    // A check is running (the button becomes Cancel) or not.
    void setChecking(bool checking);
    // The outcome of a check: its cases listed, or why there are none.
    void showReport(const GradingReport &report);
    // A message in place of the outcome ("could not start the check: ...").
    void showProblem(const QString &text);
    // The case shown in the view is marked in the list; -1: none (the student's own scene).
    void markShownCase(int index);
    // What the last check measured for case `index`, in words for the difference view's
    // caption ("Check My Work, at 320 x 240: largest 104/255, 84.6% within 2/255"); empty
    // for no such case.
    QString caseMeasured(int index) const;
    // The program in the editor is no longer the one the listed outcome was checked with
    // (false again when the edit is undone): the outcome says so.
    void setOutOfDate(bool outOfDate);
    bool isOutOfDate() const { return m_outOfDate; }
    QLabel *outOfDateLabel() const { return m_stale; }

    QPushButton *checkButton() const { return m_check; }
    QPushButton *backButton() const { return m_back; }
    QTreeWidget *caseList() const { return m_cases; }
    QLabel *summaryLabel() const { return m_summary; }
    QLabel *titleLabel() const { return m_title; }
    // The known mistake a failing check's frames match, in the window's language; hidden
    // when there is none.
    QLabel *hintLabel() const { return m_hint; }

signals:
    void checkRequested();
    void cancelRequested();
    void caseChosen(int index); // a case of the last report, to show in the difference view
    void backRequested();       // the scene as it was before the first case was shown

private:
    // Why a report lists no cases, in words (its status and diagnostic).
    static QString problemText(const GradingReport &report);
    // The known mistake the report names, above the cases, or nothing.
    void showHint(const GradingReport &report);

    QLabel *m_title;
    QLabel *m_task;
    QLabel *m_about;
    QPushButton *m_check;
    QLabel *m_summary;
    QLabel *m_stale;
    QLabel *m_hint;
    QTreeWidget *m_cases;
    QPushButton *m_back;
    bool m_checking = false;
    bool m_outOfDate = false;
    double m_passShare = 0.99;
    int m_tolerance = 2;
    QSize m_size;
    std::vector<CaseResult> m_results;         // the last report's cases
    std::vector<LocalizedText> m_mistakeHints; // the exercise's, by the report's index
};

} // namespace lb
