// Grading a class (--grade) as a teacher runs it: the sample submissions in tests/data/grading
// against the example exercise (the sheet's per-fragment lighting task): the correct one
// passes every case, each wrong one fails the cases that expose its mistake, the one that does
// not compile names its line, the endless loop is refused without stalling the batch; the
// CSV and the sheets; the same seed gives the same report; bad input exits 2 naming it; a
// faulty exercise stops the batch; children that crash, chatter, cannot start or run past the
// time limit (a stand-in program and a tiny limit play them) are reported and the batch goes on.
#include "csv_rows.h"
#include "file_status.h"

#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QImage>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

#include <algorithm>
#include <memory>

#include <csignal>
#include <sys/stat.h>
#include <unistd.h>

namespace {

const QString kData = QStringLiteral(LB_TEST_DATA "/grading");
const QString kExercise = QStringLiteral(LB_EXAMPLES_DIR "/exercise_lighting.json");

struct Run
{
    int exitCode;
    QByteArray out, err;
    qint64 ms;
};

Run run(const QStringList &args,
        const QProcessEnvironment &env = QProcessEnvironment::systemEnvironment())
{
    QElapsedTimer clock;
    clock.start();
    QProcess p;
    p.setProcessEnvironment(env);
    p.start(LIGHTBENCH_EXE, args);
    if (!p.waitForFinished(300000))
        return {-1, {}, "timed out", clock.elapsed()};
    return {p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -2, p.readAllStandardOutput(),
            p.readAllStandardError(), clock.elapsed()};
}

// One submission's JSON, as the batch's child prints it.
QJsonObject gradeOne(const QString &submission, const QString &exercise = kExercise)
{
    const Run r = run({"--grade-one", submission, "--exercise", exercise});
    return QJsonDocument::fromJson(r.out.trimmed()).object();
}

bool write(const QString &path, const QByteArray &bytes)
{
    QFile f(path);
    return f.open(QIODevice::WriteOnly) && f.write(bytes) == bytes.size();
}

// A stand-in for the batch's child: submissions named slow* never end (the child writes its
// pid to `pidFile` first), any other prints a passing result at once; each start leaves a
// line in `starts`.
QString writeStandIn(const QString &path, const QString &pidFile, const QString &starts)
{
    const QByteArray script = QString("#!/bin/sh\n"
                                      "echo \"$4\" >> '%2'\n"
                                      "case \"$4\" in slow*) echo $$ > '%1'; exec sleep 60;; esac\n"
                                      "echo '{\"status\":\"graded\",\"submission\":\"x\",\"cases\":"
                                      "[{\"passed\":true,\"largest\":1,\"shareWithin\":1}]}'\n")
                                  .arg(pidFile, starts)
                                  .toUtf8();
    if (!write(path, script) ||
        !QFile::setPermissions(path, QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner))
        return {};
    return path;
}

// A submission folder NAME holding the correct pair.
QString correctCopy(const QDir &dir, const QString &name)
{
    if (!dir.mkpath(name))
        return {};
    for (const char *suffix : {".vert", ".frag"})
        if (!QFile::copy(kData + "/correct/lighting" + suffix,
                         dir.filePath(name + "/lighting" + suffix)))
            return {};
    return dir.filePath(name);
}

} // namespace

class TestGrading : public QObject
{
    Q_OBJECT
private:
    QTemporaryDir m_dir;

private slots:
    void theSampleClass()
    {
        const QString report = m_dir.filePath("grades.csv");
        const QString sheets = m_dir.filePath("sheets");
        const Run r = run({"--grade", kData + "/correct", kData + "/reflect_sign.vert",
                           kData + "/normal_matrix.frag", kData + "/syntax", kData + "/loop.vert",
                           "--exercise", kExercise, "--report", report, "--sheets", sheets});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        qInfo("five submissions in %lld ms", r.ms);
        const QList<QByteArray> lines = r.out.trimmed().split('\n');
        QCOMPARE(lines.size(), 5);
        QVERIFY2(lines[0].startsWith("correct: passed, 20/20 cases passed"), lines[0].constData());
        QVERIFY2(lines[1].startsWith("reflect_sign: failed, "), lines[1].constData());
        QVERIFY2(lines[2].startsWith("normal_matrix: failed, "), lines[2].constData());
        QVERIFY2(lines[3].startsWith("syntax: does not compile: syntax.frag:26:"),
                 lines[3].constData());
        QVERIFY2(lines[4].startsWith("loop: refused: loop.frag:"), lines[4].constData());

        const QList<QStringList> rows = csvRows(report);
        QCOMPARE(rows.size(), 6);
        QCOMPARE(rows[0], QString("submission,status,cases_passed,cases,worst_difference,"
                                  "mean_share_within,first_diagnostic,points,max_points,hint,"
                                  "seed,lightbench")
                              .split(','));
        QCOMPARE(rows[1].mid(0, 4), QStringList({"correct", "graded", "20", "20"}));
        QVERIFY(rows[1][4].toInt() <= 2);
        QCOMPARE(rows[2][1], QString("graded"));
        QVERIFY(rows[2][2].toInt() < 20);
        QCOMPARE(rows[4][1], QString("does not compile"));
        QVERIFY(rows[4][6].startsWith("syntax.frag:26: syntax error"));
        QCOMPARE(rows[4][2], QString()); // not graded: no numbers
        QCOMPARE(rows[5][1], QString("refused"));
        QVERIFY(rows[5][6].startsWith("loop.frag:24:"));

        // One sheet per graded submission: student | reference | heat map, with a title.
        for (const char *name : {"correct", "reflect_sign", "normal_matrix"}) {
            const QImage sheet(QDir(sheets).filePath(QString(name) + ".png"));
            QVERIFY2(!sheet.isNull(), name);
            QVERIFY(sheet.width() > 3 * 320 && sheet.height() > 240);
        }
        QVERIFY(!QFileInfo::exists(QDir(sheets).filePath("syntax.png")));
    }

