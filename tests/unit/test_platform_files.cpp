// The platform room's file calls (render/platform: file_status.h, exclusive_file.h,
// read_only_file.h, signal_names.h), asked directly, so that the Linux layer and the portable
// one (-DLIGHTBENCH_PORTABLE=ON) are held to the same answers. The bad inputs tried: a FIFO
// (which a blocking open would wait on for ever), /dev/null, a folder, a link loop, a link to
// nothing, a file used as a folder, a missing file, a name already taken (also by a link to
// nothing, which must not be written through), a read past the end and a seek past it.
// The writer and the helper over them are tested in test_safe_write and test_side_files.
#include "exclusive_file.h"
#include "file_status.h"
#include "process_bounds.h"
#include "qt_paths.h"
#include "read_only_file.h"
#include "signal_names.h"

#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QTemporaryDir>
#include <QTest>

#include <atomic>
#include <csignal>
#include <thread>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

using namespace lb;
using namespace lb::platform;

namespace {

std::filesystem::path native(const QString &path)
{
    return nativePath(path);
}

QByteArray contents(const QString &path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray("(unreadable)");
}

void write(const QString &path, const QByteArray &bytes)
{
    QFile f(path);
    QVERIFY2(f.open(QIODevice::WriteOnly), qPrintable(path));
    QCOMPARE(f.write(bytes), bytes.size());
}

QStringList entries(const QString &folder)
{
    return QDir(folder).entryList(
        QDir::AllEntries | QDir::Hidden | QDir::System | QDir::NoDotAndDotDot, QDir::Name);
}

} // namespace

class TestPlatformFiles : public QObject
{
    Q_OBJECT
private:
    QTemporaryDir m_tmp;
    QString at(const QString &name) const { return m_tmp.filePath(name); }

private slots:
    void initTestCase()
    {
        QVERIFY(m_tmp.isValid());
        qInfo("platform layer: %s", platform::name());
        write(at("file"), "0123456789");
        QVERIFY(QFile::setPermissions(at("file"), QFile::ReadOwner | QFile::WriteOwner |
                                                      QFile::ReadGroup | QFile::ReadOther));
        QVERIFY(QDir(m_tmp.path()).mkdir("folder"));
        QCOMPARE(::mkfifo(QFile::encodeName(at("fifo")).constData(), 0600), 0);
        QVERIFY(QFile::link("file", at("link")));
        QVERIFY(QFile::link("gone", at("dangling")));
        QVERIFY(QFile::link(at("loop2"), at("loop1")) && QFile::link(at("loop1"), at("loop2")));
    }

    void kindsWithAndWithoutLinks_data()
    {
        QTest::addColumn<QString>("path");
        QTest::addColumn<bool>("follow");
        QTest::addColumn<int>("kind");
        QTest::addColumn<int>("error");
        QTest::addColumn<QString>("reason"); // the system's words, where they are asked for
        const auto row = [](const char *tag, const QString &path, bool follow, FileKind kind,
                            FileError::Code error, const QString &reason = {}) {
            QTest::newRow(tag) << path << follow << int(kind) << int(error) << reason;
        };
        row("file", at("file"), true, FileKind::Regular, FileError::None);
        row("folder", at("folder"), true, FileKind::Folder, FileError::None);
        row("FIFO", at("fifo"), true, FileKind::Fifo, FileError::None);
        row("/dev/null", "/dev/null", true, FileKind::Device, FileError::None);
        row("link kept", at("link"), false, FileKind::Link, FileError::None);
        row("link followed", at("link"), true, FileKind::Regular, FileError::None);
        row("link to nothing kept", at("dangling"), false, FileKind::Link, FileError::None);
        row("link to nothing followed", at("dangling"), true, FileKind::Unknown,
            FileError::Missing);
        row("loop kept", at("loop1"), false, FileKind::Link, FileError::None);
        row("loop followed", at("loop1"), true, FileKind::Unknown, FileError::Loop);
        row("missing", at("nothing"), true, FileKind::Unknown, FileError::Missing);
        row("a file as folder", at("file/inside"), false, FileKind::Unknown, FileError::Other,
            "Not a directory");
    }

