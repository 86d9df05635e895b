#pragma once
// lightbench's own catalogue (resources/translations/*.ts, built into :/i18n) for the window
// and for the helpers the window starts whose words it shows: the trial helper (a refused
// program's reason) and Check My Work's grading child. They learn the window's language from
// LIGHTBENCH_LANGUAGE, which only the window sets: the command line, run from a shell, keeps
// speaking English and its output stays the same bytes in every language.

#include <QString>

class QCoreApplication;

namespace lb {

extern const char *const kLanguageVariable; // "LIGHTBENCH_LANGUAGE"

// Installs lightbench's catalogue for `language` ("en": its plural forms only); true when it
// loaded. The translator belongs to the application.
bool installCatalogue(QCoreApplication &app, const QString &language);
// For a helper the window started: the window's language, when it named one.
void installCatalogueFromWindow(QCoreApplication &app);

} // namespace lb
