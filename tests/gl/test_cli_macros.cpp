// Issue 29 through the lightbench executable, under a memory cap: the 946-byte macro bomb
// (40 doublings: it grew Mesa's preprocessor to 24 GB), a `for (;;)` behind a macro, a
// 2-billion-step loop behind a function-like macro and a vertex loop that only wrapping around
// ends are refused by --check, --render, --probe and --grade, exit 1, with the file, line and
// macro; the bomb never reaches the driver (the cap would end the process first). Bad inputs
// tried: those four; a plain program under the same cap is the control.
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

#include <sys/resource.h>

namespace {

#ifndef LIGHTBENCH_SANITIZE
// Far above what lightbench needs (llvmpipe included), far below the 24 GB the bomb took.
constexpr rlim_t kAddressSpaceCap = rlim_t(3) << 30;
#endif

struct Run
{
    int exitCode;
    QByteArray out, err;
    qint64 ms;
};

Run runCapped(const QStringList &args)
{
    QElapsedTimer clock;
    clock.start();
    QProcess p;
#ifndef LIGHTBENCH_SANITIZE
    // (AddressSanitizer reserves terabytes of address space at start: the sanitizer build
    // runs uncapped, its driver's memory bounded by the program guard's 2 GB alone.)
    p.setChildProcessModifier([] {
        const rlimit cap{kAddressSpaceCap, kAddressSpaceCap};
        setrlimit(RLIMIT_AS, &cap);
    });
#endif
    p.start(LIGHTBENCH_EXE, args);
    if (!p.waitForFinished(60000)) {
        p.kill();
        p.waitForFinished();
        return {-1, {}, "timed out", clock.elapsed()};
    }
    return {p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -2, p.readAllStandardOutput(),
            p.readAllStandardError(), clock.elapsed()};
}

bool writeFile(const QString &path, const QByteArray &bytes)
{
    QFile f(path);
    return f.open(QIODevice::WriteOnly | QIODevice::Truncate) && f.write(bytes) == bytes.size();
}

const QByteArray kVertex = "attribute vec4 vPosition;\nvoid main() { gl_Position = vPosition; }\n";
const QByteArray kFragment =
    "precision mediump float;\nvoid main() { gl_FragColor = vec4(1.0); }\n";

// The shader: the use on line 42.
QByteArray bomb()
{
    QByteArray s = "precision mediump float;\n#define M0 1.0\n";
    for (int i = 1; i < 40; ++i)
        s += QString("#define M%1 (M%2+M%2)\n").arg(i).arg(i - 1).toUtf8();
    return s + "void main() { gl_FragColor = vec4(M39); }\n";
}

} // namespace

class TestCliMacros : public QObject
{
    Q_OBJECT
private:
    QTemporaryDir m_dir;

private slots:
    void refusedWithTheLineAndTheMacro_data()
    {
        QTest::addColumn<QString>("mode");
        QTest::addColumn<QByteArray>("vertex");
        QTest::addColumn<QByteArray>("fragment");
        QTest::addColumn<QString>("said"); // after "<file>:"; empty: accepted
        const QByteArray endless =
            "precision mediump float;\n#define FOREVER for(;;)\nvoid main() {\n  float x = 0.0;\n"
            "  FOREVER { x += 0.5; }\n  gl_FragColor = vec4(x);\n}\n";
        const QByteArray repeat =
            "precision mediump float;\n#define REPEAT(n) for (int i = 0; i < n; i++)\n"
            "void main() {\n  float x = 0.0;\n  REPEAT(2000000000) { x += 1e-9; }\n"
            "  gl_FragColor = vec4(x);\n}\n";
        const QByteArray wraps = "attribute vec4 vPosition;\nvoid main() {\n  float s = 1.0;\n"
                                 "  for (int i = 0; i >= 0; i++) { s *= 1.0; }\n"
                                 "  gl_Position = vPosition * s;\n}\n";
        const QString bombSaid = "42:35: error: macro M39 expands to more than ";
        for (const QString mode : {"--check", "--render", "--probe"})
            QTest::newRow(qPrintable(mode + " the 40-doubling bomb"))
                << mode << kVertex << bomb() << bombSaid;
        QTest::newRow("--check FOREVER")
            << "--check" << kVertex << endless
            << "5:3: error: this program never finishes a frame: the loop here has no condition "
               "(or an always-true one) and no break, return or discard (the loop comes from "
               "macro FOREVER, used on this line)";
        QTest::newRow("--check REPEAT(2000000000)")
            << "--check" << kVertex << repeat
            << "5:3: error: this program never finishes a frame: the loop here runs "
               "2,000,000,000 times for every fragment";
        QTest::newRow("--check a vertex loop that wraps around")
            << "--check" << wraps << kFragment
            << "4:3: error: this program never finishes a frame: the loop here runs "
               "2,147,483,648 times for every vertex";
        QTest::newRow("--check the control: a plain program")
            << "--check" << kVertex << kFragment << "";
    }

    void refusedWithTheLineAndTheMacro()
    {
        QFETCH(QString, mode);
        QFETCH(QByteArray, vertex);
        QFETCH(QByteArray, fragment);
        QFETCH(QString, said);
        const QString vert = m_dir.filePath("m.vert"), frag = m_dir.filePath("m.frag");
        const QString png = m_dir.filePath("m.png");
        QFile::remove(png);
        QVERIFY(writeFile(vert, vertex) && writeFile(frag, fragment));
        QStringList args{mode};
        if (mode == "--render")
            args << png;
        else if (mode == "--probe")
            args << "10,10";
        const Run r = runCapped(args + QStringList{"--vertex", vert, "--fragment", frag});
        const QByteArray out = mode == "--check" ? r.out : r.err;
        QVERIFY2(r.ms < 10000, qPrintable(QString("%1 ms").arg(r.ms)));
        if (said.isEmpty()) {
            QVERIFY2(r.exitCode == 0, r.out + r.err);
            return;
        }
        QCOMPARE(r.exitCode, 1);
        const QString file = vertex == kVertex ? frag : vert;
        QVERIFY2(out.contains((file + ":" + said).toUtf8()), (out + r.err).constData());
        QVERIFY(!QFile::exists(png));
    }

    // The bomb as a student's submission: --grade reports it (among what does not compile),
    // with its line and macro (the teacher's batch does not grow to 24 GB).
    void gradeRefusesTheBomb()
    {
        const QString dir = m_dir.filePath("class");
        QVERIFY(QDir().mkpath(dir));
        QFile::remove(dir + "/bomb.vert");
        QVERIFY(QFile::copy(LB_TEST_DATA "/grading/loop.vert", dir + "/bomb.vert"));
        QVERIFY(writeFile(dir + "/bomb.frag", bomb()));
        const Run r = runCapped({"--grade", dir + "/bomb.vert", "--exercise",
                                 LB_EXAMPLES_DIR "/exercise_lighting.json"});
        QVERIFY2(r.ms < 60000, qPrintable(QString("%1 ms").arg(r.ms)));
        QVERIFY2(
            r.out.contains("bomb: does not compile: bomb.frag:42: macro M39 expands to more than"),
            (r.out + r.err).constData());
    }
};

QTEST_GUILESS_MAIN(TestCliMacros)
#include "test_cli_macros.moc"