    void kindsWithAndWithoutLinks()
    {
        QFETCH(QString, path);
        QFETCH(bool, follow);
        QFETCH(int, kind);
        QFETCH(int, error);
        QFETCH(QString, reason);
        const FileStatus st = fileStatus(native(path), follow ? Links::Follow : Links::Keep);
        QCOMPARE(int(st.kind), kind);
        QCOMPARE(int(st.error.code), error);
        QCOMPARE(bool(st.error), error != FileError::None);
        QCOMPARE(st.error.reason.empty(), error == FileError::None);
        if (!reason.isEmpty())
            QCOMPARE(errorText(st.error), reason);
    }

    void sizeAndPermissions()
    {
        const FileStatus st = fileStatus(native(at("link")), Links::Follow);
        QCOMPARE(st.size, std::uint64_t(10));
        QCOMPARE(st.permissions, 0644u);
        // The owner: this user's own file, and "/" only for root; never "ours" where the
        // layer cannot tell.
        QCOMPARE(fileStatus(native(at("file")), Links::Keep).ownedByThisUser, canTellOwners());
        QCOMPARE(fileStatus(native("/"), Links::Keep).ownedByThisUser,
                 canTellOwners() && QFileInfo("/").ownerId() == QFileInfo(at("file")).ownerId());
    }

    void linksAreReadAndResolved()
    {
        FileError error;
        QCOMPARE(fromNativePath(linkTarget(native(at("link")), error)), QString("file"));
        QVERIFY(!error);
        QVERIFY(linkTarget(native(at("file")), error).empty()); // no link
        QCOMPARE(error.code, FileError::Other);

        const QString real = QFileInfo(at("file")).canonicalFilePath();
        QCOMPARE(fromNativePath(resolvedPath(native(at("folder/../link")), error)), real);
        QVERIFY(!error);
        QVERIFY(resolvedPath(native(at("dangling")), error).empty());
        QCOMPARE(error.code, FileError::Missing);
        QVERIFY(resolvedPath(native(at("loop1")), error).empty());
        QCOMPARE(error.code, FileError::Loop);
    }

    void foldersThatTakeNewFiles()
    {
        QVERIFY(!creatingFilesRefused(native(m_tmp.path())));
        QCOMPARE(creatingFilesRefused(native(at("nowhere"))).code, FileError::Missing);
        if (::geteuid() == 0)
            QSKIP("root writes in a read-only folder");
        QVERIFY(QDir(m_tmp.path()).mkdir("closed"));
        QVERIFY(QFile::setPermissions(at("closed"), QFile::ReadOwner | QFile::ExeOwner));
        const FileError refused = creatingFilesRefused(native(at("closed")));
        QFile::setPermissions(at("closed"), QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner);
        QCOMPARE(errorText(refused), QString("Permission denied"));
    }

    // A temporary file: never an existing name (not even a link's, which would write through
    // it), written, kept permissions, put over its target in one step, or removed.
    void exclusiveFileReplacesOrLeavesNothing()
    {
        QTemporaryDir tmp;
        const QString target = tmp.filePath("target"), temp = tmp.filePath(".target.tmp");
        write(target, "old");
        {
            ExclusiveFile taken;
            QCOMPARE(taken.create(target).code, FileError::Exists);
            QVERIFY(QFile::link(tmp.filePath("elsewhere"), temp));
            QCOMPARE(taken.create(temp).code, FileError::Exists);
            QVERIFY(!QFileInfo::exists(tmp.filePath("elsewhere")));
            QVERIFY(QFile::remove(temp));
        }
        QCOMPARE(contents(target), QByteArray("old"));
        {
            ExclusiveFile dropped; // goes without a commit: nothing is left
            QVERIFY(!dropped.create(temp));
            QVERIFY(!dropped.writeAll("half", 4));
        }
        QCOMPARE(entries(tmp.path()), QStringList{"target"});

        ExclusiveFile file;
        QVERIFY(!file.create(temp));
        file.keepPermissions(0604);
        const QByteArray bytes(300000, 'n'); // more than one write may take
        QVERIFY(!file.writeAll(bytes.constData(), std::size_t(bytes.size())));
        QVERIFY(!file.finish());
        QCOMPARE(contents(target), QByteArray("old")); // until the commit
        QVERIFY(!file.commitOver(target));
        file.discard(); // committed: no longer its to remove
        QCOMPARE(contents(target), bytes);
        QCOMPARE(entries(tmp.path()), QStringList{"target"});
        QCOMPARE(fileStatus(native(target), Links::Keep).permissions, 0604u);
    }

