#pragma once
// Text a file gives in several languages (issue 31): a lesson's titles and captions, an
// exercise's title and task. In the file, a plain string (English) or {"en": ..., "pt": ...,
// "de": ...}; shown in the language lessons and examples are shown in (the window's, unless
// Lesson > Caption Language sets one apart), falling back to English.

#include <QJsonValue>
#include <QMap>
#include <QString>

#include <functional>

namespace lb {

// Text by language code ("en", "pt", "de").
using LocalizedText = QMap<QString, QString>;

// The text for `language` ("pt", "pt_PT", "de_DE.UTF-8"): that language, else English, else
// the first there is; empty when there is none.
QString localized(const LocalizedText &text, const QString &language);

// English alone (a name the user typed, a file's plain string); empty for an empty one.
LocalizedText plainText(const QString &english);

// Reads a string or a {language: string} object; empty strings are left out. What cannot be used
// (not text, longer than `maxCharacters`, a key that is no language code) is left out and told to
// `ignore` with where it was ("title.de") and why; `where` names the field itself.
LocalizedText
readLocalizedText(const QJsonValue &value, const QString &where, int maxCharacters,
                  const std::function<void(const QString &, const QString &)> &ignore);
// As the file writes it: a plain string when there is only English, nothing when empty.
QJsonValue localizedTextJson(const LocalizedText &text);

// The language lessons and examples are shown and written in, as "en", "pt", "de": the one
// chosen (Lesson > Caption Language), else the window's (View > Language), else the system's
// (LANG), else English.
QString lessonLanguage();
void setLessonLanguage(const QString &language);        // empty: the window's again
void setDefaultLessonLanguage(const QString &language); // the window's language

} // namespace lb
