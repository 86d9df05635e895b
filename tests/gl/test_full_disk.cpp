// A full disk, as a hostile tester made one: a 64 KB tmpfs in a private mount namespace (root
// only; skipped otherwise, tests/unit/test_safe_write.cpp plays it with the file size limit).
// Saving a scene, a shader pair, a PNG, the CSV report and a grading sheet onto it each fail
// with the system's reason and a non-zero exit, and the old file's bytes are unchanged. (A
// scene used to become a 0-byte file with exit 0.) The window's settings file stays whole too.
#include "program_run.h"

#include "lesson.h"
#include "safe_write.h"
#include "settings_store.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

#include <cerrno>
#include <cstring>
#include <sched.h>
#include <sys/mount.h>
#include <unistd.h>

namespace {

const QString kGrading = QStringLiteral(LB_TEST_DATA "/grading");
const QString kExercise = QStringLiteral(LB_EXAMPLES_DIR "/exercise_lighting.json");

QString g_disk;   // the small tmpfs, when there is one
QString g_noDisk; // why there is none
QTemporaryDir *g_root = nullptr;

// Before any thread starts (unshare refuses a process with threads): a mount namespace of our
// own, so the tmpfs is seen by this process and its children only, and goes with them.
void makeSmallDisk()
{
    if (::geteuid() != 0) {
        g_noDisk = "needs root (a tmpfs in a private mount namespace)";
        return;
    }
    g_root = new QTemporaryDir;
    const QString disk = g_root->filePath("disk");
    if (!QDir().mkpath(disk))
        g_noDisk = "cannot make " + disk;
    else if (::unshare(CLONE_NEWNS) != 0)
        g_noDisk = QString("unshare: %1").arg(std::strerror(errno));
    else if (::mount(nullptr, "/", nullptr, MS_REC | MS_PRIVATE, nullptr) != 0)
        g_noDisk = QString("mount --make-rprivate: %1").arg(std::strerror(errno));
    else if (::mount("tmpfs", QFile::encodeName(disk).constData(), "tmpfs", 0, "size=64k") != 0)
        g_noDisk = QString("mount tmpfs: %1").arg(std::strerror(errno));
    else
        g_disk = disk;
}

bool write(const QString &path, const QByteArray &bytes)
{
    QFile f(path);
    return f.open(QIODevice::WriteOnly | QIODevice::Truncate) && f.write(bytes) == bytes.size() &&
           f.flush();
}

QByteArray contents(const QString &path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray("(unreadable)");
}

// Fills the disk to the last byte.
bool fill()
{
    QFile f(QDir(g_disk).filePath("fill"));
    if (!f.open(QIODevice::WriteOnly | QIODevice::Unbuffered))
        return false;
    const QByteArray block(4096, '\0');
    while (f.write(block) == block.size()) {
    }
    f.close();
    return QFile(QDir(g_disk).filePath("fill")).size() > 0;
}

using Run = ProgramRun;

Run run(const QStringList &args)
{
    return runProgram(LIGHTBENCH_EXE, args, 120000);
}

} // namespace

class TestFullDisk : public QObject
{
    Q_OBJECT
private slots:
    void init()
    {
        if (g_disk.isEmpty())
            QSKIP(qPrintable(g_noDisk));
        for (const QString &name : QDir(g_disk).entryList(QDir::Files | QDir::Hidden))
            QFile::remove(QDir(g_disk).filePath(name));
        QDir(QDir(g_disk).filePath("sheets")).removeRecursively();
    }

    void eachWriterSaysWhyAndKeepsTheOldFile_data()
    {
        QTest::addColumn<QString>("what");
        QTest::newRow("--save-scene") << "scene";
        QTest::newRow("--render (PNG)") << "png";
        QTest::newRow("--report (CSV)") << "csv";
        QTest::newRow("--sheets (a grading sheet)") << "sheet";
        QTest::newRow("a shader pair (File > Save Shaders)") << "pair";
        QTest::newRow("a lesson (Lesson > Save Lesson)") << "lesson";
    }