    // Each wrong answer fails the cases that expose it and passes those that cannot.
    void eachMistakeFailsItsCases()
    {
        const QJsonObject correct = gradeOne(kData + "/correct");
        QCOMPARE(correct["status"].toString(), QString("graded"));
        for (const QJsonValue &c : correct["cases"].toArray())
            QVERIFY2(c["passed"].toBool(), qPrintable(QJsonDocument(c.toObject()).toJson()));

        // The normal matrix is only wrong under a non-uniform scale: case 0 (the exercise as
        // it is, unscaled) passes, the scaled ones fail.
        const QJsonArray normals = gradeOne(kData + "/normal_matrix.vert")["cases"].toArray();
        QCOMPARE(normals.size(), 20);
        QVERIFY(normals[0]["passed"].toBool());
        int failed = 0;
        for (const QJsonValue &c : normals)
            failed += !c["passed"].toBool();
        QVERIFY2(failed >= 10, qPrintable(QString::number(failed)));

        // The reflection's sign changes every highlight: most cases fail, with big differences.
        const QJsonArray reflect = gradeOne(kData + "/reflect_sign.frag")["cases"].toArray();
        int reflectFailed = 0, largest = 0;
        for (const QJsonValue &c : reflect) {
            reflectFailed += !c["passed"].toBool();
            largest = std::max(largest, c["largest"].toInt());
        }
        QVERIFY2(reflectFailed >= 10, qPrintable(QString::number(reflectFailed)));
        QVERIFY(largest > 50);
    }

    // Issue 36: the batch draws the reference's and the mistakes' frames once (--grade-prepare)
    // and each child reads them (--grade-frames): the child's report is the same bytes as
    // when it draws its own. Frames made for another seed, a frame cut short, or no key are
    // not read (the child draws its own); frames with the right key are (painted black, they
    // change the report: this test would see a child that ignored them).
    void theBatchsFramesGradeAsTheChildAlone()
    {
        const QString frames = m_dir.filePath("frames");
        QVERIFY(QDir().mkpath(frames));
        const Run prepared =
            run({"--grade-prepare", frames, "--exercise", kExercise, "--seed", "3"});
        QVERIFY2(prepared.exitCode == 0, prepared.err.constData());
        QCOMPARE(prepared.out.trimmed(), QByteArray(R"({"status":"prepared"})"));
        // Every case's reference frame and every mistake's (7 in the example), and the key.
        QCOMPARE(QDir(frames).entryList(QDir::Files).size(), 20 + 7 * 20 + 1);

        const auto child = [&](const QString &submission, const char *seed,
                               const QString &framesDir) {
            QStringList args{"--grade-one", submission, "--exercise", kExercise, "--seed", seed};
            if (!framesDir.isEmpty())
                args << "--grade-frames" << framesDir;
            const Run r = run(args);
            return r.exitCode == 0 ? r.out : QByteArray("exit ") + QByteArray::number(r.exitCode);
        };
        for (const QString &submission :
             {kData + "/correct", kData + "/reflect_sign.vert", kData + "/normal_matrix.vert"}) {
            const QByteArray alone = child(submission, "3", {});
            QVERIFY2(alone.contains(R"("status":"graded")"), alone.constData());
            QCOMPARE(child(submission, "3", frames), alone);
            // Drawn for seed 3: a child of seed 4 draws its own.
            QCOMPARE(child(submission, "4", frames), child(submission, "4", {}));
        }

        // The mistakes' frames painted black with the key kept: read, and the reflection's
        // mistake is no longer found.
        const QByteArray reflect = child(kData + "/reflect_sign.vert", "3", {});
        QVERIFY2(reflect.contains(R"("mistake")"), reflect.constData());
        const auto paintBlack = [&](const QString &pattern) {
            for (const QString &name : QDir(frames).entryList({pattern}, QDir::Files)) {
                QFile f(QDir(frames).filePath(name));
                if (!f.open(QIODevice::ReadWrite) ||
                    f.write(QByteArray(int(f.size()), '\0')) != f.size())
                    return false;
            }
            return true;
        };
        QVERIFY(paintBlack("mistake-*"));
        const QByteArray blackMistakes = child(kData + "/reflect_sign.vert", "3", frames);
        QVERIFY2(!blackMistakes.contains(R"("mistake")"), blackMistakes.constData());

        // The reference's painted black: read, and the correct program no longer passes.
        QVERIFY(paintBlack("reference-*"));
        const QByteArray black = child(kData + "/correct", "3", frames);
        QVERIFY2(!black.contains(R"("passed":true)"), black.constData());
        // One frame cut short, or no key: not read.
        QVERIFY(QFile::resize(QDir(frames).filePath("reference-5.rgb32"), 100));
        const QByteArray alone = child(kData + "/correct", "3", {});
        QCOMPARE(child(kData + "/correct", "3", frames), alone);
        QVERIFY(QFile::remove(QDir(frames).filePath("key")));
        QVERIFY(QFile::resize(QDir(frames).filePath("reference-5.rgb32"), 320 * 240 * 4));
        QCOMPARE(child(kData + "/correct", "3", frames), alone);
    }

