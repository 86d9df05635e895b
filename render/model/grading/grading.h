#pragma once
// One case of a grading: the student's frame against the reference's, pixel by pixel, over
// the pixels either of them covers (the background, the same in both, would make any program
// look nearly right); and the sheet a teacher looks at: student | reference | heat map, with
// the numbers.

#include <QImage>
#include <QPoint>
#include <QString>

namespace lb {

struct CaseResult
{
    int largest = 0;        // the largest channel difference, out of 255
    QPoint at{-1, -1};      // where (top-left origin); (-1, -1) when nothing differs
    double shareWithin = 1; // of the pixels compared, those within the tolerance
    int compared = 0;       // pixels either frame covers
    bool passed = false;    // shareWithin >= the exercise's passShare, something drawn
};

// `background`: the clear colour both frames share where nothing is drawn.
CaseResult measureCase(const QImage &student, const QImage &reference, QRgb background,
                       int tolerance, double passShare);

// The pixels where a known mistake's frame differs from the reference's by more than the
// tolerance (what the mistake changes: its signature), and how many of them the student's
// frame has within the tolerance of the mistake's.
struct SignatureAgreement
{
    long differing = 0, agreeing = 0;
};
SignatureAgreement signatureAgreement(const QImage &student, const QImage &reference,
                                      const QImage &mistake, int tolerance);

// |student - reference| per pixel, black at 0 to white at 64/255 (the difference view's scale).
QImage differenceHeatMap(const QImage &student, const QImage &reference);

// The sheet's title: "alice - case 3: largest difference 12/255 at (40, 17), 98.5% of 5120
// pixels within tolerance, failed".
QString gradingSheetTitle(const QString &title, const CaseResult &result, int caseIndex);

// The three frames side by side with a line of text under each and a title above.
QImage gradingSheet(const QString &title, const QImage &student, const QImage &reference,
                    const CaseResult &result, int caseIndex);

} // namespace lb