    void eachWriterSaysWhyAndKeepsTheOldFile()
    {
        QFETCH(QString, what);
        const QDir disk(g_disk);
        const QByteArray old = "{\"format\": \"lightbench-scene\", \"version\": 3}\n";
        QString target;
        if (what == "sheet") {
            QVERIFY(disk.mkdir("sheets"));
            target = disk.filePath("sheets/correct.png");
        } else {
            target = disk.filePath(what == "scene"    ? "s.json"
                                   : what == "png"    ? "r.png"
                                   : what == "csv"    ? "r.csv"
                                   : what == "lesson" ? "l.json"
                                                      : "pair.vert");
        }
        QVERIFY(write(target, old));
        const QString fragment = disk.filePath("pair.frag");
        if (what == "pair")
            QVERIFY(write(fragment, "void main() {}\n"));
        QVERIFY(fill());

        QString message;
        if (what == "pair") {
            message = lb::writeFilesSafely(
                {{target, "attribute vec4 vPosition;\nvoid main() { gl_Position = vPosition; }\n"},
                 {fragment, "void main() { gl_FragColor = vec4(1.0); }\n"}});
            QCOMPARE(contents(fragment), QByteArray("void main() {}\n"));
        } else if (what == "lesson") {
            lb::Lesson lesson;
            lesson.steps.resize(3);
            message = lb::writeLessonFile(target, lesson);
        } else {
            QStringList args;
            if (what == "scene")
                args = {"--scene", target, "--save-scene", target};
            else if (what == "png")
                args = {"--render", target, "--size", "64x64"};
            else if (what == "csv")
                args = {"--grade", kGrading + "/correct", "--exercise", kExercise, "--report",
                        target};
            else
                args = {"--grade",  kGrading + "/correct",  "--exercise", kExercise,
                        "--sheets", disk.filePath("sheets")};
            const Run r = run(args);
            QVERIFY2(
                r.exitCode == 1,
                qPrintable(QString("exit %1: %2").arg(r.exitCode).arg(QString::fromUtf8(r.err))));
            message = QString::fromUtf8(r.err + r.out); // a sheet's failure is its line
        }
        QVERIFY2(message.contains(target + ": No space left on device"), qPrintable(message));
        QCOMPARE(contents(target), old);
        // Nothing but the files put there: no temporary left behind.
        QStringList expected{"fill", QFileInfo(target).fileName()};
        if (what == "pair")
            expected << "pair.frag";
        QDir where(QFileInfo(target).absolutePath());
        QStringList left = where.entryList(QDir::Files | QDir::Hidden);
        if (what != "sheet")
            QCOMPARE(QSet<QString>(left.begin(), left.end()),
                     QSet<QString>(expected.begin(), expected.end()));
        else
            QCOMPARE(left, QStringList{"correct.png"});
    }

    // The window's settings (its session: scene, layout, editor text) are written whole or
    // not at all: QSettings' own writer left an empty file on a full disk.
    void theSettingsFileStaysWhole()
    {
        const QString path = QDir(g_disk).filePath("lightbench.conf");
        {
            lb::SettingsStore store(path);
            QCOMPARE(store.error(), QString());
            store.settings().setValue("scene", QByteArray(3000, 's'));
            QCOMPARE(store.save(), QString());
        }
        const QByteArray old = contents(path);
        QVERIFY(old.contains("scene="));
        lb::SettingsStore store(path);
        QCOMPARE(store.settings().value("scene").toByteArray(), QByteArray(3000, 's'));
        QVERIFY(fill());
        store.settings().setValue("editor", QByteArray(5000, 'e'));
        const QString error = store.save();
        QVERIFY2(error == path + ": No space left on device", qPrintable(error));
        QCOMPARE(contents(path), old);
        QVERIFY(QFile::remove(QDir(g_disk).filePath("fill")));
        QCOMPARE(store.save(), QString()); // room again: all of it, the earlier value too
        lb::SettingsStore again(path);
        QCOMPARE(again.settings().value("editor").toByteArray(), QByteArray(5000, 'e'));
        QCOMPARE(again.settings().value("scene").toByteArray(), QByteArray(3000, 's'));
    }
};

int main(int argc, char **argv)
{
    makeSmallDisk();
    QCoreApplication app(argc, argv);
    TestFullDisk test;
    const int status = QTest::qExec(&test, argc, argv);
    if (!g_disk.isEmpty())
        ::umount2(QFile::encodeName(g_disk).constData(), MNT_DETACH);
    delete g_root;
    return status;
}

#include "test_full_disk.moc"
