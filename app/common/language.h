#pragma once
// The window's language (issue 31): English, Portuguese (Portugal) or German, from View >
// Language or, by default, from the system (LANG). lightbench's own catalogue is built into
// the resources (resources/translations/*.ts -> :/i18n/*.qm); Qt's and QScintilla's come from
// Debian's qt6-translations-l10n and libqscintilla2-qt6-l10n where installed. The command
// line loads none of them: what it prints stays English, and its data is never translated.

#include <QList>
#include <QString>

class QCoreApplication;
class QLocale;

namespace lb {

struct InterfaceLanguage
{
    QString code; // "" (the system's), "en", "pt", "de": as kept in the settings
    QString name; // in its own language: "Português", "Deutsch"
};
QList<InterfaceLanguage> interfaceLanguages(); // System first

extern const char *const kInterfaceLanguageKey; // "interface/language"

// The language the window speaks for a setting: the chosen one, else the system's when
// lightbench has it, else English. Always one of "en", "pt", "de".
QString resolvedLanguage(const QString &setting);

// Installs the translators for `language` on the application (lightbench's, Qt's,
// QScintilla's) and returns the names of the catalogues that loaded. Call before the
// window is built: the window reads its strings once (a change asks for a restart).
QStringList installTranslators(QCoreApplication &app, const QString &language);
// The window's language as a QLocale.
QLocale interfaceLocale();
// A count as the window's sentences write it: grouped the language's way ("9,216 triangles",
// "9 216 triângulos"), except that a language grouping with a point ("9.216 Dreiecke") groups
// with a no-break space instead ("9 216 Dreiecke"): numbers with decimals keep the point in
// every language (window/run_window.cpp), and 1.024 beside a field showing 1.024 read as two
// numbers of one kind; one convention on screen.
QString writtenCount(qulonglong count);
// The language installTranslators() installed last ("en" before).
QString installedLanguage();
// Takes them off again (English from then on, for what is built after).
void removeTranslators(QCoreApplication &app);

} // namespace lb
