#pragma once
// A translator for tests of what reaches translators: every text asked of Qt's translation
// system comes back marked as «CONTEXT|SOURCE», so that a test can tell a message that goes
// through tr() / QCoreApplication::translate (and in which context) from one built outside
// it, and data (file keys, JSON, CSV), which must never be translated, from both. The marks
// keep the placeholders (%1, %n), which arg() and Qt's plural handling fill in as usual.
// Installed for the life of a MarkedMessages.

#include <QCoreApplication>
#include <QString>
#include <QTranslator>

class MarkingTranslator : public QTranslator
{
public:
    bool isEmpty() const override { return false; }
    QString translate(const char *context, const char *sourceText, const char *, int) const override
    {
        if (!sourceText)
            return {};
        return QStringLiteral("\u00ab") + QString::fromUtf8(context) + QLatin1Char('|') +
               QString::fromUtf8(sourceText) + QStringLiteral("\u00bb");
    }
};

// `text` in `context` as the MarkingTranslator gives it: marked("lb::Scene", "sphere").
inline QString marked(const char *context, const QString &text)
{
    return QStringLiteral("\u00ab") + QString::fromUtf8(context) + QLatin1Char('|') + text +
           QStringLiteral("\u00bb");
}

class MarkedMessages
{
public:
    MarkedMessages() { QCoreApplication::installTranslator(&m_translator); }
    ~MarkedMessages() { QCoreApplication::removeTranslator(&m_translator); }
    MarkedMessages(const MarkedMessages &) = delete;
    MarkedMessages &operator=(const MarkedMessages &) = delete;

private:
    MarkingTranslator m_translator;
};
