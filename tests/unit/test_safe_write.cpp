// The one writer every file goes through (render/model/safe_write.h): what it refuses, what it
// keeps when a write fails, and what it says. A full disk is played by the file size limit
// here (any user can set it: `ulimit -f`); tests/gl/test_full_disk.cpp fills a real one.
#include "bounded_read.h"
#include "safe_write.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QImage>
#include <QTemporaryDir>
#include <QTest>

#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

using namespace lb;

namespace {

QByteArray contents(const QString &path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray("(unreadable)");
}

// Files and links in `dir`, hidden ones (the writer's temporaries) included.
QStringList entries(const QDir &dir)
{
    return dir.entryList(QDir::Files | QDir::Hidden | QDir::System | QDir::NoDotAndDotDot,
                         QDir::Name);
}

// The file size limit for one scope (the soft limit only: it can be raised back).
class FileSizeLimit
{
public:
    explicit FileSizeLimit(rlim_t bytes)
    {
        ::getrlimit(RLIMIT_FSIZE, &m_old);
        rlimit limit = m_old;
        limit.rlim_cur = bytes;
        m_ok = ::setrlimit(RLIMIT_FSIZE, &limit) == 0;
    }
    ~FileSizeLimit() { ::setrlimit(RLIMIT_FSIZE, &m_old); }
    bool ok() const { return m_ok; }

private:
    rlimit m_old{};
    bool m_ok = false;
};

} // namespace

class TestSafeWrite : public QObject
{
    Q_OBJECT
private slots:
    void writesAndReplaces()
    {
        QTemporaryDir tmp;
        const QString path = tmp.filePath("a.json");
        QCOMPARE(writeFileSafely(path, "first"), QString());
        QCOMPARE(writeFileSafely(path, "second"), QString());
        QCOMPARE(contents(path), QByteArray("second"));
        QCOMPARE(entries(QDir(tmp.path())), QStringList{"a.json"}); // no temporary left
    }

    // A write past the file size limit (a quota, `ulimit -f`) raised SIGXFSZ, which killed
    // the process without a word. Now it is "File too large" and the old file stays.
    void aFailedWriteKeepsTheOldFile()
    {
        QTemporaryDir tmp;
        const QString path = tmp.filePath("scene.json"), image = tmp.filePath("frame.png");
        QCOMPARE(writeFileSafely(path, "the old scene"), QString());
        QImage old(8, 8, QImage::Format_RGB32);
        old.fill(Qt::red);
        QCOMPARE(writeImageSafely(image, old), QString());
        const QByteArray oldImage = contents(image);
        QString error, imageError, pairError;
        {
            const FileSizeLimit limit(1000);
            QVERIFY(limit.ok());
            error = writeFileSafely(path, QByteArray(5000, 'x'));
            QImage noise(200, 200, QImage::Format_RGB32);
            for (int y = 0; y < noise.height(); ++y)
                for (int x = 0; x < noise.width(); ++x)
                    noise.setPixel(x, y, uint(x * 7919 + y * 104729) * 2654435761u);
            imageError = writeImageSafely(image, noise);
            // A pair whose second file fails changes neither.
            pairError = writeFilesSafely({{tmp.filePath("pair.vert"), "small"},
                                          {tmp.filePath("pair.frag"), QByteArray(5000, 'y')}});
        }
        QCOMPARE(error, path + ": File too large");
        QCOMPARE(contents(path), QByteArray("the old scene"));
        QCOMPARE(imageError, image + ": File too large");
        QCOMPARE(contents(image), oldImage);
        QCOMPARE(pairError, tmp.filePath("pair.frag") + ": File too large");
        QCOMPARE(entries(QDir(tmp.path())), QStringList({"frame.png", "scene.json"}));
    }

