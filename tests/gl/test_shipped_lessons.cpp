// The two lessons lightbench ships (resources/lessons, built in as :/lessons/): the slides'
// (Portuguese and English) and the exercise sheet's (German and English). Read from the
// resources as the window and the command line read them: no error, nothing ignored, every
// step with a title and a caption in both languages; every step drawn (with its own program
// where it has one, which must build and pass the trial) and visibly different from the one
// before; a few steps through the real command line.
//
// The checks themselves are tried on bad lessons (badLessonsAreCaught): a step with English
// only, a caption copied untranslated, a caption of six lines, a scene field misspelt, two
// consecutive steps with the same scene, a step whose program does not compile, and a step
// past the end on the command line.
#include "lesson.h"
#include "offscreen.h"
#include "reference_compare.h"

#include <QDir>
#include <QGuiApplication>
#include <QImage>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

#include <algorithm>
#include <cmath>

using namespace lb;

namespace {

const QSize kStepSize(160, 120);
// Consecutive steps must differ by at least this mean absolute difference per channel, in
// 1/255, over the whole frame. The same scene drawn twice differs by 0; the smallest change a
// shipped lesson makes on purpose (the sheet's highlight appearing on the sphere, Aufgabe 3)
// moves about 0.5 on average, a changed light, frame, term or program far more.
constexpr double kVisibleDifference = 0.3;
constexpr int kMaxCaptionLines = 4;

// The mean absolute difference of the colour channels of two frames of one size, in 1/255.
double meanAbsoluteDifference(const QImage &a, const QImage &b)
{
    if (a.size() != b.size() || a.isNull())
        return 255.0;
    const QImage x = a.convertToFormat(QImage::Format_RGB32);
    const QImage y = b.convertToFormat(QImage::Format_RGB32);
    double sum = 0.0;
    for (int row = 0; row < x.height(); ++row) {
        const auto *p = reinterpret_cast<const QRgb *>(x.constScanLine(row));
        const auto *q = reinterpret_cast<const QRgb *>(y.constScanLine(row));
        for (int col = 0; col < x.width(); ++col)
            sum += std::abs(qRed(p[col]) - qRed(q[col])) +
                   std::abs(qGreen(p[col]) - qGreen(q[col])) +
                   std::abs(qBlue(p[col]) - qBlue(q[col]));
    }
    return sum / (3.0 * x.width() * x.height());
}

// The share of pixels unlike the top left one (the background): something was drawn.
double drawnShare(const QImage &frame)
{
    const QRgb background = frame.pixel(0, 0);
    int drawn = 0;
    for (int row = 0; row < frame.height(); ++row)
        for (int col = 0; col < frame.width(); ++col)
            drawn += frame.pixel(col, row) != background;
    return double(drawn) / (frame.width() * frame.height());
}

// What is wrong with the text of `lesson` for a class taught in `language`.
QStringList textProblems(const Lesson &lesson, const QString &language)
{
    QStringList problems;
    const auto check = [&](const LocalizedText &text, const QString &where, int maxLines) {
        for (const QString &code : {QString("en"), language})
            if (text.value(code).trimmed().isEmpty())
                problems << QString("%1: no %2 text").arg(where, code);
        if (text.contains("en") && text.value(language) == text.value("en"))
            problems << QString("%1: the %2 text is the English one").arg(where, language);
        for (const QString &code : text.keys())
            if (text[code].count('\n') + 1 > maxLines)
                problems << QString("%1.%2: %3 lines; at most %4")
                                .arg(where, code)
                                .arg(text[code].count('\n') + 1)
                                .arg(maxLines);
    };
    check(lesson.title, "title", 1);
    for (std::size_t i = 0; i < lesson.steps.size(); ++i) {
        const QString where = QString("step %1").arg(i + 1);
        check(lesson.steps[i].title, where + ": title", 1);
        check(lesson.steps[i].caption, where + ": caption", kMaxCaptionLines);
    }
    return problems;
}

QString joined(const QStringList &list)
{
    return list.join("\n  ");
}

} // namespace

