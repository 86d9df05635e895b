#include "window_fixture.h"

#include <QDockWidget>
#include <QScrollArea>
#include <QScrollBar>

namespace lb::test {

const QString kCube = "/usr/share/assimp/models/PLY/cube.ply";
const QString kMalformed = "/usr/share/assimp/models/invalid/malformed.obj";

int imageDifference(const QImage &a, const QImage &b)
{
    if (a.size() != b.size())
        return 255;
    int worst = 0;
    for (int y = 0; y < a.height(); y += 2)
        for (int x = 0; x < a.width(); x += 2) {
            const QRgb p = a.pixel(x, y), q = b.pixel(x, y);
            worst = std::max({worst, std::abs(qRed(p) - qRed(q)), std::abs(qGreen(p) - qGreen(q)),
                              std::abs(qBlue(p) - qBlue(q))});
        }
    return worst;
}

QImage WindowTest::frame()
{
    QCoreApplication::processEvents();
    return m_window->viewport()->grabFramebuffer();
}

std::pair<bool, QString> WindowTest::openMesh(const QString &path)
{
    QSignalSpy finished(m_window->objectLoader(), &ObjectLoader::loadFinished);
    m_window->meshActions()->open(path);
    if (finished.isEmpty() && !finished.wait(30000))
        return {false, "no answer"};
    QCoreApplication::processEvents();
    return {finished.first()[0].toBool(), finished.first()[1].toString()};
}

std::optional<ProgramBuild> WindowTest::buildAfter(const std::function<void()> &action)
{
    // What was on its way before (a program opened with a scene, being tried) has arrived
    // first: its answer is not taken for the action's (CI's sanitizer pass took an exercise's
    // own program's answer for the next one's, typed meanwhile and still in the live compile's
    // pause).
    (void)QTest::qWaitFor([&] { return m_window->isSettled(); }, 30000);
    std::optional<ProgramBuild> built;
    const QMetaObject::Connection c = connect(m_window->viewport(), &Viewport::programBuilt, this,
                                              [&](const ProgramBuild &b) { built = b; });
    action();
    if (!QTest::qWaitFor([&] { return built.has_value(); }, 10000))
        built.reset(); // none came: the caller's check fails
    disconnect(c);
    // Objects that arrive after a program was tried on an empty view have it tried again on
    // them, with the built-in program drawing meanwhile (Viewport::setObject): the picture is
    // the program's once that is over. (Under AddressSanitizer in CI the shapes came after.)
    // Not a failure here: the callers that read pixels check isSettled().
    (void)QTest::qWaitFor([&] { return m_window->isSettled(); }, 30000);
    QCoreApplication::processEvents(); // the editor and panels hear the same signal
    return built;
}

void WindowTest::init()
{
    m_settings = std::make_unique<QSettings>(m_dir.filePath("settings.ini"), QSettings::IniFormat);
    m_settings->clear();
    m_window = std::make_unique<MainWindow>(*m_settings);
    m_window->show();
    m_window->activateWindow(); // shortcuts only reach the active window
    QVERIFY(QTest::qWaitForWindowActive(m_window.get()));
    QVERIFY2(m_window->viewport()->renderError().isEmpty(),
             qPrintable(m_window->viewport()->renderError()));
}

QString writeSlowImportHelper(const QTemporaryDir &dir)
{
    const QString helper = dir.filePath("slow-helper.sh");
    QFile f(helper);
    if (!f.open(QIODevice::WriteOnly) || f.write("#!/bin/sh\nexec sleep 600\n") < 0)
        return {};
    f.close();
    f.setPermissions(QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner);
    return helper;
}

QString docksNeedingSideways(MainWindow &window)
{
    QStringList wide;
    for (QDockWidget *dock : window.panelDocks()) {
        dock->raise();
        QCoreApplication::processEvents();
        auto *scroll = qobject_cast<QScrollArea *>(dock->widget());
        if (scroll && (scroll->horizontalScrollBar()->isVisible() ||
                       scroll->widget()->minimumSizeHint().width() > scroll->viewport()->width()))
            wide << QString("%1 (%2 px for %3)")
                        .arg(dock->windowTitle())
                        .arg(scroll->viewport()->width())
                        .arg(scroll->widget()->minimumSizeHint().width());
    }
    return wide.join(", ");
}

int runWindowTest(WindowTest &test, int argc, char **argv)
{
    setDefaultGlFormat();
    QApplication app(argc, argv);
    return QTest::qExec(&test, argc, argv);
}

} // namespace lb::test
