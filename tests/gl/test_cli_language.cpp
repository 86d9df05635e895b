// Data is never translated (issue 31): the command line's probe JSON, --check's diagnostics,
// a --grade batch's lines and CSV are the same bytes under LANG=C.UTF-8, de_DE.UTF-8 and
// pt_PT.UTF-8, even with the window's language set to German in the settings (the command
// line loads no translator). Scripts that parse them keep working in every classroom.
#include <QDir>
#include <QFile>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

namespace {

const QString kGrading = QStringLiteral(LB_TEST_DATA "/grading");
const QString kExercise = QStringLiteral(LB_EXAMPLES_DIR "/exercise_lighting.json");

struct Output
{
    int exitCode = -1;
    QByteArray out, err, report;
};

} // namespace

class TestCliLanguage : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;

    // `args` under LANG=`lang` (LC_ALL, LC_MESSAGES and LANGUAGE taken away, so LANG decides),
    // with settings whose window language is German. "REPORT" in args is a CSV path to read.
    Output run(QStringList args, const QString &lang)
    {
        const QString report = m_dir.filePath(QString("report-%1.csv").arg(lang));
        QFile::remove(report);
        args.replaceInStrings("REPORT", report);
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        for (const char *name : {"LC_ALL", "LC_MESSAGES", "LC_NUMERIC", "LANGUAGE"})
            env.remove(name);
        env.insert("LANG", lang);
        env.insert("XDG_CONFIG_HOME", m_dir.filePath("config"));
        QProcess p;
        p.setProcessEnvironment(env);
        p.start(LIGHTBENCH_EXE, args);
        Output o;
        if (!p.waitForFinished(300000)) {
            p.kill();
            p.waitForFinished();
            return o;
        }
        o.exitCode = p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -2;
        o.out = p.readAllStandardOutput();
        o.err = p.readAllStandardError();
        QFile f(report);
        if (f.open(QIODevice::ReadOnly))
            o.report = f.readAll();
        return o;
    }

private slots:
    void initTestCase()
    {
        QVERIFY(QDir().mkpath(m_dir.filePath("config/lightbench")));
        QFile settings(m_dir.filePath("config/lightbench/lightbench.conf"));
        QVERIFY(settings.open(QIODevice::WriteOnly));
        settings.write("[interface]\nlanguage=de\n");
    }

    void machineOutputIsTheSameInEveryLanguage_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::newRow("--probe") << QStringList{"--probe", "400,300", "--shading", "gouraud"};
        // A shader that does not compile: the diagnostics name the line, in English.
        QTest::newRow("--check") << QStringList{"--check", "--vertex", kGrading + "/syntax.vert",
                                                "--fragment", kGrading + "/syntax.frag"};
        QTest::newRow("--grade") << QStringList{"--grade",
                                                kGrading + "/correct",
                                                kGrading + "/reflect_sign.vert",
                                                kGrading + "/syntax",
                                                "--exercise",
                                                kExercise,
                                                "--seed",
                                                "7",
                                                "--report",
                                                "REPORT"};
    }
    void machineOutputIsTheSameInEveryLanguage()
    {
        QFETCH(QStringList, args);
        const Output c = run(args, "C.UTF-8");
        QVERIFY2(c.exitCode == 0 || c.exitCode == 1, c.err.constData());
        QVERIFY(!c.out.isEmpty());
        for (const QString lang : {"de_DE.UTF-8", "pt_PT.UTF-8"}) {
            const Output o = run(args, lang);
            QCOMPARE(o.exitCode, c.exitCode);
            QCOMPARE(o.out, c.out);
            QCOMPARE(o.report, c.report);
        }
        if (QTest::currentDataTag() == QByteArray("--grade")) {
            QVERIFY(c.report.startsWith("submission,status"));
            QVERIFY2(c.out.contains("does not compile"), c.out.constData());
        }
    }
};

QTEST_GUILESS_MAIN(TestCliLanguage)
#include "test_cli_language.moc"
