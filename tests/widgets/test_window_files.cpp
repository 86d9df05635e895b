// Files from the desktop (issue 32): `lightbench FILE...` opens a scene or a lesson, told
// apart by ending or content; a bad one (missing, a folder, a FIFO, not a scene, a lesson
// that is not one) leaves the window as it was and says why; several name the rest. The
// dialogs take .lbscene and .lblesson beside .json; Help > About and --version say the
// version of CMake's project().
#include "lesson_fixture.h"

#include "file_arguments.h"

#include <QElapsedTimer>
#include <QFileDialog>
#include <QFileInfo>

using namespace lb;
using namespace lb::test;

namespace {

// A scene that differs from the defaults in what the tests look at.
SceneFile shininessScene(float shininess)
{
    Scene scene;
    scene.objects[0].material.shininess = shininess;
    return SceneFile{scene, std::nullopt, std::nullopt};
}

} // namespace

class TestWindowFiles : public LessonWindowTest
{
    Q_OBJECT

    QString writeScene(const QString &name, float shininess)
    {
        const QString path = m_dir.filePath(name);
        return writeSceneFile(path, shininessScene(shininess)).isEmpty() ? path : QString();
    }
    // Answers the next modal widget with `answer` (polled: a static dialog blocks).
    void answerModal(const std::function<void(QWidget *)> &answer)
    {
        auto *poll = new QTimer(this);
        connect(poll, &QTimer::timeout, this, [poll, answer] {
            if (QWidget *modal = QApplication::activeModalWidget()) {
                poll->stop();
                poll->deleteLater();
                answer(modal);
            }
        });
        poll->start(20);
    }

private slots:
    // The ending decides where it says something; a .json (or any other) says by its start.
    void kindByEndingThenContent()
    {
        const QString lessonJson = writeLesson(fourSteps(), "lesson.json");
        const QString sceneJson = writeScene("scene.json", 40);
        const QString sceneAsLesson = writeScene("scene.lblesson", 40);
        QVERIFY(!lessonJson.isEmpty() && !sceneJson.isEmpty() && !sceneAsLesson.isEmpty());
        QCOMPARE(documentKind(lessonJson), DocumentKind::Lesson);
        QCOMPARE(documentKind(sceneJson), DocumentKind::Scene);
        QCOMPARE(documentKind(sceneAsLesson),
                 DocumentKind::Lesson); // opening it says it is not one
        QVERIFY(QFile::copy(lessonJson, m_dir.filePath("lesson.lbscene")));
        QCOMPARE(documentKind(m_dir.filePath("lesson.lbscene")), DocumentKind::Scene);
        QVERIFY(QFile::copy(lessonJson, m_dir.filePath("lesson.txt")));
        QCOMPARE(documentKind(m_dir.filePath("lesson.txt")), DocumentKind::Lesson);
        QCOMPARE(documentKind(m_dir.filePath("L.LBLESSON")), DocumentKind::Lesson); // in any case
        // Nothing to read: a scene's message will say why.
        QCOMPARE(documentKind(m_dir.filePath("missing.json")), DocumentKind::Scene);
        QCOMPARE(documentKind(m_dir.path()), DocumentKind::Scene);
        const QString fifo = m_dir.filePath("kind-pipe.json");
        QCOMPARE(mkfifo(fifo.toLocal8Bit().constData(), 0600), 0);
        QElapsedTimer clock;
        clock.start();
        QCOMPARE(documentKind(fifo), DocumentKind::Scene); // not opened: it would wait for a writer
        QVERIFY(clock.elapsed() < 2000);
    }

    void aSceneFileOpens()
    {
        const QString path = writeScene("desk.lbscene", 61);
        QVERIFY(!path.isEmpty());
        QVERIFY(openFileArguments(*m_window, {path}));
        QCOMPARE(scene().objects[0].material.shininess, 61.0f);
        QCOMPARE(m_window->sceneActions()->currentPath(), path);
        QVERIFY(m_window->windowTitle().startsWith("desk.lbscene"));
        QVERIFY(!m_window->findChild<QMessageBox *>(kFilesNotOpenedMessage));
    }

