// The messages made below the window (render/model, render/glsl) go through Qt's translation
// system, whole (issue 31): with a translator that marks every text it is asked for
// (marking_translator.h), each message comes back marked in its file's context, one sentence
// to a mark, while the data around it (a scene file's field names, JSON, preset keys, shape
// words written into files) stays as it was. Without a translator the English is unchanged,
// plurals included (the command line installs none; its tests compare its words).
// Bad inputs tried: JSON that does not parse, a scene whose fields have wrong types, unknown
// keys, unknown words, out-of-range numbers and a w of 0.5; a lesson with a step that is no
// object, a caption of numbers and a panel that does not exist; an exercise without a
// reference and with an unknown shading; a folder, a missing file and a too-big file read as
// a scene; a save into a missing folder, onto a folder, of a null image and over the limit; a
// JPEG without a scan; an empty image file and one wider than a texture may be; a mesh file
// with broken faces and non-finite numbers; 32 spheres over the memory budget; a torus
// built under an address-space limit; endless, counted and macro-made loops; a macro bomb; a
// program too slow to draw.

#include "address_space.h"
#include "bounded_read.h"
#include "exercise.h"
#include "grading.h"
#include "grading_report.h"
#include "image_truncation.h"
#include "lesson.h"
#include "loops.h"
#include "macro_expansion.h"
#include "marking_translator.h"
#include "mesh_file.h"
#include "message_text.h"
#include "object_mesh.h"
#include "presets.h"
#include "program_trial.h"
#include "safe_write.h"
#include "scene_budget.h"
#include "scene_file.h"
#include "texture_file.h"

#include <QFile>
#include <QImage>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

#include <sys/resource.h>

using namespace lb;

namespace {

QByteArray json(const QJsonObject &o)
{
    return QJsonDocument(o).toJson();
}

// What an ignored field reads as with the marks: the file's own path, unmarked, in the
// context's "%1 (%2)", the reason marked in its own context.
QString ignoredField(const char *context, const QString &path, const char *reasonContext,
                     const QString &reason)
{
    return marked(context, "%1 (%2)").arg(path, marked(reasonContext, reason));
}

} // namespace

class TestRenderMessages : public QObject
{
    Q_OBJECT

private slots:
    // English plurals stay as they were without a translator ("1 object", "32 objects"),
    // while a translator gets the numerus source ("%n object(s)") to give its own forms.
    void pluralsKeepTheirEnglishWithoutATranslator()
    {
        const char *source = QT_TRANSLATE_N_NOOP("lb::Test", "%n object(s) at tessellation %1");
        QCOMPARE(countedText("lb::Test", source, 1), QString("1 object at tessellation %1"));
        QCOMPARE(countedText("lb::Test", source, 32).arg(2000),
                 QString("32 objects at tessellation 2000"));
        QCOMPARE(countedText("lb::Test", source, 0), QString("0 objects at tessellation %1"));
        const MarkedMessages marks;
        QCOMPARE(countedText("lb::Test", source, 1),
                 marked("lb::Test", "1 object(s) at tessellation %1"));
    }

    void sceneFileMessagesAreTranslatedItsFieldNamesAreNot()
    {
        const MarkedMessages marks;
        const SceneFileRead broken = parseSceneFile("{\"lights\": [", QDir("/tmp"), "x.json");
        QVERIFY2(broken.error.startsWith(
                     marked("lb::SceneFile", "x.json: not a scene file: ").chopped(1)),
                 qPrintable(broken.error));

        QJsonObject root{{"format", "lightbench-other"},
                         {"version", "two"},
                         {"program", 3},
                         {"lights", QJsonArray{QJsonObject{{"frame", "sideways"},
                                                           {"position", QJsonArray{0, 1, 0, 0.5}},
                                                           {"colour", 1}}}},
                         {"objects", QJsonArray{QJsonObject{{"tessellation", 40.5}}}},
                         {"shaderValues", QJsonObject{{"u", "x"}}}};
        const SceneFileRead read = parseSceneObject(root, QDir("/tmp"));
        const QStringList expected{
            ignoredField("lb::SceneJson", "format", "lb::SceneFile",
                         "expected \"lightbench-scene\""),
            ignoredField("lb::SceneJson", "version", "lb::SceneFile",
                         "missing or not a number; read as 3"),
            ignoredField("lb::SceneJson", "program", "lb::SceneFile", "not an object"),
            ignoredField("lb::SceneJson", "lights[0].colour", "lb::SceneJson", "unknown field"),
            ignoredField("lb::SceneJson", "lights[0].position", "lb::LightingParameters",
                         "w must be 0 (directional) or 1 (point)"),
            ignoredField("lb::SceneJson", "lights[0].frame", "lb::SceneJson", "unknown value"),
            ignoredField("lb::SceneJson", "objects[0].tessellation", "lb::SceneJson",
                         "not a whole number"),
            ignoredField("lb::SceneJson", "shaderValues.u", "lb::SceneJson", "not 1 to 4 numbers")};
        for (const QString &e : expected)
            QVERIFY2(read.ignored.contains(e), qPrintable(e + "\nin\n" + read.ignored.join('\n')));
        QCOMPARE(read.ignored.size(), expected.size());

        // What is written is data: the same bytes with and without a translator.
        QVERIFY(read.file);
        const QByteArray withMarks = sceneFileBytes(*read.file, QDir("/tmp"));
        QVERIFY(!withMarks.contains("\xc2\xab")); // no mark («) in the file
        QVERIFY(withMarks.contains("\"shape\": \"sphere\""));
    }