    // The batch hands its children the frames it drew when there are more submissions to grade
    // than processes at once (a stand-in child writes down its arguments); with no more, each
    // draws its own.
    void childrenGetTheBatchsFrames()
    {
        QTemporaryDir tmp;
        const QDir dir(tmp.path());
        // The stand-in writes down its arguments, and whether the folder it was given (the
        // last argument) holds the key when it runs.
        const QString arguments = dir.filePath("arguments"), child = dir.filePath("child.sh");
        QVERIFY(write(child, QString("#!/bin/sh\necho \"$*\" >> '%1'\n"
                                     "for last; do :; done\n"
                                     "[ -f \"$last/key\" ] && echo 'the key is there' >> '%1'\n"
                                     "echo '{\"status\":\"graded\",\"submission\":\"x\",\"cases\":"
                                     "[{\"passed\":true,\"largest\":1,\"shareWithin\":1}]}'\n")
                                 .arg(arguments)
                                 .toUtf8()));
        QVERIFY(QFile::setPermissions(child, QFile::ReadOwner | QFile::ExeOwner));
        const QString temporary = dir.filePath("tmp"); // where the batch's folder goes
        QVERIFY(dir.mkpath("tmp"));
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert("LIGHTBENCH_GRADE_PROGRAM", child);
        env.insert("LIGHTBENCH_GRADE_PROCESSES", "1"); // two submissions are more than run at once
        env.insert("TMPDIR", temporary);
        const auto childArguments = [&](const QStringList &submissions) {
            QFile::remove(arguments);
            const Run r = run(
                QStringList{"--grade"} + submissions + QStringList{"--exercise", kExercise}, env);
            QFile f(arguments);
            return r.exitCode == 0 && f.open(QIODevice::ReadOnly)
                       ? QString::fromUtf8(f.readAll()).trimmed().split('\n')
                       : QStringList{QString("exit %1").arg(r.exitCode)};
        };
        const QStringList two = childArguments({correctCopy(dir, "amy"), correctCopy(dir, "ben")});
        QCOMPARE(two.size(), 4);
        for (int i : {0, 2}) {
            QVERIFY2(two[i].contains("--grade-frames " + temporary), qPrintable(two[i]));
            QCOMPARE(two[i + 1], QString("the key is there"));
        }
        // The folder ("lightbench-frames-XXXXXX") goes with the batch. (Qt may put its runtime
        // folder there too, without XDG_RUNTIME_DIR.)
        QCOMPARE(
            QDir(temporary).entryList({"lightbench-*"}, QDir::NoDotAndDotDot | QDir::AllEntries),
            QStringList());
        const QStringList one = childArguments({correctCopy(dir, "cat")});
        QCOMPARE(one.size(), 1);
        QVERIFY2(!one[0].contains("--grade-frames"), qPrintable(one[0]));
    }

    // A batch killed with SIGKILL cannot remove its frames' folder; the next batch does, and
    // leaves a live batch's alone.
    void aKilledBatchsFramesAreRemovedByTheNext()
    {
        if (!lb::platform::canTellOwners())
            QSKIP("this platform layer cannot tell a folder's owner: it removes no frames folder");
        QTemporaryDir tmp;
        const QDir dir(tmp.path());
        // A stand-in child that waits as long as its batch lives, and one that passes at once.
        const QString waiting = dir.filePath("waiting.sh"), passing = dir.filePath("passing.sh");
        QVERIFY(write(waiting, "#!/bin/sh\nwhile kill -0 $PPID 2>/dev/null; do sleep 0.1; done\n"));
        QVERIFY(write(passing,
                      "#!/bin/sh\necho '{\"status\":\"graded\",\"submission\":\"x\","
                      "\"cases\":[{\"passed\":true,\"largest\":1,\"shareWithin\":1}]}'\n"));
        for (const QString &f : {waiting, passing})
            QVERIFY(QFile::setPermissions(f, QFile::ReadOwner | QFile::ExeOwner));
        const QString temporary = dir.filePath("tmp");
        QVERIFY(dir.mkpath("tmp"));
        const auto environment = [&](const QString &child) {
            QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
            env.insert("LIGHTBENCH_GRADE_PROGRAM", child);
            env.insert("LIGHTBENCH_GRADE_PROCESSES", "1");
            env.insert("TMPDIR", temporary);
            return env;
        };
        const QStringList batch{"--grade", correctCopy(dir, "amy"), correctCopy(dir, "ben"),
                                "--exercise", kExercise};
        const auto folders = [&] {
            return QDir(temporary).entryList({"lightbench-frames-*"},
                                             QDir::Dirs | QDir::NoDotAndDotDot);
        };
        // Two batches whose children wait: their frames are drawn, then one is killed.
        std::vector<std::unique_ptr<QProcess>> batches;
        for (int i = 0; i < 2; ++i) {
            batches.push_back(std::make_unique<QProcess>());
            batches.back()->setProcessEnvironment(environment(waiting));
            batches.back()->start(LIGHTBENCH_EXE, batch);
            QTRY_COMPARE_WITH_TIMEOUT(folders().size(), i + 1, 60000);
        }
        const auto drawn = [&] { // every folder has its key: the frames are drawn
            const QStringList all = folders();
            return std::all_of(all.begin(), all.end(), [&](const QString &f) {
                return QFile::exists(QDir(temporary).filePath(f + "/key"));
            });
        };
        QTRY_VERIFY_WITH_TIMEOUT(folders().size() == 2 && drawn(), 120000);
        batches[0]->kill(); // SIGKILL: no clean-up
        QVERIFY(batches[0]->waitForFinished(10000));
        QCOMPARE(folders().size(), 2);
        // The next batch removes the killed one's folder (and its own), not the live one's.
        const Run next = run(batch, environment(passing));
        QVERIFY2(next.exitCode == 0, next.err.constData());
        QCOMPARE(folders().size(), 1);
        batches[1]->kill();
        QVERIFY(batches[1]->waitForFinished(10000));
        const Run last = run(batch, environment(passing));
        QVERIFY2(last.exitCode == 0, last.err.constData());
        QCOMPARE(folders(), QStringList());
    }

