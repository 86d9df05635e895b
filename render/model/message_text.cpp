#include "message_text.h"

#include <QLocale>

#include <algorithm>

namespace lb {

QString elidedForMessage(const QString &text, int max)
{
    if (text.size() <= max)
        return text;
    const int half = std::max(1, (max - 3) / 2);
    return text.left(half) + "..." + text.right(half);
}

QString echoedValue(const QString &text, int max)
{
    QString line = elidedForMessage(text, max);
    for (QChar &c : line)
        if (c.category() == QChar::Other_Control || c.category() == QChar::Separator_Line ||
            c.category() == QChar::Separator_Paragraph)
            c = QChar(0xFFFD);
    return line;
}

QString summarisedList(const QStringList &items, const QString &separator, int shown)
{
    QStringList parts;
    for (int i = 0; i < std::min(shown, int(items.size())); ++i)
        parts << elidedForMessage(items[i]);
    if (items.size() > shown)
        parts << QString("... and %1 more")
                     .arg(QLocale(QLocale::English).toString(qlonglong(items.size() - shown)));
    return parts.join(separator);
}

} // namespace lb