    // A lesson opens at its first step and closes for a scene asked for after it.
    void aLessonFileOpens()
    {
        m_settings->setValue(window_settings::kAnimateLessonsKey, false); // no glide
        const QString path = writeLesson(fourSteps(), "talk.lblesson");
        QVERIFY(!path.isEmpty());
        QVERIFY(openFileArguments(*m_window, {path}));
        QVERIFY(lessons()->isOpen());
        QCOMPARE(lessons()->currentStep(), 0);
        QVERIFY(scene() == stepScene(0));
        const QString json = writeLesson(fourSteps(), "talk.json"); // told by content
        QVERIFY(openFileArguments(*m_window, {json}));
        QVERIFY(lessons()->isOpen());
        QVERIFY(openFileArguments(*m_window, {writeScene("after.json", 33)}));
        QVERIFY(!lessons()->isOpen());
        QCOMPARE(scene().objects[0].material.shininess, 33.0f);
    }

    // Each leaves the window as it was, with the reader's message naming the file and why.
    void aBadFileChangesNothingAndSaysWhy_data()
    {
        QTest::addColumn<QString>("name");
        QTest::addColumn<QString>("why");
        QTest::newRow("missing") << "missing.lbscene"
                                 << "no such file";
        QTest::newRow("folder") << "folder.lbscene"
                                << "not a regular file";
        QTest::newRow("fifo") << "pipe.json"
                              << "not a regular file";
        QTest::newRow("not a scene") << "text.json"
                                     << "not a scene file";
        QTest::newRow("empty") << "empty.lbscene"
                               << "not a scene file";
        QTest::newRow("a scene named as a lesson") << "scene.lblesson"
                                                   << "a scene file, not a lesson";
        QTest::newRow("missing lesson") << "gone.lblesson"
                                        << "no such file";
    }
    void aBadFileChangesNothingAndSaysWhy()
    {
        QFETCH(QString, name);
        QFETCH(QString, why);
        const QString path = m_dir.filePath(name);
        if (name.startsWith("folder"))
            QVERIFY(QDir(m_dir.path()).mkdir(name));
        else if (name.startsWith("pipe"))
            QCOMPARE(mkfifo(path.toLocal8Bit().constData(), 0600), 0);
        else if (name.startsWith("text") || name.startsWith("empty")) {
            QFile f(path);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write(name.startsWith("text") ? "hello\n" : "");
        } else if (name.startsWith("scene"))
            QVERIFY(!writeScene(name, 50).isEmpty());
        m_window->document().edit([](Scene &s) { s.objects[0].material.shininess = 77; });
        const Scene before = scene();
        const bool lesson = documentKind(path) == DocumentKind::Lesson;
        QElapsedTimer clock;
        clock.start();
        QVERIFY(!openFileArguments(*m_window, {path}));
        QVERIFY(clock.elapsed() < 5000); // a FIFO is not waited on
        QVERIFY(scene() == before);
        QVERIFY(!lessons()->isOpen());
        QMessageBox *box =
            lesson ? lessons()->messageBox() : m_window->sceneActions()->messageBox();
        QVERIFY(box && box->isVisible());
        QVERIFY2(box->informativeText().contains(path) && box->informativeText().contains(why),
                 qPrintable(box->informativeText()));
        QVERIFY(box->text().contains("nothing changed"));
        box->close();
    }