    void theSameSeedGivesTheSameReport()
    {
        QStringList reports;
        for (const char *seed : {"7", "7", "8"}) {
            const QString report = m_dir.filePath(QString("seed%1.csv").arg(reports.size()));
            const Run r = run({"--grade", kData + "/reflect_sign.vert", kData + "/normal_matrix",
                               "--exercise", kExercise, "--seed", seed, "--report", report});
            QVERIFY2(r.exitCode == 0, r.err.constData());
            QFile f(report);
            QVERIFY(f.open(QIODevice::ReadOnly));
            reports << QString::fromUtf8(f.readAll());
        }
        QCOMPARE(reports[0], reports[1]);
        QVERIFY(reports[0] != reports[2]); // other cases, other numbers
    }

    // Issue 28: the CSV report and the summary lines are the same bytes under German or
    // Portuguese as under C: a point in every number (Qt reads LANG itself).
    void theReportIsTheSameInEveryLocale()
    {
        QList<QByteArray> reports, outs;
        for (const char *locale : {"C", "de_DE.UTF-8", "pt_PT.UTF-8"}) {
            QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
            env.remove("LC_NUMERIC");
            env.insert("LC_ALL", locale);
            env.insert("LANG", locale);
            const QString report = m_dir.filePath(QString("locale%1.csv").arg(reports.size()));
            const Run r = run({"--grade", kData + "/reflect_sign.vert", "--exercise", kExercise,
                               "--seed", "7", "--report", report},
                              env);
            QVERIFY2(r.exitCode == 0, r.err.constData());
            QFile f(report);
            QVERIFY(f.open(QIODevice::ReadOnly));
            reports << f.readAll();
            outs << r.out;
        }
        QCOMPARE(reports[1], reports[0]);
        QCOMPARE(reports[2], reports[0]);
        QCOMPARE(outs[1], outs[0]);
        QCOMPARE(outs[2], outs[0]);
        const QList<QStringList> rows = csvRows(m_dir.filePath("locale1.csv"));
        QCOMPARE(rows.size(), 2);
        QVERIFY2(QRegularExpression("^\\d+\\.\\d{4}$").match(rows[1][5]).hasMatch(),
                 qPrintable(rows[1][5])); // mean_share_within
        QVERIFY2(QRegularExpression("\\d\\.\\d%").match(QString(outs[1])).hasMatch(),
                 outs[1].constData()); // "... 41.2% of pixels ..."
    }

    // A submission given as a scene file with a program is graded like a pair.
    void aSceneFileSubmission()
    {
        const QString scene = m_dir.filePath("carol.json");
        QFile vert(kData + "/correct/lighting.vert"), frag(kData + "/correct/lighting.frag");
        QVERIFY(vert.open(QIODevice::ReadOnly) && frag.open(QIODevice::ReadOnly));
        const QJsonObject json{{"format", "lightbench-scene"},
                               {"version", 3},
                               {"program", QJsonObject{{"name", "carol"},
                                                       {"vertex", QString(vert.readAll())},
                                                       {"fragment", QString(frag.readAll())}}}};
        QVERIFY(write(scene, QJsonDocument(json).toJson()));
        const QJsonObject o = gradeOne(scene);
        QCOMPARE(o["submission"].toString(), QString("carol"));
        QCOMPARE(o["status"].toString(), QString("graded"));
    }

    void badInputIsNamed_data()
    {
        QTest::addColumn<QString>("what");
        QTest::newRow("missing exercise") << "missing exercise";
        QTest::newRow("exercise without reference") << "no reference";
        QTest::newRow("not an exercise") << "not an exercise";
        QTest::newRow("empty submission folder") << "empty folder";
        QTest::newRow("unreadable submission") << "fifo";
        QTest::newRow("a FIFO lighting.frag in a folder") << "fifo in a folder";
    }

