// Where the workbench finds its helpers (render/install/helper_program.h), on made-up trees:
// the build tree's layout (beside the executable), an installed prefix's (libexec), the
// environment's override and the PATH. Bad inputs tried: a helper that is not executable, a
// folder named like the helper, an empty environment variable, nothing anywhere.
// tests/install/ runs a real installed tree.
#include "helper_program.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

using namespace lb;

namespace {

const char *const kVariable = "LB_TEST_HELPER_PROGRAM";
const QString kName = QStringLiteral("lightbench-import");

// A file at `path` (its folders made), executable when asked.
void makeFile(const QString &path, bool executable)
{
    QVERIFY(QDir().mkpath(QFileInfo(path).absolutePath()));
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write("#!/bin/sh\n");
    f.close();
    QFileDevice::Permissions permissions = QFileDevice::ReadOwner | QFileDevice::WriteOwner;
    if (executable)
        permissions |= QFileDevice::ExeOwner;
    QVERIFY(f.setPermissions(permissions));
}

// One environment variable set (or unset) for a scope, restored after.
class ScopedVariable
{
public:
    ScopedVariable(const char *name, const QByteArray &value)
        : m_name(name), m_had(qEnvironmentVariableIsSet(name)), m_saved(qgetenv(name))
    {
        if (value.isNull())
            qunsetenv(name);
        else
            qputenv(name, value);
    }
    ~ScopedVariable()
    {
        if (m_had)
            qputenv(m_name, m_saved);
        else
            qunsetenv(m_name);
    }

private:
    const char *m_name;
    bool m_had;
    QByteArray m_saved;
};

} // namespace

class TestHelperProgram : public QObject
{
    Q_OBJECT

private slots:
    void init()
    {
        QVERIFY(m_dir.isValid());
        m_bin = m_dir.filePath("prefix/bin");
        m_installed = QDir::cleanPath(m_bin + '/' + installedHelperDir() + '/' + kName);
        QVERIFY(QDir().mkpath(m_bin));
        // An empty PATH folder: only what a test puts there is on the PATH.
        m_path = m_dir.filePath("path");
        QVERIFY(QDir().mkpath(m_path));
    }
    void cleanup()
    {
        QVERIFY(QDir(m_dir.path()).removeRecursively() && QDir().mkpath(m_dir.path()));
    }

    // Only a relative folder is compiled in, never the prefix: the tree works wherever it
    // is unpacked. It leads out of bin/ into the libexec folder's lightbench/.
    void installedDirIsRelative()
    {
        QVERIFY2(QDir::isRelativePath(installedHelperDir()), qPrintable(installedHelperDir()));
        QVERIFY(installedHelperDir().startsWith(QLatin1String("../")));
        QVERIFY(installedHelperDir().endsWith(QLatin1String("/lightbench")));
    }

    void installedTreeFindsLibexec()
    {
        const ScopedVariable unset(kVariable, QByteArray());
        const ScopedVariable path("PATH", m_path.toLocal8Bit());
        makeFile(m_installed, true);
        // One on the PATH too (another version, say): the tree's own comes first.
        makeFile(m_path + '/' + kName, true);
        QCOMPARE(helperProgramPath(kName, kVariable, m_bin), m_installed);
        // The same tree moved elsewhere finds its own helper there.
        const QString moved = m_dir.filePath("elsewhere");
        QVERIFY(QDir().rename(m_dir.filePath("prefix"), moved));
        QCOMPARE(helperProgramPath(kName, kVariable, moved + "/bin"),
                 QDir::cleanPath(moved + "/bin/" + installedHelperDir() + '/' + kName));
    }

    // The build tree keeps the helpers beside the executable; that wins over an installed
    // copy, so a build next to an old install runs its own helpers.
    void besideWinsOverInstalled()
    {
        const ScopedVariable unset(kVariable, QByteArray());
        makeFile(m_installed, true);
        makeFile(m_bin + '/' + kName, true);
        QCOMPARE(helperProgramPath(kName, kVariable, m_bin), m_bin + '/' + kName);
    }

    void environmentWins()
    {
        makeFile(m_bin + '/' + kName, true);
        const ScopedVariable set(kVariable, "/somewhere/else/lightbench-import");
        QCOMPARE(helperProgramPath(kName, kVariable, m_bin),
                 QStringLiteral("/somewhere/else/lightbench-import"));
        // Set but empty: as if unset.
        const ScopedVariable empty(kVariable, QByteArray(""));
        QCOMPARE(helperProgramPath(kName, kVariable, m_bin), m_bin + '/' + kName);
    }

    // Not executable beside, a folder in libexec: neither is started; the PATH's is.
    void skipsWhatCannotRun()
    {
        const ScopedVariable unset(kVariable, QByteArray());
        makeFile(m_bin + '/' + kName, false);
        QVERIFY(QDir().mkpath(m_installed));
        makeFile(m_path + '/' + kName, true);
        const ScopedVariable path("PATH", m_path.toLocal8Bit());
        QCOMPARE(helperProgramPath(kName, kVariable, m_bin), m_path + '/' + kName);
    }

    // Nowhere: the installed place, so that "cannot start" says where it should have been.
    void nowhereNamesTheInstalledPlace()
    {
        const ScopedVariable unset(kVariable, QByteArray());
        const ScopedVariable path("PATH", m_path.toLocal8Bit());
        makeFile(m_installed, false);
        QCOMPARE(helperProgramPath(kName, kVariable, m_bin), m_installed);
    }

private:
    QTemporaryDir m_dir;
    QString m_bin, m_installed, m_path;
};

QTEST_GUILESS_MAIN(TestHelperProgram)
#include "test_helper_program.moc"