    void lessonMessagesAreTranslated()
    {
        const MarkedMessages marks;
        const QJsonObject lesson{
            {"format", "lightbench-lesson"},
            {"steps", QJsonArray{QJsonObject{{"caption", 7}, {"panel", "kitchen"}}, 3}}};
        const LessonRead read = parseLesson(json(lesson), QDir("/tmp"), "l.json");
        QVERIFY(read.lesson);
        const QString step1 = marked("lb::Lesson", "step %1").arg(1);
        const QString step2 = marked("lb::Lesson", "step %1").arg(2);
        QVERIFY2(read.ignored.contains(
                     marked("lb::Lesson", "%1 (%2)")
                         .arg(step1 + ": caption", marked("lb::LocalizedText", "not text"))),
                 qPrintable(read.ignored.join('\n')));
        // The words a file may give are its own: listed as they are spelt.
        const QString panel = marked("lb::Lesson", "\"%1\" is not one of %2")
                                  .arg("kitchen", lessonPanels().join(", "));
        QVERIFY2(
            read.ignored.contains(marked("lb::Lesson", "%1 (%2)").arg(step1 + ": panel", panel)),
            qPrintable(read.ignored.join('\n')));
        QCOMPARE(read.lesson->steps[1].error, marked("lb::Lesson", "%1: not an object").arg(step2));
        QCOMPARE(read.lesson->steps[0].error,
                 marked("lb::Lesson", "%1: no scene (\"scene\" must be a scene object or the "
                                      "name of a scene file)")
                     .arg(step1));
        QCOMPARE(parseLesson("[]", QDir("/tmp"), "l.json").error,
                 marked("lb::Lesson", "%1: not a lesson file (\"format\" is not \"%2\")")
                     .arg("l.json", "lightbench-lesson"));
    }

    void exerciseMessagesAreTranslatedItsSectionNamesAreNot()
    {
        const MarkedMessages marks;
        QStringList ignored;
        const ExerciseRead none = readExercise(QJsonObject{{"task", "t"}}, &ignored);
        QVERIFY2(none.error.startsWith(
                     marked("lb::Exercise", "exercise: no reference program").chopped(1)),
                 qPrintable(none.error));
        const ExerciseRead read = readExercise(
            QJsonObject{{"reference", QJsonObject{{"builtIn", QJsonObject{{"shading", "toon"}}}}},
                        {"colour", 1}},
            &ignored);
        QVERIFY(read.error.isEmpty());
        QVERIFY2(
            ignored.contains(marked("lb::Exercise", "%1 (%2)")
                                 .arg("exercise.colour", marked("lb::Exercise", "unknown field"))),
            qPrintable(ignored.join('\n')));
        QVERIFY2(ignored.contains(
                     marked("lb::Exercise", "%1 (%2)")
                         .arg("exercise.reference.builtIn.shading",
                              marked("lb::Exercise", "not %1").arg(shadingNames().join(", ")))),
                 qPrintable(ignored.join('\n')));
    }