    void badInputIsNamed()
    {
        QFETCH(QString, what);
        QString exercise = kExercise;
        QStringList submissions{kData + "/correct"};
        QString named;
        if (what == "missing exercise") {
            exercise = m_dir.filePath("nowhere.json");
            named = "nowhere.json";
        } else if (what == "no reference") {
            exercise = m_dir.filePath("noref.json");
            QVERIFY(write(exercise, R"({"format": "lightbench-scene", "version": 3,
                                        "exercise": {"title": "Lighting"}})"));
            named = "no reference program";
        } else if (what == "not an exercise") {
            exercise = LB_EXAMPLES_DIR "/toon.json";
            named = "not an exercise";
        } else if (what == "empty folder") {
            QVERIFY(QDir(m_dir.path()).mkpath("dave"));
            submissions << m_dir.filePath("dave");
            named = "dave: a folder needs one NAME.vert and one NAME.frag";
        } else if (what == "fifo in a folder") { // it was "it has 1 and 0"
            QVERIFY(QDir(m_dir.path()).mkpath("fay"));
            QVERIFY(
                QFile::copy(kData + "/correct/lighting.vert", m_dir.filePath("fay/lighting.vert")));
            QCOMPARE(
                mkfifo(QFile::encodeName(m_dir.filePath("fay/lighting.frag")).constData(), 0600),
                0);
            submissions << m_dir.filePath("fay");
            named = "fay/lighting.frag: not a regular file";
        } else {
            QVERIFY(QFile::copy(kData + "/correct/lighting.vert", m_dir.filePath("erin.vert")));
            QCOMPARE(mkfifo(QFile::encodeName(m_dir.filePath("erin.frag")).constData(), 0600), 0);
            submissions << m_dir.filePath("erin.vert");
            named = "erin.frag: not a regular file";
        }
        const Run r =
            run(QStringList{"--grade"} + submissions + QStringList{"--exercise", exercise});
        QCOMPARE(r.exitCode, 2);
        const QStringList alternatives = named.split(" || "); // any one of them
        QVERIFY2(std::any_of(alternatives.begin(), alternatives.end(),
                             [&](const QString &a) { return r.err.contains(a.toUtf8()); }),
                 r.err.constData());
        QCOMPARE(r.err.count("lightbench: "), 1);
        // Where only a submission is bad, the others are still graded.
        if (submissions.size() > 1)
            QVERIFY2(r.out.startsWith("correct: passed, 20/20"), r.out.constData());
    }

    // The exercise's fault (a misspelt "vary", a reference that does not build) stops the
    // batch with one line, instead of grading everyone against it.
    void aFaultyExerciseStopsTheBatch_data()
    {
        QTest::addColumn<QString>("field");
        QTest::addColumn<QJsonValue>("value");
        QTest::addColumn<QString>("named");
        QTest::newRow("misspelt vary") << "vary" << QJsonValue(QJsonArray{"lights", "camra"})
                                       << "exercise.grading.vary (no such parameter 'lights'";
        QTest::newRow("reference that does not build")
            << "reference"
            << QJsonValue(QJsonObject{{"vertex", "void main() { gl_Position = vec4(0.0) }"},
                                      {"fragment", "void main() {}"}})
            << "reference does not build";
        // The teacher's program is tried as a student's is: one that never finishes a frame
        // (or is over the budget) is named on its line, instead of every submission taking
        // the time limit and being compared with the driver's cut-short frames.
        const QString vertex =
            "attribute vec4 vPosition;\nvoid main() { gl_Position = vPosition; }";
        QTest::newRow("reference that never finishes a frame")
            << "reference"
            << QJsonValue(QJsonObject{{"vertex", vertex},
                                      {"fragment",
                                       "precision mediump float;\nvoid main() {\n  float x = 0.0;\n"
                                       "  for (;;) { x += 1.0; }\n  gl_FragColor = vec4(x);\n}"}})
            << "reference refused: reference fragment:4: this program never finishes a frame";
        // A loop that ends, but 200,000 steps in every pixel: minutes a frame.
        QTest::newRow("reference over the budget")
            << "reference"
            << QJsonValue(QJsonObject{
                   {"vertex", "attribute vec4 vPosition;\nvarying vec3 v;\nvoid main() { v = "
                              "vPosition.xyz; gl_Position = vPosition; }"},
                   {"fragment", "precision mediump float;\nvarying vec3 v;\nvoid main() {\n"
                                "  vec3 c = v;\n  for (int i = 0; i < 200000; i++)\n"
                                "    c = sin(c + v);\n  gl_FragColor = vec4(c, 1.0);\n}"}})
            // On a loaded machine the trial's wall-clock bound can come first: refused too.
            << "reference refused: reference fragment:5: drawing one frame with this program at "
               "320x240 would take more than || reference refused: reference fragment:5: compiling "
               "this program "
               "and drawing it on small frames took more than";
    }

    void aFaultyExerciseStopsTheBatch()
    {
        QFETCH(QString, field);
        QFETCH(QJsonValue, value);
        QFETCH(QString, named);
        QFile f(kExercise);
        QVERIFY(f.open(QIODevice::ReadOnly));
        QJsonObject root = QJsonDocument::fromJson(f.readAll()).object();
        QJsonObject exercise = root["exercise"].toObject();
        if (field == "vary") {
            QJsonObject grading = exercise["grading"].toObject();
            grading["vary"] = value;
            exercise["grading"] = grading;
        } else {
            exercise[field] = value;
        }
        root["exercise"] = exercise;
        const QString path = m_dir.filePath(field + ".json");
        QVERIFY(write(path, QJsonDocument(root).toJson()));
        const Run r =
            run({"--grade", kData + "/correct", kData + "/reflect_sign", "--exercise", path});
        QCOMPARE(r.exitCode, 2);
        const QStringList alternatives = named.split(" || "); // any one of them
        QVERIFY2(std::any_of(alternatives.begin(), alternatives.end(),
                             [&](const QString &a) { return r.err.contains(a.toUtf8()); }),
                 r.err.constData());
        QCOMPARE(r.err.count("lightbench: "), 1);
        QVERIFY(r.out.isEmpty());
    }