    // The first opens; the others are named in one message, the first one too.
    void severalFilesOpenTheFirstAndNameTheRest()
    {
        const QString first = writeScene("first.lbscene", 21);
        const QString second = writeScene("second.json", 22);
        const QString third = writeLesson(fourSteps(), "third.lblesson");
        QVERIFY(openFileArguments(*m_window, {first, second, third}));
        QCOMPARE(scene().objects[0].material.shininess, 21.0f);
        QVERIFY(!lessons()->isOpen());
        auto *box = m_window->findChild<QMessageBox *>(kFilesNotOpenedMessage);
        QVERIFY(box && box->isVisible());
        QVERIFY2(box->text().contains("first.lbscene"), qPrintable(box->text()));
        QCOMPARE(box->informativeText(), QString("second.json\nthird.lblesson"));
    }

    // Dropped on the window, .lbscene and .lblesson open as .json files do (not as meshes).
    void droppedLbFilesOpen()
    {
        m_settings->setValue(window_settings::kAnimateLessonsKey, false);
        const auto drop = [this](const QString &path) {
            QMimeData mime;
            mime.setUrls({QUrl::fromLocalFile(path)});
            QDragEnterEvent enter(QPoint(50, 50), Qt::CopyAction, &mime, Qt::LeftButton,
                                  Qt::NoModifier);
            QApplication::sendEvent(m_window.get(), &enter); // Qt delivers no drop without it
            QDropEvent event(QPointF(50, 50), Qt::CopyAction, &mime, Qt::LeftButton,
                             Qt::NoModifier);
            QApplication::sendEvent(m_window.get(), &event);
            return event.isAccepted();
        };
        QVERIFY(drop(writeScene("dropped.lbscene", 44)));
        QVERIFY(
            QTest::qWaitFor([this] { return scene().objects[0].material.shininess == 44; }, 2000));
        QVERIFY(drop(writeLesson(fourSteps(), "dropped.lblesson")));
        QVERIFY(QTest::qWaitFor([this] { return lessons()->isOpen(); }, 2000));
        QVERIFY(scene() == stepScene(0));
    }

    // Saving without an ending: .json unless the .lbscene filter was chosen; opening lists
    // both. Qt's own dialog, answered by the test.
    void theSceneDialogsTakeLbscene()
    {
        QStringList filters;
        answerModal([&](QWidget *modal) {
            auto *dialog = qobject_cast<QFileDialog *>(modal);
            QVERIFY(dialog);
            dialog->selectNameFilter(dialog->nameFilters().value(1));
            dialog->selectFile(m_dir.filePath("chosen"));
            static_cast<QDialog *>(dialog)->accept();
        });
        QVERIFY(m_window->sceneActions()->showSaveDialog());
        QVERIFY(QFileInfo(m_dir.filePath("chosen.lbscene")).isFile());
        QCOMPARE(m_window->sceneActions()->currentPath(), m_dir.filePath("chosen.lbscene"));

        m_window->sceneActions()->forgetFile();
        answerModal([&](QWidget *modal) {
            auto *dialog = qobject_cast<QFileDialog *>(modal);
            QVERIFY(dialog);
            filters = dialog->nameFilters();
            dialog->selectFile(m_dir.filePath("plain"));
            static_cast<QDialog *>(dialog)->accept();
        });
        QVERIFY(m_window->sceneActions()->showSaveDialog());
        QVERIFY(QFileInfo(m_dir.filePath("plain.json")).isFile());
        QCOMPARE(filters.value(0), QString("Scenes (*.json)"));
        QCOMPARE(filters.value(1), QString("lightbench scenes (*.lbscene)"));

        answerModal([&](QWidget *modal) {
            auto *dialog = qobject_cast<QFileDialog *>(modal);
            QVERIFY(dialog);
            filters = dialog->nameFilters();
            dialog->reject();
        });
        QAction *open = nullptr;
        for (QAction *a : m_window->findChildren<QAction *>())
            if (a->shortcut() == QKeySequence(QKeySequence::Open))
                open = a;
        QVERIFY(open);
        open->trigger();
        QVERIFY2(filters.value(0).contains("*.lbscene") && filters.value(0).contains("*.json"),
                 qPrintable(filters.join(";;")));
    }