    void fileMessagesAreTranslated()
    {
        const MarkedMessages marks;
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const FileLimit limit{QT_TRANSLATE_NOOP("lb::FileLimit", "a scene file"), 4};
        QCOMPARE(unreadableFile(dir.path(), limit),
                 marked("lb::BoundedRead", "%1: not a regular file (a folder, a device or a pipe)")
                     .arg(dir.path()));
        QCOMPARE(unreadableFile(dir.filePath("gone"), limit),
                 dir.filePath("gone") + ": " + marked("lb::BoundedRead", "no such file"));
        QFile big(dir.filePath("big.json"));
        QVERIFY(big.open(QIODevice::WriteOnly) && big.write("0123456789") == 10);
        big.close();
        QCOMPARE(unreadableFile(big.fileName(), limit),
                 marked("lb::BoundedRead", "%1: %2 is more than %3 may be (%4)")
                     .arg(big.fileName(), marked("lb::BoundedRead", "%1 KiB").arg(1),
                          marked("lb::FileLimit", "a scene file"),
                          marked("lb::BoundedRead", "%1 KiB").arg(1)));
        const QString over =
            writeWithinLimit(dir.filePath("s.json"), "0123456789",
                             QT_TRANSLATE_NOOP("lb::FileLimit", "the scene"), limit);
        QVERIFY2(over.contains(marked("lb::FileLimit", "the scene")), qPrintable(over));
        QVERIFY2(
            over.startsWith(
                marked("lb::BoundedRead", "%1: not saved").arg(dir.filePath("s.json")).chopped(1)),
            qPrintable(over));

        QCOMPARE(
            writeFileSafely(dir.filePath("none/s.json"), "x"),
            dir.filePath("none/s.json") + ": " +
                marked("lb::SafeWrite", "the folder %1 does not exist").arg(dir.filePath("none")));
        QCOMPARE(writeFileSafely(dir.path(), "x"),
                 dir.path() + ": " +
                     marked("lb::SafeWrite",
                            "not a regular file (a device, a pipe or a folder); not replaced"));
        QCOMPARE(writeImageSafely(dir.filePath("i.png"), QImage()),
                 dir.filePath("i.png") + ": " + marked("lb::SafeWrite", "no image to write"));
    }

    void imageMessagesAreTranslated()
    {
        const MarkedMessages marks;
        QCOMPARE(truncatedImage(QByteArray("\xFF\xD8\xFF\xD9", 4), "jpeg"),
                 marked("lb::ImageTruncation", "no image data (no scan)"));
        QTemporaryDir dir;
        QFile empty(dir.filePath("empty.png"));
        QVERIFY(empty.open(QIODevice::WriteOnly));
        empty.close();
        QCOMPARE(
            readTextureFile(empty.fileName()).error,
            marked("lb::TextureFile", "%1: an empty file, not an image").arg(empty.fileName()));
        // A picture wider than a texture is scaled: the summary says so in one sentence.
        QImage wide(Texture::kMaxSize * 2, 2, QImage::Format_RGB32);
        wide.fill(Qt::red);
        QVERIFY(wide.save(dir.filePath("wide.png")));
        const TextureFileRead read = readTextureFile(dir.filePath("wide.png"));
        QVERIFY2(read.texture, qPrintable(read.error));
        const QSize drawn = read.texture->image().size();
        QVERIFY(drawn.width() <= Texture::kMaxSize);
        QCOMPARE(read.summary, marked("lb::TextureFile", "%1: %2 x %3 texels (scaled from %4 x %5)")
                                   .arg("wide.png")
                                   .arg(drawn.width())
                                   .arg(drawn.height())
                                   .arg(Texture::kMaxSize * 2)
                                   .arg(2));
    }

    void meshFileMessagesAreTranslated()
    {
        const MarkedMessages marks;
        MeshFile file;
        file.path = "/tmp/teapot.obj";
        Mesh mesh = makeShape(Shape::Cube, 1);
        mesh.normals.clear(); // the file has none
        file.mesh = std::make_shared<const Mesh>(std::move(mesh));
        file.skippedFaces = 3;
        file.seconds = 0.5;
        const QString skipped =
            marked("lb::MeshFile", "%1 points, lines or broken faces skipped").arg(3);
        QCOMPARE(file.remarks(), QStringList{skipped});
        // One sentence for what was drawn, the remarks after it.
        QCOMPARE(meshSummary("teapot.obj", 24, 12, &file),
                 marked("lb::MeshFile", "%1 (%2)")
                     .arg(marked("lb::MeshFile", "%1: %2 vertices, %3 triangles, loaded in %4 s, "
                                                 "normals generated (the file has none)")
                              .arg("teapot.obj", "24", "12", "0.50"),
                          skipped));
        QCOMPARE(meshSummary(shapeLabel(Shape::Torus), 24, 12, nullptr),
                 marked("lb::MeshFile", "%1: %2 vertices, %3 triangles")
                     .arg(marked("lb::Scene", "torus"), "24", "12"));
    }