    // Two submissions with one name (each student's folder holds lighting.vert) are told
    // apart in the report and the sheets; a trailing slash names the folder.
    void sameNamesAreToldApart()
    {
        for (const char *student : {"amy", "ben"}) {
            QVERIFY(QDir(m_dir.path()).mkpath(student));
            for (const char *suffix : {".vert", ".frag"})
                QVERIFY(QFile::copy(kData + "/correct/lighting" + suffix,
                                    m_dir.filePath(QString(student) + "/lighting" + suffix)));
        }
        const QString sheets = m_dir.filePath("named-sheets");
        const Run r = run({"--grade", m_dir.filePath("amy") + "/lighting.vert",
                           m_dir.filePath("ben") + "/lighting.vert", m_dir.filePath("amy") + "/",
                           "--exercise", kExercise, "--sheets", sheets});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        const QList<QByteArray> lines = r.out.trimmed().split('\n');
        QCOMPARE(lines.size(), 3);
        QVERIFY2(lines[0].startsWith("lighting: passed"), r.out.constData());
        QVERIFY2(lines[1].startsWith("lighting-2: passed"), r.out.constData());
        QVERIFY2(lines[2].startsWith("amy: passed"), r.out.constData());
        for (const char *sheet : {"lighting.png", "lighting-2.png", "amy.png"})
            QVERIFY2(QFileInfo::exists(QDir(sheets).filePath(sheet)), sheet);
    }

    // A child that crashes, one that prints more after its result, one that cannot start:
    // each is reported for what it is (a stand-in program plays the child).
    void childrenThatMisbehave_data()
    {
        QTest::addColumn<QByteArray>("script");
        QTest::addColumn<QString>("expected");
        QTest::newRow("crash") << QByteArray("#!/bin/sh\nkill -SEGV $$\n")
                               << "correct: crashed: killed by signal 11";
        QTest::newRow("chatter after the result")
            << QByteArray("#!/bin/sh\necho '{\"status\":\"graded\",\"submission\":\"x\","
                          "\"cases\":[{\"passed\":true,\"largest\":1,\"shareWithin\":1}]}'\n"
                          "echo 'driver: goodbye'\nkill -SEGV $$\n")
            << "correct: passed, 1/1 cases passed";
        QTest::newRow("not there") << QByteArray() << "correct: crashed: could not start";
    }

    void childrenThatMisbehave()
    {
        QFETCH(QByteArray, script);
        QFETCH(QString, expected);
        const QString program = m_dir.filePath(QString("child-%1.sh").arg(QTest::currentDataTag()));
        if (!script.isEmpty()) {
            QVERIFY(write(program, script));
            QVERIFY(QFile::setPermissions(program, QFile::ReadOwner | QFile::ExeOwner));
        }
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert("LIGHTBENCH_GRADE_PROGRAM", program);
        const Run r = run({"--grade", kData + "/correct", "--exercise", kExercise}, env);
        QCOMPARE(r.exitCode, 0);
        QVERIFY2(r.out.startsWith(expected.toUtf8()), r.out.constData());
    }

    // A submission past the time limit is killed and reported; the batch goes on. (The limit
    // is made tiny here; it is 30 s plus 4 s a case, and 2 s a known mistake and failing case.)
    void aSubmissionPastTheTimeLimitIsReported()
    {
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert("LIGHTBENCH_GRADE_TIME_LIMIT_MS", "50");
        const QString report = m_dir.filePath("late.csv");
        const Run r = run({"--grade", kData + "/correct", kData + "/syntax", "--exercise",
                           kExercise, "--report", report},
                          env);
        QCOMPARE(r.exitCode, 0);
        const QList<QStringList> rows = csvRows(report);
        QCOMPARE(rows.size(), 3);
        QCOMPARE(rows[1][1], QString("timed out"));
        QCOMPARE(rows[2][1], QString("timed out"));
        QVERIFY(r.out.contains("correct: timed out: more than 0.1 s"));
    }

    // A batch stopped after some submissions finished (Ctrl+C reaches the terminal's whole
    // process group, `kill` the batch alone, a closed terminal sends SIGHUP) printed their
    // lines, its CSV holds exactly their rows, no child is left running, and it exits as a
    // shell expects: 128 + the signal.
    void aStoppedBatchKeepsWhatItFinished_data()
    {
        QTest::addColumn<int>("signal");
        QTest::addColumn<bool>("wholeGroup");
        QTest::newRow("Ctrl+C (SIGINT to the group)") << SIGINT << true;
        QTest::newRow("kill (SIGTERM to the batch)") << int(SIGTERM) << false;
        QTest::newRow("closed terminal (SIGHUP)") << int(SIGHUP) << false;
    }