    void targetsThatAreNoFilesAreRefused_data()
    {
        QTest::addColumn<QString>("kind");
        QTest::addColumn<QString>("named");
        QTest::newRow("FIFO") << "fifo"
                              << "pipe: not a regular file";
        QTest::newRow("/dev/null") << "device"
                                   << "/dev/null: not a regular file";
        QTest::newRow("folder") << "folder"
                                << "folder: not a regular file";
        QTest::newRow("link to a FIFO") << "link to fifo"
                                        << "link: not a regular file";
        QTest::newRow("link loop") << "loop"
                                   << "loop1: a loop of symbolic links";
        QTest::newRow("missing folder") << "missing folder"
                                        << "/nowhere does not exist";
        QTest::newRow("a file as folder") << "file as folder"
                                          << "plain/a.json: Not a directory";
    }

    void targetsThatAreNoFilesAreRefused()
    {
        QFETCH(QString, kind);
        QFETCH(QString, named);
        QTemporaryDir tmp;
        const QDir dir(tmp.path());
        QString path;
        const auto link = [&](const QString &from, const QString &to) {
            return QFile::link(to, dir.filePath(from));
        };
        if (kind == "fifo" || kind == "link to fifo") {
            QCOMPARE(::mkfifo(QFile::encodeName(dir.filePath("pipe")).constData(), 0600), 0);
            path = dir.filePath("pipe");
            if (kind == "link to fifo") {
                QVERIFY(link("link", path));
                path = dir.filePath("link");
            }
        } else if (kind == "device") {
            path = "/dev/null";
        } else if (kind == "folder") {
            QVERIFY(dir.mkdir("folder"));
            path = dir.filePath("folder");
        } else if (kind == "loop") {
            QVERIFY(link("loop1", dir.filePath("loop2")) && link("loop2", dir.filePath("loop1")));
            path = dir.filePath("loop1");
        } else if (kind == "missing folder") {
            path = "/nowhere/a.json";
        } else {
            QCOMPARE(writeFileSafely(dir.filePath("plain"), "x"), QString());
            path = dir.filePath("plain/a.json");
        }
        const QString before = unwritableTarget(path);
        QVERIFY2(before.contains(named), qPrintable(before));
        QCOMPARE(writeFileSafely(path, "data"), before);
        if (kind == "device" || kind.contains("fifo")) {
            struct stat st;
            QCOMPARE(::stat(QFile::encodeName(path).constData(), &st), 0);
            QVERIFY(!S_ISREG(st.st_mode)); // still what it was
        }
    }

    // A link is written through: the file it names gets the bytes, the link stays a link.
    // The permissions of the file replaced are kept (a teacher's read-only-for-others sheet).
    void linksAndPermissionsAreKept()
    {
        QTemporaryDir tmp;
        const QDir dir(tmp.path());
        QVERIFY(dir.mkdir("real"));
        const QString real = dir.filePath("real/scene.json"), link = dir.filePath("scene.json");
        QCOMPARE(writeFileSafely(real, "old"), QString());
        QVERIFY(QFile::setPermissions(real, QFile::ReadOwner | QFile::WriteOwner));
        QVERIFY(QFile::link("real/scene.json", link));
        QCOMPARE(writeFileSafely(link, "new"), QString());
        QVERIFY(QFileInfo(link).isSymLink());
        QCOMPARE(contents(real), QByteArray("new"));
        QCOMPARE(QFile::permissions(real),
                 QFile::ReadOwner | QFile::WriteOwner | QFile::ReadUser | QFile::WriteUser);
        // A link to a file not there yet makes it.
        QVERIFY(QFile::link("real/new.json", dir.filePath("dangling.json")));
        QCOMPARE(writeFileSafely(dir.filePath("dangling.json"), "made"), QString());
        QCOMPARE(contents(dir.filePath("real/new.json")), QByteArray("made"));
    }

