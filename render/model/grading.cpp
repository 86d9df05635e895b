#include "grading.h"

#include "compare.h"
#include "message_text.h"

#include <QPainter>

#include <algorithm>
#include <cstdlib>

namespace lb {

namespace {

int channelDifference(QRgb a, QRgb b)
{
    return std::max({std::abs(qRed(a) - qRed(b)), std::abs(qGreen(a) - qGreen(b)),
                     std::abs(qBlue(a) - qBlue(b))});
}

bool isBackground(QRgb p, QRgb background)
{
    return channelDifference(p, background) <= 1;
}

} // namespace

CaseResult measureCase(const QImage &student, const QImage &reference, QRgb background,
                       int tolerance, double passShare)
{
    CaseResult r;
    const int w = std::min(student.width(), reference.width());
    const int h = std::min(student.height(), reference.height());
    int within = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const QRgb s = student.pixel(x, y), ref = reference.pixel(x, y);
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
    r.shareWithin = r.compared ? double(within) / double(r.compared) : 1.0;
    // Nothing drawn by either program tells nothing: not passed.
    r.passed = r.compared > 0 && r.shareWithin >= passShare && student.size() == reference.size();
    return r;
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
               Qt::AlignLeft | Qt::AlignVCenter,
               QString("%1 - case %2: largest difference %3/255%4, %5% of %6 pixels within "
                       "tolerance, %7")
                   .arg(escapedName(title)) // a submission's name: one line, controls shown
                   .arg(caseIndex)
                   .arg(result.largest)
                   .arg(result.at.x() >= 0
                            ? QString(" at (%1, %2)").arg(result.at.x()).arg(result.at.y())
                            : QString())
                   .arg(100.0 * result.shareWithin, 0, 'f', 1)
                   .arg(result.compared)
                   .arg(result.passed ? "passed" : "failed"));
    const QImage frames[3] = {student, reference, differenceHeatMap(student, reference)};
    const char *captions[3] = {"student", "reference", "|student - reference| (white: 64/255)"};
    for (int i = 0; i < 3; ++i) {
        const QPoint at(margin + i * (w + margin), margin + titleHeight);
        p.drawImage(at, frames[i]);
        p.drawText(QRect(at.x(), at.y() + h, w, captionHeight), Qt::AlignCenter,
                   QLatin1String(captions[i]));
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