    void aStoppedBatchKeepsWhatItFinished()
    {
        QFETCH(int, signal);
        QFETCH(bool, wholeGroup);
        QTemporaryDir tmp;
        const QDir dir(tmp.path());
        const QString pidFile = dir.filePath("slow.pid"), starts = dir.filePath("starts");
        const QString child = writeStandIn(dir.filePath("child.sh"), pidFile, starts);
        QVERIFY(!child.isEmpty());
        QStringList args{"--grade"};
        for (const char *name : {"amy", "ben", "slow_cat", "dan", "eve"})
            args << correctCopy(dir, name);
        const QString report = dir.filePath("grades.csv");
        args << "--exercise" << kExercise << "--report" << report;

        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert("LIGHTBENCH_GRADE_PROGRAM", child);
        env.insert("LIGHTBENCH_GRADE_PROCESSES", "1");
        QProcess p;
        p.setProcessEnvironment(env);
        p.setChildProcessModifier([] { ::setpgid(0, 0); }); // a group of its own, as a shell's job
        p.start(LIGHTBENCH_EXE, args);
        QVERIFY(p.waitForStarted());
        // amy and ben finish, slow_cat hangs: the batch is stopped while it waits on that one.
        QTRY_VERIFY_WITH_TIMEOUT(QFileInfo(pidFile).size() > 0, 60000);
        QFile pidText(pidFile);
        QVERIFY(pidText.open(QIODevice::ReadOnly));
        const pid_t slowChild = pid_t(pidText.readAll().trimmed().toInt());
        QVERIFY(slowChild > 0);
        QVERIFY(::kill(wholeGroup ? -pid_t(p.processId()) : pid_t(p.processId()), signal) == 0);
        QVERIFY(p.waitForFinished(30000));
        QCOMPARE(p.exitStatus(), QProcess::NormalExit);
        QCOMPARE(p.exitCode(), 128 + signal);

        const QList<QByteArray> lines = p.readAllStandardOutput().trimmed().split('\n');
        QCOMPARE(lines.size(), 2);
        QVERIFY2(lines[0].startsWith("amy: passed") && lines[1].startsWith("ben: passed"),
                 lines.join('\n').constData());
        const QList<QStringList> rows = csvRows(report);
        QCOMPARE(rows.size(), 3); // the header, amy, ben
        QCOMPARE(rows[1][0], QString("amy"));
        QCOMPARE(rows[2][0], QString("ben"));
        QVERIFY2(p.readAllStandardError().contains("2 of 5 submissions done"), "the message");
        // The hanging child went with the batch, and no submission after it was started.
        QVERIFY(::kill(slowChild, 0) != 0 && errno == ESRCH);
        QFile started(starts);
        QVERIFY(started.open(QIODevice::ReadOnly));
        QCOMPARE(started.readAll(), QByteArray("amy\nben\nslow_cat\n"));
    }

    // `--grade submissions/*` over a folder of NAME.vert + NAME.frag pairs grades each student
    // once (it gave rows NAME and NAME-2).
    void aPairGivenAsTwoArgumentsIsOneSubmission()
    {
        QTemporaryDir tmp;
        const QDir dir(tmp.path());
        for (const char *student : {"alice", "bob"})
            for (const char *suffix : {".vert", ".frag"})
                QVERIFY(QFile::copy(kData + "/correct/lighting" + suffix,
                                    dir.filePath(QString(student) + suffix)));
        const QString child =
            writeStandIn(dir.filePath("child.sh"), dir.filePath("pid"), dir.filePath("starts"));
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert("LIGHTBENCH_GRADE_PROGRAM", child);
        const Run r = run({"--grade", dir.filePath("alice.frag"), dir.filePath("alice.vert"),
                           dir.filePath("bob.frag"), dir.filePath("bob.vert"), dir.filePath("bob"),
                           "--exercise", kExercise},
                          env);
        QVERIFY2(r.exitCode == 0, r.err.constData());
        // The stand-in passes one case of the exercise's 20: its 5 points of 100.
        QCOMPARE(r.out, QByteArray("alice: passed, 1/1 cases passed (5/100 points), largest "
                                   "difference 1/255, 100.0% of pixels within tolerance\n"
                                   "bob: passed, 1/1 cases passed (5/100 points), largest "
                                   "difference 1/255, 100.0% of pixels within tolerance\n"));
    }

    // Two batches writing one report (issue 49: both exited 0 and one's rows were lost): the
    // second is refused while the first runs, and may write it once the first is gone.
    void aSecondBatchOnTheSameReportIsRefused()
    {
        QTemporaryDir tmp;
        const QDir dir(tmp.path());
        const QString pidFile = dir.filePath("slow.pid"), starts = dir.filePath("starts");
        const QString child = writeStandIn(dir.filePath("child.sh"), pidFile, starts);
        const QString slow = correctCopy(dir, "slow_one"), amy = correctCopy(dir, "amy");
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert("LIGHTBENCH_GRADE_PROGRAM", child);
        const QString report = dir.filePath("grades.csv");
        QProcess first;
        first.setProcessEnvironment(env);
        first.start(LIGHTBENCH_EXE, {"--grade", slow, "--exercise", kExercise, "--report", report});
        QTRY_VERIFY_WITH_TIMEOUT(QFileInfo::exists(pidFile), 30000); // it is grading
        const Run second = run({"--grade", amy, "--exercise", kExercise, "--report", report}, env);
        QCOMPARE(second.exitCode, 2);
        QVERIFY2(second.err.contains("--report: ") &&
                     second.err.contains("is being written by another batch (process"),
                 second.err.constData());
        first.terminate();
        QVERIFY(first.waitForFinished(30000));
        const Run third = run({"--grade", amy, "--exercise", kExercise, "--report", report}, env);
        QVERIFY2(third.exitCode == 0, third.err.constData());
        QVERIFY(!QFileInfo::exists(report + ".lock"));
    }