    // The scene budget's message: two clauses, each a whole sentence with its own count.
    void budgetMessageIsTranslatedWhole()
    {
        Scene scene;
        scene.objects.assign(32, ObjectSettings{});
        for (ObjectSettings &o : scene.objects)
            o.tessellation = 2000;
        Scene english = scene;
        const MeshBudget budget{64ull << 20, 8ull << 30};
        const BudgetFit plain = fitToBudget(english, {}, budget);
        QVERIFY2(plain.message.startsWith("32 objects at tessellation 2000 would make "),
                 qPrintable(plain.message));
        QVERIFY2(plain.message.contains("; tessellation lowered to "), qPrintable(plain.message));
        const MarkedMessages marks;
        const BudgetFit fit = fitToBudget(scene, {}, budget);
        // "%1; %2" holds both clauses; %n is filled in in the translator's text.
        QVERIFY2(fit.message.startsWith("\u00ablb::SceneBudget|\u00ablb::SceneBudget|32 object(s) "
                                        "at tessellation 2000 would make "),
                 qPrintable(fit.message));
        QVERIFY2(fit.message.contains(
                     "; " +
                     marked("lb::SceneBudget", "tessellation lowered to %1 on 32 object(s) (")
                         .arg(fit.tessellation)
                         .chopped(1) +
                     marked("lb::Scene", "sphere") + " #1, "),
                 qPrintable(fit.message));
    }

    // A real allocation failure, as test_scene_budget makes it: the message is translated.
#ifndef LIGHTBENCH_SANITIZE // ASan cannot run under an address-space limit (moc sees this one)
    void outOfMemoryIsTranslated()
    {
        rlimit old{};
        QVERIFY(getrlimit(RLIMIT_AS, &old) == 0);
        const rlim_t now = lb::test::addressSpaceInUse();
        QVERIFY(now > 0);
        ObjectSettings torus;
        torus.shape = Shape::Torus;
        torus.tessellation = 2000;
        const MarkedMessages marks;
        rlimit tight = old;
        tight.rlim_cur = now + (64u << 20);
        QVERIFY(setrlimit(RLIMIT_AS, &tight) == 0);
        const ObjectMeshBuild built = tryBuildObjectMesh(torus, nullptr);
        setrlimit(RLIMIT_AS, &old);
        QVERIFY(!built.mesh);
        QCOMPARE(built.error,
                 marked("lb::ObjectMesh", "out of memory building the torus at tessellation %1")
                     .arg(2000));
    }
#endif

    void shaderMessagesAreTranslatedWhole()
    {
        const MarkedMessages marks;
        const QString endless = "void main() {\n  for (;;) {}\n  gl_FragColor = vec4(1.0);\n}\n";
        const auto warnings = endlessLoopWarnings(endless, ShaderStage::Fragment);
        QCOMPARE(int(warnings.size()), 1);
        QCOMPARE(warnings[0].message,
                 marked("lb::Loops", "this loop never ends: it has no condition and nothing in "
                                     "it breaks, returns or discards (the driver may drop it "
                                     "and draw garbage, or hang)"));
        const QString vertex = "void main() { gl_Position = vec4(0.0); }\n";
        const QString refusedEndless = marked(
            "lb::Loops", "this program never finishes a frame: the loop here has no condition "
                         "(or an always-true one) and no break, return or discard");
        QCOMPARE(refusalWithoutFrames(vertex, endless)->message, refusedEndless);
        // A macro's loop: the note is part of the sentence, in the refusal too.
        const QString fromMacro = "#define FOREVER for (;;)\nvoid main() {\n  FOREVER {}\n  "
                                  "gl_FragColor = vec4(1.0);\n}\n";
        QCOMPARE(refusalWithoutFrames(vertex, fromMacro)->message,
                 marked("lb::Loops", "%1 (the loop comes from macro %2, used on this line)")
                     .arg(refusedEndless, "FOREVER"));
        // A counter moving away from its bound, in the vertex stage.
        const QString wrapping =
            "void main() {\n  float s = 0.0;\n  for (int i = 0; i >= 0; i++) { s += 1.0; }\n"
            "  gl_Position = vec4(s);\n}\n";
        QCOMPARE(refusalWithoutFrames(wrapping, "void main() {}\n")->message,
                 marked("lb::Loops",
                        "this program never finishes a frame: the loop here runs %1 times for "
                        "every vertex (its counter moves away from its bound: only wrapping "
                        "around ends it): a frame would take seconds or more on any GPU "
                        "(llvmpipe stops it after 65,535 steps and draws a wrong picture)")
                     .arg("2,147,483,648"));
        // A macro bomb.
        QString bomb = "#define M0 1.0\n";
        for (int i = 1; i < 40; ++i)
            bomb += QString("#define M%1 (M%2+M%2)\n").arg(i).arg(i - 1);
        bomb += "void main() { gl_FragColor = vec4(M39); }\n";
        const std::optional<Diagnostic> refusal =
            macroExpansionRefusal(bomb, ShaderStage::Fragment);
        QVERIFY(refusal);
        QVERIFY2(refusal->message.startsWith(
                     marked("lb::MacroExpansion", "macro M39 expands to ").chopped(1)),
                 qPrintable(refusal->message));
        QVERIFY(refusal->message.endsWith("refused before the driver sees it\u00bb"));
    }

