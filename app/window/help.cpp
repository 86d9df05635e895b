#include "help.h"

#include "lightbench_version.h"

#include <QAction>
#include <QCoreApplication>
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

// The translation context of the help windows' words ("lb::Help" in the .ts files).
struct Help
{
    Q_DECLARE_TR_FUNCTIONS(lb::Help)
};

QString row(const QString &keys, const QString &what)
{
    return QString("<tr><td style='padding-right:16px'><b>%1</b></td><td>%2</td></tr>")
        .arg(keys.toHtmlEscaped(), what.toHtmlEscaped());
}

QString keyName(const QKeySequence &key)
{
    return key.toString(QKeySequence::NativeText);
}

// "F11 or F5": the keys that do the same, in the translator's words and order. Key names
// are Qt's own (QKeySequence's native text, which Qt's catalogue translates).
QString alternatives(const QList<QKeySequence> &keys)
{
    QStringList names;
    for (const QKeySequence &k : keys)
        names << keyName(k);
    if (names.size() < 2)
        return names.value(0);
    QString text = names.takeFirst();
    const QString last = names.takeLast();
    for (const QString &name : names)
        //: shortcuts that do the same: all but the last two, "Ctrl++, Ctrl+= or ..."
        text = Help::tr("%1, %2").arg(text, name);
    //: shortcuts that do the same: "F11 or F5"
    return Help::tr("%1 or %2").arg(text, last);
}

// Two keys for two actions side by side: "Ctrl+Z / Ctrl+Y" for "undo / redo".
QString keyPair(const QKeySequence &first, const QKeySequence &second)
{
    return QString("%1 / %2").arg(keyName(first), keyName(second));
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
        html += row(alternatives(a->shortcuts()), path + " > " + a->text().remove('&'));
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
    const QString heading = "<tr><td colspan='2'><h3>%1</h3></td></tr>";
    QString html = "<table cellspacing='3'>";
    //: Help > Keyboard Shortcuts: the heading over every menu's keys
    html += heading.arg(Help::tr("Menus"));
    for (const QAction *a : menus->actions())
        if (a->menu())
            addMenu(html, a->menu(), a->menu()->title().remove('&'));
    html += heading.arg(Help::tr("Shader editor"));
    html += row(keyName(QKeySequence(Qt::CTRL | Qt::Key_Enter)), Help::tr("compile and link now"));
    html += row(keyName(QKeySequence(Qt::CTRL | Qt::Key_F)), Help::tr("find in the shader"));
    html += row(keyPair(QKeySequence(Qt::CTRL | Qt::Key_Z), QKeySequence(Qt::CTRL | Qt::Key_Y)),
                Help::tr("undo / redo (also what a preset, an example or a reset replaced)"));
    html += row(keyName(QKeySequence(Qt::CTRL | Qt::Key_Space)), Help::tr("complete the word"));
    html += row(keyPair(QKeySequence(Qt::CTRL | Qt::Key_L), QKeySequence(Qt::CTRL | Qt::Key_D)),
                Help::tr("delete / duplicate the line"));
    //: Help > Keyboard Shortcuts: the heading over the mouse and keys of the 3D view (not
    //: the View menu)
    html += heading.arg(Help::tr("View"));
    html += row(Help::tr("left drag"), Help::tr("orbit the camera"));
    html += row(Help::tr("click"), Help::tr("select the object under the cursor"));
    html += row(Help::tr("right or middle drag"), Help::tr("pan"));
    html += row(Help::tr("wheel"), Help::tr("zoom"));
    //: the keys as the keyboard names them (Ctrl, Shift), held while clicking
    html += row(Help::tr("Ctrl+click, Shift+click"),
                Help::tr("probe the surface point (drag to move it)"));
    html += row(Help::tr("drag the wipe's line"), Help::tr("move the wipe (compare)"));
    html +=
        row(Help::tr("drop a file"), Help::tr("open a mesh, a scene, a lesson or a shader pair"));
    html += "</table>";
    return html;
}

void showShortcuts(QWidget *parent, const QMenuBar *menus)
{
    QTextBrowser *browser = nullptr;
    QDialog *dialog = textWindow(parent, Help::tr("Keyboard shortcuts - lightbench"), browser);
    browser->setHtml(shortcutsHtml(menus));
    dialog->setObjectName("shortcutsWindow");
    dialog->show();
}

void showFeatures(QWidget *parent)
{
    QTextBrowser *browser = nullptr;
    QDialog *dialog = textWindow(parent, Help::tr("Features - lightbench"), browser);
    QFile readme(":/docs/README.md");
    browser->setSearchPaths({":/docs"}); // its screenshots, by their paths in the README
    if (readme.open(QIODevice::ReadOnly))
        browser->setMarkdown(QString::fromUtf8(readme.readAll()));
    else
        browser->setPlainText(Help::tr("The README is missing from this build."));
    dialog->setObjectName("featuresWindow");
    dialog->show();
}

void showAbout(QWidget *parent, const QString &glInfo)
{
    QMessageBox::about(
        parent, Help::tr("About lightbench"),
        Help::tr("<h3>lightbench %1</h3><p>A workbench for the lighting model of computer "
                 "graphics courses: ambient, diffuse and specular terms, Phong and "
                 "Blinn-Phong, Gouraud and Phong shading, every pixel checked against a CPU "
                 "reference.</p><p>Qt %2 (built with %3)<br>%4</p>")
            .arg(QStringLiteral(LIGHTBENCH_VERSION), QString::fromLatin1(qVersion()),
                 QStringLiteral(QT_VERSION_STR),
                 glInfo.isEmpty() ? Help::tr("OpenGL not started yet") : glInfo.toHtmlEscaped()));
}

} // namespace lb