    // One student's sheet that cannot be written (a FIFO in its place) fails that sheet, never
    // the class (issue 49): both are graded, the other's sheet is written, exit 1, the FIFO
    // stays a FIFO. Names as long as a file name may be (253 bytes; 80 CJK characters, 240
    // bytes) get sheets too: cut to 255 bytes with a hash where needed (the check of the
    // sheet names up front ended the batch, nobody graded).
    void oneSheetThatCannotBeWrittenFailsOnlyItself()
    {
        QTemporaryDir tmp;
        const QDir dir(tmp.path());
        QVERIFY(dir.mkpath("sheets"));
        const QString amy = correctCopy(dir, "amy"), bob = correctCopy(dir, "bob");
        const QString longName = QString(253, 'x'), cjk = QString(80, QChar(0x6f22));
        const QString longOne = correctCopy(dir, longName), cjkOne = correctCopy(dir, cjk);
        QVERIFY(!amy.isEmpty() && !bob.isEmpty() && !longOne.isEmpty() && !cjkOne.isEmpty());
        const QString fifo = dir.filePath("sheets/amy.png");
        QCOMPARE(::mkfifo(QFile::encodeName(fifo).constData(), 0600), 0);
        const Run r = run({"--grade", amy, bob, longOne, cjkOne, "--exercise", kExercise,
                           "--sheets", dir.filePath("sheets")});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.out.contains("amy: passed") && r.out.contains("bob: passed"), r.out.constData());
        // Said on amy's own line.
        QVERIFY2(r.out.contains("amy.png: not a regular file"), r.out.constData());
        struct stat st;
        QCOMPARE(::stat(QFile::encodeName(fifo).constData(), &st), 0);
        QVERIFY(S_ISFIFO(st.st_mode));
        const QStringList sheets = QDir(dir.filePath("sheets")).entryList({"*.png"}, QDir::Files);
        QVERIFY2(sheets.contains("bob.png") && sheets.contains(cjk + ".png"),
                 qPrintable(sheets.join(", ")));
        const QStringList cut = sheets.filter(QRegularExpression("^x+-[0-9a-f]{8}\\.png$"));
        QCOMPARE(cut.size(), 1);
        QVERIFY(QFile::encodeName(cut.first()).size() <= 255);
    }

    // The report and the sheets never replace what is not a regular file, and say so before
    // the first submission is graded (the stand-in child would leave a line in `starts`).
    void outputsThatAreNoFilesAreRefusedBeforeGrading_data()
    {
        QTest::addColumn<QString>("option");
        QTest::addColumn<QString>("kind");
        QTest::newRow("--report at a FIFO") << "--report"
                                            << "fifo";
        QTest::newRow("--report at /dev/null") << "--report"
                                               << "device";
        QTest::newRow("--report at a folder") << "--report"
                                              << "folder";
        QTest::newRow("--report in a missing folder") << "--report"
                                                      << "missing folder";
    }

    void outputsThatAreNoFilesAreRefusedBeforeGrading()
    {
        QFETCH(QString, option);
        QFETCH(QString, kind);
        QTemporaryDir tmp;
        const QDir dir(tmp.path());
        const QString starts = dir.filePath("starts");
        const QString child = writeStandIn(dir.filePath("child.sh"), dir.filePath("pid"), starts);
        const QString submission = correctCopy(dir, "amy");
        QString target = dir.filePath("grades.csv"), value = target, named = "not a regular file";
        if (option == "--sheets") {
            QVERIFY(dir.mkpath("sheets"));
            value = dir.filePath("sheets");
            target = dir.filePath("sheets/amy.png");
        }
        if (kind == "fifo") {
            QCOMPARE(::mkfifo(QFile::encodeName(target).constData(), 0600), 0);
        } else if (kind == "device") {
            value = target = "/dev/null";
        } else if (kind == "folder") {
            QVERIFY(dir.mkpath("grades.csv"));
        } else {
            value = dir.filePath("nowhere/grades.csv");
            named = "the folder " + dir.filePath("nowhere") + " does not exist";
        }
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert("LIGHTBENCH_GRADE_PROGRAM", child);
        const Run r = run({"--grade", submission, "--exercise", kExercise, option, value}, env);
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(option.toUtf8() + ": ") && r.err.contains(named.toUtf8()),
                 r.err.constData());
        QVERIFY2(!QFileInfo::exists(starts), "a submission was graded first");
        if (kind == "fifo" || kind == "device") {
            struct stat st;
            QCOMPARE(::stat(QFile::encodeName(target).constData(), &st), 0);
            QVERIFY(kind == "fifo" ? S_ISFIFO(st.st_mode) : S_ISCHR(st.st_mode));
        }
    }
};

QTEST_MAIN(TestGrading)
#include "test_grading.moc"
