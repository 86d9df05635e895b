#include "grading.h"

#include "compare.h"
#include "message_text.h"

#include <QCoreApplication>
#include <QPainter>

#include <algorithm>
#include <cstdlib>

namespace lb {

namespace {

// The translation context of the sheet's text.
struct GradingMessages
{
    Q_DECLARE_TR_FUNCTIONS(lb::Grading)
};

int channelDifference(QRgb a, QRgb b)
{
    return std::max({std::abs(qRed(a) - qRed(b)), std::abs(qGreen(a) - qGreen(b)),
                     std::abs(qBlue(a) - qBlue(b))});
}

bool isBackground(QRgb p, QRgb background)
{
    return channelDifference(p, background) <= 1;
}

// The image with 32-bit words a pixel, each what QImage::pixel gives (its colour channels:
// the alpha is not compared): read by the row, as QImage::pixel (a call and a format switch
// for every pixel) took over half of a failing submission's grading (its frames against the
// reference's and every known mistake's). QImage::pixel gives a format's values as they are
// stored, premultiplied or not (a colour table's entries for the indexed formats), except for
// the formats it has no case for, which it premultiplies: all of them premultiplied or opaque.
QImage wordsPerPixel(const QImage &image)
{
    switch (image.format()) {
    case QImage::Format_RGB32:
    case QImage::Format_ARGB32:
    case QImage::Format_ARGB32_Premultiplied:
        return image; // shared, not copied
    default:
        return image.convertToFormat(image.pixelFormat().premultiplied() ==
                                             QPixelFormat::Premultiplied
                                         ? QImage::Format_ARGB32_Premultiplied
                                         : QImage::Format_ARGB32);
    }
}

const QRgb *row(const QImage &image, int y)
{
    return reinterpret_cast<const QRgb *>(image.constScanLine(y));
}

} // namespace

CaseResult measureCase(const QImage &studentImage, const QImage &referenceImage, QRgb background,
                       int tolerance, double passShare)
{
    CaseResult r;
    const QImage student = wordsPerPixel(studentImage), reference = wordsPerPixel(referenceImage);
    const int w = std::min(student.width(), reference.width());
    const int h = std::min(student.height(), reference.height());
    int within = 0;
    for (int y = 0; y < h; ++y) {
        const QRgb *studentRow = row(student, y), *referenceRow = row(reference, y);
        for (int x = 0; x < w; ++x) {
            const QRgb s = studentRow[x], ref = referenceRow[x];
            if (isBackground(s, background) && isBackground(ref, background))
                continue;
            ++r.compared;
            const int d = channelDifference(s, ref);
            within += d <= tolerance;
            if (d > r.largest) {
                r.largest = d;
                r.at = QPoint(x, y);
            }
        }
    }
    r.shareWithin = r.compared ? double(within) / double(r.compared) : 1.0;
    // Nothing drawn by either program tells nothing: not passed.
    r.passed = r.compared > 0 && r.shareWithin >= passShare && student.size() == reference.size();
    return r;
}

SignatureAgreement signatureAgreement(const QImage &studentImage, const QImage &referenceImage,
                                      const QImage &mistakeImage, int tolerance)
{
    SignatureAgreement a;
    if (studentImage.size() != referenceImage.size() ||
        mistakeImage.size() != referenceImage.size())
        return a;
    const QImage student = wordsPerPixel(studentImage), reference = wordsPerPixel(referenceImage),
                 mistake = wordsPerPixel(mistakeImage);
    for (int y = 0; y < reference.height(); ++y) {
        const QRgb *studentRow = row(student, y), *referenceRow = row(reference, y),
                   *mistakeRow = row(mistake, y);
        for (int x = 0; x < reference.width(); ++x) {
            const QRgb m = mistakeRow[x];
            if (channelDifference(m, referenceRow[x]) <= tolerance)
                continue;
            ++a.differing;
            a.agreeing += channelDifference(studentRow[x], m) <= tolerance;
        }
    }
    return a;
}

QImage differenceHeatMap(const QImage &student, const QImage &reference)
{
    QImage heat(reference.size(), QImage::Format_RGB32);
    for (int y = 0; y < heat.height(); ++y)
        for (int x = 0; x < heat.width(); ++x) {
            const int d = x < student.width() && y < student.height()
                              ? channelDifference(student.pixel(x, y), reference.pixel(x, y))
                              : 255;
            const int v = std::min(255, int(d / (kDifferenceScale * 255.0f) * 255.0f + 0.5f));
            heat.setPixel(x, y, qRgb(v, v, v));
        }
    return heat;
}

QString gradingSheetTitle(const QString &title, const CaseResult &result, int caseIndex)
{
    // All at once: a name holding "%2" is not filled in by the arguments after it.
    const QString name = escapedName(title); // a submission's name: one line, controls shown
    const QString index = QString::number(caseIndex), largest = QString::number(result.largest);
    const QString share = QString::number(100.0 * result.shareWithin, 'f', 1);
    const QString compared = QString::number(result.compared);
    //: the outcome of a case, at the end of a grading sheet's title
    const QString outcome =
        result.passed ? GradingMessages::tr("passed") : GradingMessages::tr("failed");
    if (result.at.x() < 0) // nothing differs
        return GradingMessages::tr(
                   "%1 - case %2: largest difference %3/255, %4% of %5 pixels within "
                   "tolerance, %6")
            .arg(name, index, largest, share, compared, outcome);
    //: %4, %5: the pixel that differs most
    return GradingMessages::tr(
               "%1 - case %2: largest difference %3/255 at (%4, %5), %6% of %7 pixels "
               "within tolerance, %8")
        .arg(name, index, largest, QString::number(result.at.x()), QString::number(result.at.y()),
             share, compared, outcome);
}

QImage gradingSheet(const QString &title, const QImage &student, const QImage &reference,
                    const CaseResult &result, int caseIndex)
{
    const int w = reference.width(), h = reference.height();
    const int margin = 8, titleHeight = 28, captionHeight = 22;
    QImage sheet(3 * w + 4 * margin, h + titleHeight + captionHeight + 2 * margin,
                 QImage::Format_RGB32);
    sheet.fill(QColor(250, 250, 248));
    QPainter p(&sheet);
    p.setRenderHint(QPainter::TextAntialiasing);
    QFont font = p.font();
    font.setPixelSize(14);
    p.setFont(font);
    p.setPen(Qt::black);
    p.drawText(QRect(margin, margin, sheet.width() - 2 * margin, titleHeight),
               Qt::AlignLeft | Qt::AlignVCenter, gradingSheetTitle(title, result, caseIndex));
    const QImage frames[3] = {student, reference, differenceHeatMap(student, reference)};
    //: the captions under a grading sheet's three frames
    const QString captions[3] = {GradingMessages::tr("student"), GradingMessages::tr("reference"),
                                 GradingMessages::tr("|student - reference| (white: 64/255)")};
    for (int i = 0; i < 3; ++i) {
        const QPoint at(margin + i * (w + margin), margin + titleHeight);
        p.drawImage(at, frames[i]);
        p.drawText(QRect(at.x(), at.y() + h, w, captionHeight), Qt::AlignCenter, captions[i]);
    }
    if (result.at.x() >= 0) { // the worst pixel, ringed on each frame
        p.setPen(QPen(QColor(230, 40, 40), 2));
        for (int i = 0; i < 3; ++i)
            p.drawEllipse(QPoint(margin + i * (w + margin), margin + titleHeight) + result.at, 7,
                          7);
    }
    return sheet;
}

} // namespace lb