    void trialMessagesAreTranslated()
    {
        const MarkedMessages marks;
        const QString fragment = "void main() {\n  gl_FragColor = vec4(sin(1.0));\n}\n";
        // 2 ms per 1000 pixels, measured the same at every size: over the 100 ms budget.
        const TrialResult r =
            tryProgram("void main() { gl_Position = vec4(0.0); }\n", fragment, QSize(640, 480),
                       100.0, kWindowTrial, [](QSize s) { return 2e-3 * s.width() * s.height(); });
        QVERIFY(r.refusal);
        QCOMPARE(r.refusal->message,
                 marked("lb::ProgramTrial",
                        "drawing one frame with this program at %1x%2 would take more than its "
                        "budget of %3: too much work for every pixel?")
                     .arg("640", "480", marked("lb::ProgramTrial", "%1 ms").arg(100)));
        QVERIFY2(r.refusal->message.endsWith("too much work for every pixel?\u00bb"),
                 qPrintable(r.refusal->message));
        QCOMPARE(durationText(3400), marked("lb::ProgramTrial", "%1 s").arg("3.4"));
    }

    // The sheet's title is translated; the report the grading child writes is data.
    void gradingTextIsTranslatedItsReportIsNot()
    {
        CaseResult result;
        result.largest = 12;
        result.at = QPoint(40, 17);
        result.shareWithin = 0.985;
        result.compared = 5120;
        QCOMPARE(gradingSheetTitle("alice", result, 3),
                 QString("alice - case 3: largest difference 12/255 at (40, 17), 98.5% of 5120 "
                         "pixels within tolerance, failed"));
        GradingReport report;
        report.submission = "alice";
        report.status = "graded";
        report.cases = {result};
        const QJsonObject data = gradingReportJson(report);
        const MarkedMessages marks;
        QCOMPARE(gradingSheetTitle("a%2", result, 3),
                 marked("lb::Grading", "%1 - case %2: largest difference %3/255 at (%4, %5), %6% "
                                       "of %7 pixels within tolerance, %8")
                     .arg("a%2", "3", "12", "40", "17", "98.5", "5120",
                          marked("lb::Grading", "failed")));
        QCOMPARE(gradingReportJson(report), data);
    }

    // Names shown are translated; the words files hold are not.
    void namesShownAreTranslatedKeysAreNot()
    {
        const MarkedMessages marks;
        const Preset &phong = builtInPreset(false);
        QCOMPARE(phong.name, QString("Built-in: Phong shading (per fragment)"));
        QCOMPARE(phong.title(), marked("lb::Presets", phong.name));
        QCOMPARE(presetNamed(phong.name), &phong);
        QCOMPARE(toName(Shape::Sphere), QString("sphere"));
        QCOMPARE(displayName(ObjectSettings{}), marked("lb::Scene", "sphere"));
        QCOMPARE(summarisedList({"a", "b", "c"}, ", ", 1),
                 "a, " + marked("lb::MessageText", "... and %1 more").arg(2));
    }
};

QTEST_MAIN(TestRenderMessages)
#include "test_render_messages.moc"