class TestShippedLessons : public QObject
{
    Q_OBJECT
private:
    OffscreenRenderer m_offscreen;
    QTemporaryDir m_dir;

    // Draws `step` with its program (or the built-in one); an empty image and a message in
    // `problem` when its program does not build or is refused by the trial.
    QImage renderStep(const LessonStep &step, QString &problem)
    {
        const Scene &scene = step.scene.scene;
        if (const QString error = m_offscreen.readTextureFiles(scene); !error.isEmpty()) {
            problem = error;
            return {};
        }
        if (!step.scene.program) {
            m_offscreen.renderer().clearUserProgram();
            return m_offscreen.render(scene);
        }
        const ProgramText &program = *step.scene.program;
        const ProgramBuild build = m_offscreen.useProgram(program.vertex, program.fragment);
        if (!build.ok() || build.hasErrors()) {
            problem = "its program does not build: " + build.log();
            return {};
        }
        const TrialResult trial = m_offscreen.tryUserProgram(
            scene, program.vertex, program.fragment, kStepSize, 1000.0, kCommandLineTrial);
        if (trial.refusal) {
            problem = "its program is refused: " + trial.refusal->message;
            return {};
        }
        return m_offscreen.render(scene);
    }

    // Every step drawn; what is wrong: a step not drawn, or drawn like the step before (that
    // frame is saved as LB_TEST_OUTPUT/NAME_step_N.png unless `name` is empty). `frames` gets
    // the frames, in order.
    QStringList renderProblems(const Lesson &lesson, const QString &name,
                               std::vector<QImage> *frames = nullptr)
    {
        QStringList problems;
        QImage previous;
        for (std::size_t i = 0; i < lesson.steps.size(); ++i) {
            const QString where = QString("step %1").arg(i + 1);
            QString problem;
            const QImage frame = renderStep(lesson.steps[i], problem);
            if (frame.isNull()) {
                problems << QString("%1: %2").arg(where, problem.isEmpty() ? "no frame" : problem);
            } else if (drawnShare(frame) < 0.02) {
                problems << QString("%1: nothing drawn").arg(where);
            } else if (!previous.isNull()) {
                const double difference = meanAbsoluteDifference(previous, frame);
                if (difference < kVisibleDifference)
                    problems << QString("%1: looks like step %2 (mean difference %3/255, at "
                                        "least %4 wanted)%5")
                                    .arg(where)
                                    .arg(i)
                                    .arg(difference, 0, 'f', 2)
                                    .arg(kVisibleDifference)
                                    .arg(name.isEmpty()
                                             ? QString()
                                             : "; saved as " +
                                                   test::saveForInspection(
                                                       frame,
                                                       QString("%1_step_%2").arg(name).arg(i + 1)));
            }
            previous = frame;
            if (frames)
                frames->push_back(frame);
        }
        return problems;
    }

    // The shipped lessons and the language each is taught in, besides English.
    static void lessons_data()
    {
        QTest::addColumn<QString>("name");
        QTest::addColumn<QString>("language");
        QTest::addColumn<int>("minSteps");
        QTest::addColumn<int>("maxSteps");
        QTest::newRow("slides") << "slides"
                                << "pt" << 8 << 14;
        QTest::newRow("exercise sheet") << "exercise_sheet"
                                        << "de" << 6 << 14;
    }

    static QString lessonPath(const QString &name) { return ":/lessons/" + name + ".json"; }

    static QByteArray runCommandLine(const QStringList &args, int *exitCode)
    {
        QProcess p;
        p.start(LIGHTBENCH_EXE, args);
        if (!p.waitForFinished(60000)) {
            p.kill();
            p.waitForFinished();
            *exitCode = -1;
            return "timed out";
        }
        *exitCode = p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -2;
        return p.readAllStandardError();
    }

private slots:
    void initTestCase()
    {
        const QString error = m_offscreen.initialize(kStepSize);
        QVERIFY2(error.isEmpty(), qPrintable(error));
        QVERIFY(m_dir.isValid());
    }