    void theLessonDialogsTakeLblesson()
    {
        openFourSteps();
        answerModal([&](QWidget *modal) {
            auto *dialog = qobject_cast<QFileDialog *>(modal);
            QVERIFY(dialog);
            dialog->selectNameFilter(dialog->nameFilters().value(1));
            dialog->selectFile(m_dir.filePath("talk"));
            static_cast<QDialog *>(dialog)->accept();
        });
        QAction *saveAs = nullptr;
        for (QAction *a : lessons()->lessonMenu()->actions())
            if (a->text() == "Save Lesson &As...")
                saveAs = a;
        QVERIFY(saveAs);
        saveAs->trigger();
        QVERIFY(QFileInfo(m_dir.filePath("talk.lblesson")).isFile());
        QCOMPARE(documentKind(m_dir.filePath("talk.lblesson")), DocumentKind::Lesson);
        QVERIFY(readLessonFile(m_dir.filePath("talk.lblesson")).lesson);
    }

    void aboutSaysTheVersion()
    {
        QString text;
        answerModal([&](QWidget *modal) {
            if (auto *box = qobject_cast<QMessageBox *>(modal)) {
                text = box->text();
                box->accept();
            }
        });
        showAbout(m_window.get(), {});
        QVERIFY2(text.contains("lightbench " LB_PROJECT_VERSION "</h3>"), qPrintable(text));
    }

    // main(): FILE... in the window (here with --screenshot, which grabs and quits), and
    // --version with no display at all.
    void theProgramOpensItsFileArguments()
    {
        const QString path = writeScene("shot.lbscene", 88);
        QTemporaryDir config;
        const QString png = config.filePath("shot.png");
        QCOMPARE(runLightbench({"--screenshot", png, path}, config.path()), 0);
        QVERIFY(!QImage(png).isNull());
        QSettings session(config.filePath("lightbench/lightbench.conf"), QSettings::IniFormat);
        QCOMPARE(session.value("scenes/current").toString(), path);
        // A missing file: the window still opens (and grabs), the session's scene kept.
        QCOMPARE(
            runLightbench({"--screenshot", png, m_dir.filePath("nowhere.lbscene")}, config.path()),
            0);
        QSettings again(config.filePath("lightbench/lightbench.conf"), QSettings::IniFormat);
        QCOMPARE(again.value("scenes/current").toString(), path);
        // A headless mode refuses it, as before.
        QByteArray err;
        QCOMPARE(runLightbench({"--render", png, path}, config.path(), &err), 2);
        QVERIFY2(err.contains("unexpected argument"), err.constData());

        QProcess version;
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        for (const char *display : {"DISPLAY", "WAYLAND_DISPLAY", "QT_QPA_PLATFORM"})
            env.remove(display);
        version.setProcessEnvironment(env);
        version.start(LIGHTBENCH_EXE, {"--version"});
        QVERIFY(version.waitForFinished(30000));
        QCOMPARE(version.exitCode(), 0);
        QCOMPARE(version.readAllStandardOutput(),
                 QByteArray("lightbench " LB_PROJECT_VERSION "\n"));

        // Bad input: standard output on a full disk. The version is not written, and it says so.
        if (QFileInfo::exists("/dev/full")) {
            QProcess full;
            full.setProcessEnvironment(env);
            full.setStandardOutputFile("/dev/full");
            full.start(LIGHTBENCH_EXE, {"--version"});
            QVERIFY(full.waitForFinished(30000));
            QCOMPARE(full.exitCode(), 1);
            QVERIFY(full.readAllStandardError().contains("could not write to standard output"));
        }
    }
};

int main(int argc, char **argv)
{
    // Qt's own file dialog, whatever the desktop: the test answers it.
    QCoreApplication::setAttribute(Qt::AA_DontUseNativeDialogs);
    TestWindowFiles test;
    return lb::test::runWindowTest(test, argc, argv);
}

#include "test_window_files.moc"
