#include "message_text.h"

#include <QCoreApplication>
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

QString echoedPath(const QString &path)
{
    return echoedValue(path, 300);
}

namespace {

// The Unicode controls that break a line or reorder the text after them (bidi embeddings,
// overrides and isolates; the marks): "alice\u202egnp.exe" reads as another name.
bool isLayoutControl(char16_t c)
{
    return c == 0x2028 || c == 0x2029 || c == 0x200e || c == 0x200f ||
           (c >= 0x202a && c <= 0x202e) || (c >= 0x2066 && c <= 0x2069) || c == 0x061c;
}

QString escaped(const QString &text, bool backslashes)
{
    QString out;
    out.reserve(text.size());
    for (const QChar qc : text) {
        const char16_t c = qc.unicode();
        if (c == '\\' && backslashes)
            out += QLatin1String("\\\\");
        else if (c == '\n')
            out += QLatin1String("\\n");
        else if (c == '\r')
            out += QLatin1String("\\r");
        else if (c == '\t')
            out += QLatin1String("\\t");
        else if (c < 0x20 || (c >= 0x7f && c <= 0x9f))
            out += QString("\\x%1").arg(int(c), 2, 16, QChar('0'));
        else if (isLayoutControl(c))
            out += QString("\\u%1").arg(int(c), 4, 16, QChar('0'));
        else
            out += qc;
    }
    return out;
}

} // namespace

QString escapedName(const QString &name)
{
    return escaped(name, true);
}

QString escapedControls(const QString &text)
{
    return escaped(text, false);
}

QString summarisedList(const QStringList &items, const QString &separator, int shown)
{
    QStringList parts;
    for (int i = 0; i < std::min(shown, int(items.size())); ++i)
        parts << elidedForMessage(items[i]);
    if (items.size() > shown)
        parts << QCoreApplication::translate("lb::MessageText", "... and %1 more")
                     .arg(QLocale(QLocale::English).toString(qlonglong(items.size() - shown)));
    return parts.join(separator);
}

QString countedText(const char *context, const char *source, int n)
{
    const QString translated = QCoreApplication::translate(context, source, nullptr, n);
    QString untranslated = QString::fromUtf8(source);
    untranslated.replace(QLatin1String("%n"), QString::number(n)); // as translate() does
    if (translated != untranslated)
        return translated;
    return untranslated.replace(QLatin1String("(s)"), n == 1 ? QString() : QStringLiteral("s"));
}

} // namespace lb
