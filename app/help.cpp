#include "help.h"

#include <QAction>
#include <QDesktopServices>
#include <QDialog>
#include <QDialogButtonBox>
#include <QFile>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QTextBrowser>
#include <QUrl>
#include <QVBoxLayout>

namespace lb {

namespace {

QString row(const QString &keys, const QString &what)
{
    return QString("<tr><td style='padding-right:16px'><b>%1</b></td><td>%2</td></tr>")
        .arg(keys.toHtmlEscaped(), what.toHtmlEscaped());
}

void addMenu(QString &html, const QMenu *menu, const QString &path)
{
    for (const QAction *a : menu->actions()) {
        if (a->menu()) {
            addMenu(html, a->menu(), path + " > " + a->menu()->title().remove('&'));
            continue;
        }
        if (a->shortcuts().isEmpty())
            continue;
        QStringList keys;
        for (const QKeySequence &k : a->shortcuts())
            keys << k.toString(QKeySequence::NativeText);
        html += row(keys.join(QObject::tr(" or ")), path + " > " + a->text().remove('&'));
    }
}

QDialog *textWindow(QWidget *parent, const QString &title, QTextBrowser *&browser)
{
    auto *dialog = new QDialog(parent);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->setWindowTitle(title);
    auto *layout = new QVBoxLayout(dialog);
    browser = new QTextBrowser(dialog);
    // Web links open in the browser; the README's links to files of the source tree have no
    // page here, and following one would blank the window.
    browser->setOpenLinks(false);
    QObject::connect(browser, &QTextBrowser::anchorClicked, dialog, [browser](const QUrl &url) {
        if (url.scheme().startsWith("http"))
            QDesktopServices::openUrl(url);
        else if (url.hasFragment())
            browser->scrollToAnchor(url.fragment());
    });
    layout->addWidget(browser);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Close, dialog);
    QObject::connect(buttons, &QDialogButtonBox::rejected, dialog, &QDialog::close);
    layout->addWidget(buttons);
    // Most of the parent's screen, never more than it has.
    const QSize room = parent ? parent->size() : QSize(900, 700);
    dialog->resize(std::min(760, room.width() - 40), std::min(720, room.height() - 40));
    return dialog;
}

} // namespace

QString shortcutsHtml(const QMenuBar *menus)
{
    QString html = "<table cellspacing='3'>";
    html += QString("<tr><td colspan='2'><h3>%1</h3></td></tr>").arg(QObject::tr("Menus"));
    for (const QAction *a : menus->actions())
        if (a->menu())
            addMenu(html, a->menu(), a->menu()->title().remove('&'));
    html += QString("<tr><td colspan='2'><h3>%1</h3></td></tr>").arg(QObject::tr("Shader editor"));
    html += row("Ctrl+Enter", QObject::tr("compile and link now"));
    html += row("Ctrl+F", QObject::tr("find in the shader"));
    html += row("Ctrl+Z / Ctrl+Y", QObject::tr("undo / redo (also what a preset, an example or "
                                               "a reset replaced)"));
    html += row("Ctrl+Space", QObject::tr("complete the word"));
    html += row("Ctrl+L / Ctrl+D", QObject::tr("delete / duplicate the line"));
    html += QString("<tr><td colspan='2'><h3>%1</h3></td></tr>").arg(QObject::tr("View"));
    html += row(QObject::tr("left drag"), QObject::tr("orbit the camera"));
    html += row(QObject::tr("click"), QObject::tr("select the object under the cursor"));
    html += row(QObject::tr("right or middle drag"), QObject::tr("pan"));
    html += row(QObject::tr("wheel"), QObject::tr("zoom"));
    html += row(QObject::tr("Ctrl+click, Shift+click"),
                QObject::tr("probe the surface point (drag to move it)"));
    html += row(QObject::tr("drag the wipe's line"), QObject::tr("move the wipe (compare)"));
    html += row(QObject::tr("drop a file"), QObject::tr("open a mesh, a scene, a lesson or a shader pair"));
    html += "</table>";
    return html;
}

void showShortcuts(QWidget *parent, const QMenuBar *menus)
{
    QTextBrowser *browser = nullptr;
    QDialog *dialog = textWindow(parent, QObject::tr("Keyboard shortcuts - lightbench"), browser);
    browser->setHtml(shortcutsHtml(menus));
    dialog->setObjectName("shortcutsWindow");
    dialog->show();
}

void showFeatures(QWidget *parent)
{
    QTextBrowser *browser = nullptr;
    QDialog *dialog = textWindow(parent, QObject::tr("Features - lightbench"), browser);
    QFile readme(":/docs/README.md");
    browser->setSearchPaths({":/docs"}); // its screenshots, by their paths in the README
    if (readme.open(QIODevice::ReadOnly))
        browser->setMarkdown(QString::fromUtf8(readme.readAll()));
    else
        browser->setPlainText(QObject::tr("The README is missing from this build."));
    dialog->setObjectName("featuresWindow");
    dialog->show();
}

void showAbout(QWidget *parent, const QString &glInfo)
{
    QMessageBox::about(
        parent, QObject::tr("About lightbench"),
        QObject::tr("<h3>lightbench %1</h3><p>A workbench for the lighting model of computer "
                    "graphics courses: ambient, diffuse and specular terms, Phong and "
                    "Blinn-Phong, Gouraud and Phong shading, every pixel checked against a CPU "
                    "reference.</p><p>Qt %2 (built with %3)<br>%4</p>")
            .arg(QStringLiteral(LIGHTBENCH_VERSION), QString::fromLatin1(qVersion()),
                 QStringLiteral(QT_VERSION_STR),
                 glInfo.isEmpty() ? QObject::tr("OpenGL not started yet")
                                  : glInfo.toHtmlEscaped()));
}

} // namespace lb