    // Only a regular file is opened, and a FIFO is not waited on (no writer ever comes here).
    void onlyRegularFilesAreOpened_data()
    {
        QTest::addColumn<QString>("path");
        QTest::newRow("FIFO") << at("fifo");
        QTest::newRow("folder") << at("folder");
        QTest::newRow("/dev/null") << "/dev/null";
        QTest::newRow("link") << at("link"); // the caller resolves links: one here is a race
        QTest::newRow("missing") << at("nothing");
    }

    void onlyRegularFilesAreOpened()
    {
        QFETCH(QString, path);
        std::atomic<bool> done{false};
        FileStatus opened;
        bool gotFile = true;
        std::thread open([&] {
            gotFile = bool(ReadOnlyFile::open(native(path), opened));
            done = true;
        });
        QElapsedTimer clock;
        clock.start();
        while (!done && clock.elapsed() < 10000)
            QTest::qWait(10);
        if (!done) { // a writer lets the open go, so that the thread can end
            const int fd = ::open(QFile::encodeName(path).constData(), O_WRONLY | O_NONBLOCK);
            open.join();
            ::close(fd);
            QFAIL("the open waited for a writer");
        }
        open.join();
        QVERIFY(!gotFile);
        QVERIFY(opened.error || opened.kind != FileKind::Regular);
        if (path.endsWith("nothing"))
            QCOMPARE(opened.error.code, FileError::Missing);
    }

    void readsAndSeeksWithinTheFile()
    {
        FileStatus opened;
        const std::unique_ptr<ReadOnlyFile> file = ReadOnlyFile::open(native(at("file")), opened);
        QVERIFY(file);
        QCOMPARE(int(opened.kind), int(FileKind::Regular));
        QCOMPARE(opened.size, std::uint64_t(10));
        char buffer[16] = {};
        QCOMPARE(file->read(buffer, 4, 3), std::size_t(2)); // 10 bytes: two whole items
        QCOMPARE(QByteArray(buffer, 10), QByteArray("0123456789"));
        QCOMPARE(file->position(), 10ll);
        QVERIFY(file->seek(4));
        QCOMPARE(file->read(buffer, 2, 1), std::size_t(1));
        QCOMPARE(QByteArray(buffer, 2), QByteArray("45"));
        QCOMPARE(file->position(), 6ll);
        QVERIFY(file->seek(10));
        QCOMPARE(file->read(buffer, 1, 4), std::size_t(0));
        QVERIFY(file->seek(0)); // still works after a read at the end
        QCOMPARE(file->read(buffer, 1, 1), std::size_t(1));
        QCOMPARE(buffer[0], '0');
    }

    // The names a crash message shows: the C library's words in both layers.
    void signalsByName()
    {
        QCOMPARE(signalName(SIGSEGV), QString("Segmentation fault"));
        QCOMPARE(signalName(SIGABRT), QString("Aborted"));
        QCOMPARE(signalName(SIGFPE), QString("Floating point exception"));
        QCOMPARE(signalName(SIGTERM), QString("Terminated"));
        QVERIFY(signalName(1000).contains("1000"));
    }
};

QTEST_GUILESS_MAIN(TestPlatformFiles)
#include "test_platform_files.moc"
