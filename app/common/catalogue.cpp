#include "catalogue.h"

#include <QCoreApplication>
#include <QTranslator>

namespace lb {

const char *const kLanguageVariable = "LIGHTBENCH_LANGUAGE";

bool installCatalogue(QCoreApplication &app, const QString &language)
{
    if (language != "en" && language != "pt" && language != "de")
        return false; // also what a stranger's environment might hold
    auto *translator = new QTranslator(&app);
    if (!translator->load(QString(":/i18n/lightbench_%1.qm").arg(language)) ||
        !app.installTranslator(translator)) {
        delete translator;
        return false;
    }
    return true;
}

void installCatalogueFromWindow(QCoreApplication &app)
{
    const QString language = qEnvironmentVariable(kLanguageVariable);
    if (!language.isEmpty())
        installCatalogue(app, language);
}

} // namespace lb
