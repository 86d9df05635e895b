#include "grading_progress.h"

#include <algorithm>

namespace lb {

namespace {

QString clock(qint64 ms)
{
    const qint64 s = std::max<qint64>(0, ms) / 1000;
    if (s >= 3600)
        return QString("%1:%2:%3")
            .arg(s / 3600)
            .arg(s / 60 % 60, 2, 10, QChar('0'))
            .arg(s % 60, 2, 10, QChar('0'));
    return QString("%1:%2").arg(s / 60).arg(s % 60, 2, 10, QChar('0'));
}

} // namespace

QString progressText(int done, int total, qint64 elapsedMs)
{
    QString text = QString("graded %1/%2, %3 elapsed").arg(done).arg(total).arg(clock(elapsedMs));
    if (done > 0 && done < total)
        // Submissions run side by side, so the mean over those done already counts that.
        text += QString(", about %1 left").arg(clock(elapsedMs * (total - done) / done));
    return text;
}

} // namespace lb
