#include "localized_text.h"

#include "message_text.h"

#include <QCoreApplication>
#include <QJsonObject>
#include <QLocale>
#include <QRegularExpression>

namespace lb {

namespace {

// The translation context of this file's messages.
struct LocalizedTextMessages
{
    Q_DECLARE_TR_FUNCTIONS(lb::LocalizedText)
};

} // namespace

LocalizedText readLocalizedText(const QJsonValue &value, const QString &where, int maxCharacters,
                                const std::function<void(const QString &, const QString &)> &ignore)
{
    LocalizedText text;
    const auto take = [&](const QString &language, const QJsonValue &v) {
        const QString at = language.isEmpty() ? where : QString("%1.%2").arg(where, language);
        if (!v.isString())
            ignore(at, LocalizedTextMessages::tr("not text"));
        else if (v.toString().size() > maxCharacters)
            ignore(at, LocalizedTextMessages::tr("%1 characters; at most %2")
                           .arg(v.toString().size())
                           .arg(maxCharacters));
        else if (!v.toString().isEmpty())
            text[language.isEmpty() ? QString("en") : language] = v.toString();
    };
    if (value.isUndefined() || value.isNull())
        return text;
    if (!value.isObject()) {
        take({}, value);
        return text;
    }
    const QJsonObject o = value.toObject();
    for (auto it = o.begin(); it != o.end(); ++it) {
        // A language code, as QLocale names it: "pt", "de", "pt_BR" (not "\e[2J", which has
        // a code's length).
        static const QRegularExpression code("^[A-Za-z]{2,3}([_-][A-Za-z0-9]{2,8})?$");
        if (!code.match(it.key()).hasMatch())
            ignore(QString("%1.%2").arg(where, echoedValue(it.key(), 40)),
                   LocalizedTextMessages::tr("not a language code"));
        else
            take(it.key(), it.value());
    }
    return text;
}

LocalizedText plainText(const QString &english)
{
    return english.isEmpty() ? LocalizedText{} : LocalizedText{{QString("en"), english}};
}

QJsonValue localizedTextJson(const LocalizedText &text)
{
    if (text.isEmpty())
        return QJsonValue();
    if (text.size() == 1 && text.contains("en"))
        return text["en"];
    QJsonObject o;
    for (auto it = text.begin(); it != text.end(); ++it)
        o[it.key()] = it.value();
    return o;
}

QString localized(const LocalizedText &text, const QString &language)
{
    if (text.isEmpty())
        return {};
    const QString code = language.section('.', 0, 0); // "de_DE.UTF-8" -> "de_DE"
    for (const QString &key : {code, code.section('_', 0, 0), QString("en")})
        if (!key.isEmpty() && text.contains(key))
            return text[key];
    return text.first();
}

namespace {
QString &chosenLanguage()
{
    static QString language;
    return language;
}
QString &defaultLanguage() // the window's, once it has chosen one
{
    static QString language;
    return language;
}
} // namespace

QString lessonLanguage()
{
    if (!chosenLanguage().isEmpty())
        return chosenLanguage();
    if (!defaultLanguage().isEmpty())
        return defaultLanguage();
    // The system's (LANG), for a program that chose no language (the command line). The C
    // and POSIX locales (LANG=C, a bare container) name no language: English then, so that
    // what is written is under a code a lesson file takes.
    const QString language = QLocale::system().name().section('_', 0, 0);
    static const QRegularExpression code("^[a-z]{2,3}$");
    return code.match(language).hasMatch() ? language : QString("en");
}

void setLessonLanguage(const QString &language)
{
    chosenLanguage() = language;
}

void setDefaultLessonLanguage(const QString &language)
{
    defaultLanguage() = language;
}

} // namespace lb