    // A name as long as the file system allows is written: the temporary beside it kept 200
    // UTF-16 units of the name, over 255 bytes for 80 CJK characters (240 bytes + ".png").
    void longNamesAreWritten()
    {
        QTemporaryDir tmp;
        const QDir dir(tmp.path());
        const QString emoji = QString::fromUcs4(U"\U0001F600"); // 4 bytes, two UTF-16 units
        for (const QString &name : {QString(80, QChar(0x6f22)) + ".png", QString(251, 'x') + ".csv",
                                    emoji.repeated(62) + ".png"}) {
            QVERIFY(QFile::encodeName(name).size() <= 255);
            QCOMPARE(writeFileSafely(dir.filePath(name), "bytes"), QString());
            QCOMPARE(contents(dir.filePath(name)), QByteArray("bytes"));
        }
        QCOMPARE(entries(dir).size(), 3);                               // no temporary left
        QCOMPARE(leftInBytes(emoji.repeated(3), 9), emoji.repeated(2)); // never half of one
        QCOMPARE(leftInBytes("abc", 0), QString());
    }

    // A read-only file in a writable folder is refused, as cp refuses it: `--report ro.csv`
    // and `--plot-data` over a 0444 file replaced it with exit 0 (issue 49). Through a link
    // too; a writable one beside it is still replaced, and a new file is made.
    void readOnlyFilesAreNotReplaced()
    {
        QTemporaryDir tmp;
        const QDir dir(tmp.path());
        const QString ro = dir.filePath("ro.csv");
        QCOMPARE(writeFileSafely(ro, "the teacher's"), QString());
        QVERIFY(QFile::setPermissions(ro, QFile::ReadOwner | QFile::ReadGroup | QFile::ReadOther));
        const QString error = writeFileSafely(ro, "a student's");
        QVERIFY2(error.contains("ro.csv: read-only (mode 0444); not replaced"), qPrintable(error));
        QCOMPARE(contents(ro), QByteArray("the teacher's"));
        QVERIFY(QFile::link("ro.csv", dir.filePath("link.csv")));
        QVERIFY(writeFileSafely(dir.filePath("link.csv"), "x").contains("read-only"));
        QVERIFY(unwritableTarget(ro).contains("read-only"));
        QCOMPARE(contents(ro), QByteArray("the teacher's"));
        const QString sheet = dir.filePath("sheet.png");
        QCOMPARE(writeFileSafely(sheet, "old"), QString());
        QVERIFY(QFile::setPermissions(sheet, QFile::ReadOwner));
        QVERIFY(writeImageSafely(sheet, QImage(2, 2, QImage::Format_RGB32)).contains("read-only"));
        QCOMPARE(contents(sheet), QByteArray("old"));
        QCOMPARE(entries(dir), (QStringList{"link.csv", "ro.csv", "sheet.png"})); // no temporary
        QCOMPARE(writeFileSafely(dir.filePath("new.csv"), "made"), QString());
    }

    // Reading names a loop as a loop (it said "no such file") and a link to nothing as that.
    void readsNameLinksThatLeadNowhere()
    {
        QTemporaryDir tmp;
        const QDir dir(tmp.path());
        QVERIFY(QFile::link(dir.filePath("b"), dir.filePath("a")) &&
                QFile::link(dir.filePath("a"), dir.filePath("b")));
        QCOMPARE(unreadableFile(dir.filePath("a"), {"a scene file", 1024}),
                 dir.filePath("a") + ": a loop of symbolic links");
        QVERIFY(QFile::link(dir.filePath("gone"), dir.filePath("c")));
        QCOMPARE(unreadableFile(dir.filePath("c"), {"a scene file", 1024}),
                 dir.filePath("c") + ": a symbolic link to " + dir.filePath("gone") +
                     ", which does not exist");
        QCOMPARE(unreadableFile(dir.filePath("d"), {"a scene file", 1024}),
                 dir.filePath("d") + ": no such file");
    }
};

QTEST_GUILESS_MAIN(TestSafeWrite)
#include "test_safe_write.moc"
