#include "language_menu.h"

#include "language.h"

#include <QActionGroup>
#include <QCoreApplication>
#include <QMenu>
#include <QMessageBox>
#include <QProcess>
#include <QPushButton>
#include <QWidget>

namespace lb {

namespace {
bool g_restartRequested = false;
} // namespace

void addLanguageMenu(QMenu *view, QSettings &settings, QWidget *window)
{
    QMenu *menu = view->addMenu(QCoreApplication::translate("lb::Language", "&Language"));
    auto *group = new QActionGroup(menu);
    const QString current = settings.value(kInterfaceLanguageKey).toString();
    for (const InterfaceLanguage &language : interfaceLanguages()) {
        QAction *a = menu->addAction(language.name);
        a->setCheckable(true);
        a->setChecked(language.code == current);
        a->setData(language.code);
        group->addAction(a);
        QObject::connect(a, &QAction::triggered, window, [&settings, window, code = language.code] {
            settings.setValue(kInterfaceLanguageKey, code);
            if (resolvedLanguage(code) == installedLanguage())
                return; // the one the window speaks now ("System" when LANG gives it)
            QMessageBox box(QMessageBox::Question,
                            QCoreApplication::translate("lb::Language", "Language"),
                            QCoreApplication::translate(
                                "lb::Language", "The window changes its language when lightbench "
                                                "starts again. Restart now?"),
                            QMessageBox::NoButton, window);
            box.setInformativeText(QCoreApplication::translate(
                "lb::Language", "lightbench closes as it does on Quit, asking about unsaved "
                                "work, and opens again where you were."));
            QPushButton *now =
                box.addButton(QCoreApplication::translate("lb::Language", "Restart &Now"),
                              QMessageBox::AcceptRole);
            box.addButton(QCoreApplication::translate("lb::Language", "&Later"),
                          QMessageBox::RejectRole);
            box.setDefaultButton(now);
            box.exec();
            if (box.clickedButton() != now)
                return;
            g_restartRequested = true;
            if (!window->close()) // unsaved work kept, on the user's word
                g_restartRequested = false;
        });
    }
}

bool restartRequested()
{
    return g_restartRequested;
}

bool restartApplication()
{
    return QProcess::startDetached(QCoreApplication::applicationFilePath(), {});
}

} // namespace lb
