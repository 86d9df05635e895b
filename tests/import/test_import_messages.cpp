// What the window's side of mesh import says goes through Qt's translation system, whole
// (issue 31): with a translator that marks every text (marking_translator.h), each message
// comes back as one marked sentence in its context, the path and the helper's own words put
// in as they are. Bad inputs tried: an empty file, a folder, a helper that cannot start, one
// that writes something that is no mesh stream, one that dies of SIGSEGV and one that exits
// 3 after a line on its error output; a stream that is not one.

#include "import_process.h"
#include "marking_translator.h"
#include "wire_reader.h"

#include <QFile>
#include <QTemporaryDir>
#include <QTest>

using namespace lb;

namespace {

// A stand-in for lightbench-import: a shell script with `body`.
QString fakeHelper(const QTemporaryDir &dir, const QString &name, const QByteArray &body)
{
    QFile script(dir.filePath(name));
    if (!script.open(QIODevice::WriteOnly) || script.write("#!/bin/sh\n" + body) < 0)
        return {};
    script.close();
    script.setPermissions(QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner);
    return script.fileName();
}

} // namespace

class TestImportMessages : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        QFile mesh(m_dir.filePath("tri.obj"));
        QVERIFY(mesh.open(QIODevice::WriteOnly));
        mesh.write("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
        m_mesh = mesh.fileName();
    }

    void cleanup() { qunsetenv("LIGHTBENCH_IMPORT_HELPER"); }

    void filesRefusedBeforeTheHelperAreTranslated()
    {
        const MarkedMessages marks;
        QFile empty(m_dir.filePath("empty.obj"));
        QVERIFY(empty.open(QIODevice::WriteOnly));
        empty.close();
        QCOMPARE(ImportProcess::import(empty.fileName()).error,
                 marked("lb::ImportProcess", "%1: the file is empty").arg(empty.fileName()));
        QCOMPARE(ImportProcess::import(m_dir.path()).error,
                 marked("lb::BoundedRead", "%1: not a regular file (a folder, a device or a pipe)")
                     .arg(m_dir.path()));
    }

    void helperFailuresAreTranslated_data()
    {
        QTest::addColumn<QByteArray>("script"); // empty: no helper at all
        QTest::addColumn<QString>("expected");  // after "PATH: "
        QTest::newRow("no helper") << QByteArray() << QString();
        QTest::newRow("not a stream")
            << QByteArray("printf 'this is no mesh stream, only words from a helper gone wrong'\n"
                          "sleep 5\n")
            << marked("lb::WireReader", "the import helper wrote something that is not a mesh "
                                        "stream");
        QTest::newRow("SIGSEGV") << QByteArray("kill -SEGV $$\n")
                                 << marked("lb::ImportProcess",
                                           "the importer crashed with a segmentation fault while "
                                           "reading this file; the workbench is fine");
        QTest::newRow("exit 3") << QByteArray("echo 'the helper says why' >&2\nexit 3\n")
                                << marked("lb::ImportProcess",
                                          "the import helper stopped (exit code %1) before "
                                          "sending the whole mesh: %2")
                                       .arg("3", "the helper says why");
    }

    void helperFailuresAreTranslated()
    {
        QFETCH(QByteArray, script);
        QFETCH(QString, expected);
        const QString helper = script.isEmpty()
                                   ? m_dir.filePath("no-such-helper")
                                   : fakeHelper(m_dir, QTest::currentDataTag(), script);
        QVERIFY(!helper.isEmpty());
        qputenv("LIGHTBENCH_IMPORT_HELPER", QFile::encodeName(helper));
        const MarkedMessages marks;
        const ImportResult result = ImportProcess::import(m_mesh);
        QVERIFY(!result.ok());
        if (script.isEmpty()) { // Qt's own reason after the marked sentence
            QVERIFY2(result.error.startsWith(
                         marked("lb::ImportProcess", "%1: cannot start the import helper '%2': ")
                             .arg(m_mesh, helper)
                             .chopped(1)),
                     qPrintable(result.error));
            return;
        }
        QCOMPARE(result.error, m_mesh + ": " + expected);
    }

    void streamErrorsAreTranslated()
    {
        const MarkedMessages marks;
        WireReader reader;
        const QByteArray junk(64, 'x');
        QVERIFY(!reader.feed(junk.constData(), junk.size()));
        QCOMPARE(reader.error(), marked("lb::WireReader", "the import helper wrote something that "
                                                          "is not a mesh stream"));
    }

private:
    QTemporaryDir m_dir;
    QString m_mesh;
};

QTEST_MAIN(TestImportMessages)
#include "test_import_messages.moc"