    void readWholeInTwoLanguages_data() { lessons_data(); }
    void readWholeInTwoLanguages()
    {
        QFETCH(QString, name);
        QFETCH(QString, language);
        QFETCH(int, minSteps);
        QFETCH(int, maxSteps);
        const LessonRead read = readLessonFile(lessonPath(name));
        QVERIFY2(read.lesson, qPrintable(read.error));
        QVERIFY2(read.ignored.isEmpty(), qPrintable("ignored:\n  " + joined(read.ignored)));
        QVERIFY2(read.stepErrors.isEmpty(), qPrintable("\n  " + joined(read.stepErrors)));
        const int steps = int(read.lesson->steps.size());
        QVERIFY2(steps >= minSteps && steps <= maxSteps, qPrintable(QString::number(steps)));
        const QStringList problems = textProblems(*read.lesson, language);
        QVERIFY2(problems.isEmpty(), qPrintable("\n  " + joined(problems)));
        // Scene files named by a step come from the built-in examples beside the lessons.
        for (const LessonStep &step : read.lesson->steps)
            if (!step.scenePath.isEmpty())
                QVERIFY2(step.scenePath.startsWith(":/examples/"), qPrintable(step.scenePath));
    }

    void everyStepDrawsAndDiffersFromTheLast_data() { lessons_data(); }
    void everyStepDrawsAndDiffersFromTheLast()
    {
        QFETCH(QString, name);
        const LessonRead read = readLessonFile(lessonPath(name));
        QVERIFY2(read.lesson, qPrintable(read.error));
        std::vector<QImage> frames;
        const QStringList problems = renderProblems(*read.lesson, name, &frames);
        QVERIFY2(problems.isEmpty(), qPrintable("\n  " + joined(problems)));
        QCOMPARE(frames.size(), read.lesson->steps.size());
        double smallest = 255.0;
        for (std::size_t i = 1; i < frames.size(); ++i)
            smallest = std::min(smallest, meanAbsoluteDifference(frames[i - 1], frames[i]));
        qInfo("closest consecutive steps: %.2f/255 apart", smallest);
    }

    // The command line opens a built-in lesson's step as the scene and draws what this
    // process draws for it: an inline scene, a scene file named by the lesson, a program.
    void commandLineRendersSteps_data()
    {
        QTest::addColumn<QString>("name");
        QTest::addColumn<int>("step");
        QTest::newRow("slides 1: inline") << "slides" << 1;
        QTest::newRow("slides 8: ../examples/phong_vs_blinn.json") << "slides" << 8;
        QTest::newRow("sheet 1: the sheet's program") << "exercise_sheet" << 1;
        QTest::newRow("sheet 10: toon.json, GLSL 3.30") << "exercise_sheet" << 10;
    }

    void commandLineRendersSteps()
    {
        QFETCH(QString, name);
        QFETCH(int, step);
        const LessonRead read = readLessonFile(lessonPath(name));
        QVERIFY2(read.lesson, qPrintable(read.error));
        QVERIFY(step <= int(read.lesson->steps.size()));
        const QString png = m_dir.filePath(QString("%1_%2.png").arg(name).arg(step));
        int exitCode = 0;
        const QByteArray err = runCommandLine(
            {"--lesson", lessonPath(name), "--step", QString::number(step), "--render", png,
             "--size", QString("%1x%2").arg(kStepSize.width()).arg(kStepSize.height())},
            &exitCode);
        QVERIFY2(exitCode == 0, err.constData());
        QVERIFY2(!err.contains("ignored"), err.constData());
        const QImage fromCommandLine(png);
        QCOMPARE(fromCommandLine.size(), kStepSize);
        QString problem;
        const QImage here = renderStep(read.lesson->steps[std::size_t(step - 1)], problem);
        QVERIFY2(problem.isEmpty(), qPrintable(problem));
        const double difference = meanAbsoluteDifference(here, fromCommandLine);
        QVERIFY2(difference < 0.5, qPrintable(QString("%1/255 apart").arg(difference)));
    }

    // The checks above fail where they should: each bad lesson is caught, by its step.
    void badLessonsAreCaught()
    {
        const QByteArray good = R"({"en": "Diffuse", "pt": "Difuso"})";
        const auto lesson = [&](const QByteArray &steps) {
            const QByteArray bytes = R"({"format": "lightbench-lesson", "version": 1, "title": )" +
                                     good + R"(, "steps": [)" + steps + "]}";
            return parseLesson(bytes, QDir(":/lessons"), "bad.json");
        };
        const QByteArray sphere = R"({"objects": [{"shape": "sphere"}]})";
        const QByteArray cube = R"({"objects": [{"shape": "cube"}]})";
        const auto step = [&](const QByteArray &title, const QByteArray &caption,
                              const QByteArray &scene) {
            return R"({"title": )" + title + R"(, "caption": )" + caption + R"(, "scene": )" +
                   scene + "}";
        };

        // English only; the Portuguese text the English one; six lines.
        LessonRead read = lesson(step(good, R"("Only English")", sphere) + "," +
                                 step(good, R"({"en": "Same", "pt": "Same"})", cube) + "," +
                                 step(good, R"({"en": "1\n2\n3\n4\n5\n6", "pt": "um"})", sphere));
        QVERIFY(read.lesson);
        const QStringList text = textProblems(*read.lesson, "pt");
        QVERIFY2(text.size() == 3, qPrintable(joined(text)));
        QVERIFY(text[0].startsWith("step 1: caption: no pt text"));
        QVERIFY(text[1].startsWith("step 2: caption: the pt text is the English one"));
        QVERIFY(text[2].startsWith("step 3: caption.en: 6 lines"));

        // A misspelt scene field is named as ignored.
        read = lesson(step(good, good, R"({"objects": [{"shap": "cube"}]})"));
        QVERIFY(read.lesson);
        QVERIFY2(read.ignored.size() == 1 && read.ignored[0].contains("objects[0].shap"),
                 qPrintable(joined(read.ignored)));

        // The same scene twice in a row, and a program that does not compile.
        const QByteArray broken = R"({"objects": [{"shape": "cube"}], "program": {"name": "x",
            "vertex": "void main() { gl_Position = vec4(0.0); }",
            "fragment": "void main() { gl_FragColor = undefinedThing; }"}})";
        read = lesson(step(good, good, sphere) + "," + step(good, good, sphere) + "," +
                      step(good, good, cube) + "," + step(good, good, broken));
        QVERIFY(read.lesson);
        const QStringList drawn = renderProblems(*read.lesson, {});
        QVERIFY2(drawn.size() == 2, qPrintable(joined(drawn)));
        QVERIFY2(drawn[0].startsWith("step 2: looks like step 1"), qPrintable(drawn[0]));
        QVERIFY2(drawn[1].startsWith("step 4: its program does not build"), qPrintable(drawn[1]));

        // A step past the end of a built-in lesson is refused by name on the command line.
        int exitCode = 0;
        const QByteArray err = runCommandLine({"--lesson", lessonPath("slides"), "--step", "99",
                                               "--render", m_dir.filePath("past.png")},
                                              &exitCode);
        QVERIFY2(exitCode != 0 && err.contains("step"), err.constData());
    }
};

int main(int argc, char **argv)
{
    setDefaultGlFormat();
    QGuiApplication app(argc, argv);
    TestShippedLessons test;
    return QTest::qExec(&test, argc, argv);
}
#include "test_shipped_lessons.moc"
