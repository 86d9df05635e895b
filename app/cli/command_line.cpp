#include "command_line.h"

#include "lightbench_version.h"

#include "command_line_grade.h"
#include "command_line_plot.h"
#include "lesson.h"

#include "message_text.h"
#include "safe_write.h"
#include "shader_document.h"

#include <QCommandLineParser>
#include <QFile>
#include <QFileInfo>

#include <glm/geometric.hpp>

#include <cmath>

namespace lb {

namespace {

// Thrown inside the parser only; parseCommandLine() turns it into a CommandLineResult.
struct BadOption
{
    QString message;
};

// What the user typed, as a message repeats it: a pasted megabyte or a pasted line break
// stays one readable line.
QString echoed(const QString &text, int max = 80)
{
    return echoedValue(text, max);
}

[[noreturn]] void fail(const QString &option, const QString &what)
{
    throw BadOption{QString("--%1: %2").arg(option, what)};
}

std::vector<float> numbers(const QString &option, const QString &text, int count, const char *shape)
{
    const QStringList parts = text.split(',');
    if (parts.size() != count)
        fail(option, QString("expected %1, got '%2'").arg(shape, echoed(text)));
    std::vector<float> values;
    for (const QString &part : parts) {
        bool ok = false;
        const double v = part.trimmed().toDouble(&ok);
        if (!ok || !std::isfinite(v))
            fail(option,
                 QString("'%1' is not a finite number (expected %2)").arg(echoed(part), shape));
        values.push_back(float(v));
    }
    return values;
}

void checkRange(const QString &option, float v, float lo, float hi)
{
    if (v < lo || v > hi)
        fail(option, QString("%1 is outside %2 to %3").arg(v).arg(lo).arg(hi));
}

glm::vec3 vec3Option(const QString &option, const QString &text, float lo, float hi)
{
    const auto v = numbers(option, text, 3, "X,Y,Z");
    for (float x : v)
        checkRange(option, x, lo, hi);
    return glm::vec3(v[0], v[1], v[2]);
}

glm::vec3 colourOption(const QString &option, const QString &text)
{
    const auto v = numbers(option, text, 3, "R,G,B");
    for (float x : v)
        checkRange(option, x, 0.0f, 1.0f);
    return glm::vec3(v[0], v[1], v[2]);
}

bool onOff(const QString &option, const QString &text)
{
    const QStringList names = onOffNames(); // "on", "off"
    if (text == names[0])
        return true;
    if (text == names[1])
        return false;
    fail(option, QString("expected on or off, got '%1'").arg(echoed(text)));
}

template <typename E>
E word(const QString &option, const QString &text, std::optional<E> (*parse)(const QString &),
       const QStringList &names)
{
    if (const auto v = parse(text))
        return *v;
    fail(option, QString("unknown value '%1' (expected %2)").arg(echoed(text), names.join('|')));
}

int integer(const QString &option, const QString &text, int lo, int hi)
{
    bool ok = false;
    const int v = text.toInt(&ok);
    if (!ok)
        fail(option, QString("'%1' is not a whole number").arg(echoed(text)));
    if (v < lo || v > hi)
        fail(option, QString("%1 is outside %2 to %3").arg(v).arg(lo).arg(hi));
    return v;
}

QString readShader(const char *option, const QString &path)
{
    const ShaderFileRead read = readShaderFile(path);
    if (!read.ok())
        fail(option, "cannot read " + read.error);
    return read.text;
}

void parseInto(const QCommandLineParser &parser, CommandLine &cl)
{
    auto given = [&](const char *name) { return parser.isSet(QString::fromLatin1(name)); };
    auto value = [&](const char *name) { return parser.value(QString::fromLatin1(name)); };
    auto add = [&](std::function<void(Scene &)> f) { cl.sceneOverrides.push_back(std::move(f)); };

    if (given("size")) {
        const QStringList wh = value("size").split('x');
        if (wh.size() != 2)
            fail("size", QString("expected WxH, got '%1'").arg(echoed(value("size"))));
        cl.size = QSize(integer("size", wh[0], 1, 8192), integer("size", wh[1], 1, 8192));
    }
    // Output files are checked before any work: a device, a FIFO or a folder in their place, a
    // folder that is not there or cannot be written is said now, not after the frame is drawn.
    const auto output = [&](const char *option) {
        const QString path = value(option);
        if (path.isEmpty())
            fail(option, "needs a file name");
        if (const QString why = unwritableTarget(path); !why.isEmpty())
            fail(option, why);
        return path;
    };
    if (given("render"))
        cl.renderPath = output("render");
    if (given("probe")) {
        const QStringList xy = value("probe").split(',');
        if (xy.size() != 2)
            fail("probe", QString("expected X,Y, got '%1'").arg(echoed(value("probe"))));
        cl.probe = QPoint(integer("probe", xy[0], 0, cl.size.width() - 1),
                          integer("probe", xy[1], 0, cl.size.height() - 1));
    }
    if (given("screenshot"))
        cl.screenshotPath = output("screenshot");
    if (given("bench-frames"))
        cl.benchFrames = integer("bench-frames", value("bench-frames"), 1, 100000);
    if (given("bench-edits"))
        cl.benchEdits = integer("bench-edits", value("bench-edits"), 1, 10000);
    if (given("vertex") != given("fragment"))
        fail(given("vertex") ? "vertex" : "fragment", "--vertex and --fragment go together");
    if (given("vertex")) {
        cl.vertexPath = value("vertex");
        cl.fragmentPath = value("fragment");
        cl.vertexSource = readShader("vertex", cl.vertexPath);
        cl.fragmentSource = readShader("fragment", cl.fragmentPath);
    }
    if (given("scene") && given("lesson"))
        fail("lesson", "--lesson and --scene do not go together: the lesson's step is the scene");
    if (given("step") && !given("lesson"))
        fail("step", "--step goes with --lesson");
    if (given("scene")) {
        cl.scenePath = value("scene");
        SceneFileRead read = readSceneFile(cl.scenePath);
        if (!read.file)
            fail("scene", read.error);
        cl.sceneFile = std::move(read.file);
        cl.sceneIgnored = read.ignored;
    } else if (given("lesson")) {
        cl.lessonPath = value("lesson");
        const LessonRead read = readLessonFile(cl.lessonPath);
        if (!read.lesson)
            fail("lesson", read.error);
        const int steps = int(read.lesson->steps.size());
        cl.lessonStep = given("step") ? integer("step", value("step"), 1, steps) : 1;
        const LessonStep &step = read.lesson->steps[std::size_t(cl.lessonStep - 1)];
        if (!step.error.isEmpty())
            fail("step", QString("%1: %2").arg(echoed(cl.lessonPath), step.error));
        cl.scenePath = QString("%1 (step %2)").arg(cl.lessonPath).arg(cl.lessonStep);
        cl.sceneFile = step.scene;
        // What the lesson and this step ignored; the other steps' notes are theirs.
        const QString here = QString("step %1: ").arg(cl.lessonStep);
        for (const QString &note : read.ignored)
            if (note.startsWith(here) || !note.startsWith("step "))
                cl.sceneIgnored << note;
    }
    if (cl.sceneFile) {
        if (!given("vertex") && cl.sceneFile->program) {
            cl.programFromScene = true;
            cl.vertexPath = cl.scenePath + " (vertex)";
            cl.fragmentPath = cl.scenePath + " (fragment)";
            cl.vertexSource = cl.sceneFile->program->vertex;
            cl.fragmentSource = cl.sceneFile->program->fragment;
        }
    }
    if (given("save-scene"))
        cl.saveScenePath = output("save-scene");
    if (given("frame-budget")) {
        const float v = numbers("frame-budget", value("frame-budget"), 1, "seconds")[0];
        checkRange("frame-budget", v, 0.01f, 60.0f);
        cl.frameBudgetSeconds = double(v);
    }
    cl.presentation = given("presentation");
    cl.translateWebGl1 = given("translate-webgl1");
    if (given("ui-scale"))
        cl.uiScalePercent = integer("ui-scale", value("ui-scale"), 100, 250);
    if (given("language")) {
        const QString language = value("language");
        const QStringList languages = commandLineLanguages(); // "system" first
        if (!languages.contains(language))
            fail("language",
                 QString("expected %1, got '%2'").arg(languages.join('|'), echoed(language)));
        cl.language = language == languages[0] ? QString() : language;
    }
    cl.check = given("check");
    if (const QString error = parseGradeOptions(parser, cl); !error.isEmpty())
        throw BadOption{error};
    if (const QString error = parsePlotOptions(parser, cl); !error.isEmpty())
        throw BadOption{error};
    if (cl.check && !cl.hasUserProgram())
        fail("check", "needs --vertex FILE and --fragment FILE");

    if (given("import-memory-limit"))
        cl.importMemoryMB =
            integer("import-memory-limit", value("import-memory-limit"), 16, 1 << 30);
    if (given("import-time-limit"))
        cl.importSeconds = integer("import-time-limit", value("import-time-limit"), 1, 86400);
    if (given("object")) {
        // First, so that the other object options apply to the last object named.
        std::vector<ObjectSettings> objects;
        for (const QString &named : parser.values("object")) {
            ObjectSettings o;
            if (const std::optional<Shape> shape = parseShape(named))
                o.shape = *shape;
            else if (named.isEmpty())
                fail("object", "needs a shape (" + shapeNames().join(", ") + ") or a file name");
            else
                o.meshPath = QFileInfo(named).absoluteFilePath();
            objects.push_back(o);
        }
        if (int(objects.size()) > kMaxObjects)
            fail("object", QString("at most %1 objects").arg(kMaxObjects));
        const bool replace = !given("scene");
        add([objects, replace](Scene &s) {
            std::vector<ObjectSettings> placed = objects;
            placeInRow(placed);
            if (replace) {
                s.objects.clear();
                for (Light &light : s.lights)
                    light.object = 0;
            }
            for (const ObjectSettings &o : placed)
                if (int(s.objects.size()) < kMaxObjects)
                    s.objects.push_back(o);
            s.selected = int(s.objects.size()) - 1;
            frameScene(s);
        });
    }
    if (given("mesh")) {
        if (value("mesh").isEmpty())
            fail("mesh", "needs a file name");
        const QString path = QFileInfo(value("mesh")).absoluteFilePath();
        add([path](Scene &s) { s.selectedObject().meshPath = path; });
    }
    if (given("normals")) {
        const NormalMode v = word("normals", value("normals"), parseNormalMode, normalModeNames());
        add([v](Scene &s) { s.selectedObject().normals = v; });
    }
    if (given("crease-angle")) {
        const float v = numbers("crease-angle", value("crease-angle"), 1, "a number")[0];
        checkRange("crease-angle", v, 0.0f, limits::kMaxCreaseDegrees);
        add([v](Scene &s) { s.selectedObject().creaseDegrees = v; });
    }
    if (given("shape")) {
        if (given("mesh"))
            fail("shape", "a shape or a --mesh file, not both");
        const Shape v = word("shape", value("shape"), parseShape, shapeNames());
        add([v](Scene &s) {
            s.selectedObject().shape = v;
            s.selectedObject().meshPath.clear(); // also when the saved session showed a file
        });
    }
    if (given("tessellation")) {
        const int v = integer("tessellation", value("tessellation"), limits::kMinTessellation,
                              limits::kMaxTessellation);
        add([v](Scene &s) { s.selectedObject().tessellation = v; });
    }
    if (given("shading")) {
        const Shading v = word("shading", value("shading"), parseShading, shadingNames());
        add([v](Scene &s) { s.shading.shading = v; });
    }
    if (given("specular")) {
        const SpecularModel v =
            word("specular", value("specular"), parseSpecularModel, specularModelNames());
        add([v](Scene &s) { s.shading.specular = v; });
    }
    if (given("frame")) {
        const LightFrame v = word("frame", value("frame"), parseLightFrame, lightFrameNames());
        add([v](Scene &s) { s.lights[0].frame = v; });
    }
    if (given("light")) {
        const auto v = numbers("light", value("light"), 4, "X,Y,Z,W");
        for (int i = 0; i < 3; ++i)
            checkRange("light", v[std::size_t(i)], -limits::kMaxCoordinate, limits::kMaxCoordinate);
        if (v[3] != 0.0f && v[3] != 1.0f)
            fail("light", QString("W must be 0 (directional) or 1 (point), got %1").arg(v[3]));
        if (v[3] == 0.0f && v[0] == 0.0f && v[1] == 0.0f && v[2] == 0.0f)
            fail("light", "a directional light (W = 0) needs a non-zero direction");
        const glm::vec4 p(v[0], v[1], v[2], v[3]);
        add([p](Scene &s) { s.lights[0].position = p; });
    }
    if (given("attenuation")) {
        const auto v = numbers("attenuation", value("attenuation"), 3, "KC,KL,KQ");
        for (float x : v)
            checkRange("attenuation", x, 0.0f, limits::kMaxAttenuation);
        const glm::vec3 k(v[0], v[1], v[2]);
        if (k == glm::vec3(0.0f))
            fail("attenuation", "KC, KL and KQ cannot all be 0 (the light would be infinite)");
        add([k](Scene &s) { s.lights[0].attenuation = k; });
    }
    if (given("spot")) {
        const auto v = numbers("spot", value("spot"), 5, "DX,DY,DZ,CUTOFF,EXPONENT");
        for (int i = 0; i < 3; ++i)
            checkRange("spot", v[std::size_t(i)], -limits::kMaxCoordinate, limits::kMaxCoordinate);
        if (glm::length(glm::vec3(v[0], v[1], v[2])) < limits::kMinDirectionLength)
            fail("spot", "the direction DX,DY,DZ cannot be 0,0,0 (or nearly)");
        if (v[3] < 0.0f || v[3] > limits::kMaxSpotCutoff)
            fail("spot", QString("the cutoff %1 is outside 0 to 180 degrees").arg(v[3]));
        if (v[4] < 0.0f || v[4] > limits::kMaxSpotExponent)
            fail("spot", QString("the exponent %1 is outside 0 to 128").arg(v[4]));
        const Spot spot{{v[0], v[1], v[2]}, v[3], v[4]};
        add([spot](Scene &s) { s.lights[0].spot = spot; });
    }
    if (given("show")) {
        const ShowChoice v = word("show", value("show"), parseShowChoice, showChoiceNames());
        add([v](Scene &s) { s.shading.show = v; });
    }
    if (given("terms")) {
        TermSwitches terms{false, false, false};
        const QString text = value("terms");
        for (const QString &word : text == "none" ? QStringList() : text.split(',')) {
            if (word == "ambient")
                terms.ambient = true;
            else if (word == "diffuse")
                terms.diffuse = true;
            else if (word == "specular")
                terms.specular = true;
            else
                fail("terms", QString("unknown term '%1' (expected ambient, diffuse or specular, "
                                      "separated by commas, or none)")
                                  .arg(echoed(word)));
        }
        add([terms](Scene &s) { s.shading.terms = terms; });
    }
    const std::pair<const char *, glm::vec3 LightColors::*> lightColours[] = {
        {"ia", &LightColors::ia}, {"id", &LightColors::id}, {"is", &LightColors::is}};
    for (const auto &[name, member] : lightColours) {
        if (given(name)) {
            const glm::vec3 c = colourOption(name, value(name));
            add([c, member = member](Scene &s) { s.lights[0].colors.*member = c; });
        }
    }
    const std::pair<const char *, glm::vec3 Material::*> materialColours[] = {
        {"ka", &Material::ka}, {"kd", &Material::kd}, {"ks", &Material::ks}};
    for (const auto &[name, member] : materialColours) {
        if (given(name)) {
            const glm::vec3 c = colourOption(name, value(name));
            add([c, member = member](Scene &s) { s.selectedObject().material.*member = c; });
        }
    }
    if (given("shininess")) {
        const float v = numbers("shininess", value("shininess"), 1, "a number")[0];
        checkRange("shininess", v, limits::kMinShininess, limits::kMaxShininess);
        add([v](Scene &s) { s.selectedObject().material.shininess = v; });
    }
    if (given("projection")) {
        const Projection v =
            word("projection", value("projection"), parseProjection, projectionNames());
        add([v](Scene &s) { s.shading.projection = v; });
    }
    if (given("camera-orbit")) {
        const auto v = numbers("camera-orbit", value("camera-orbit"), 2, "YAW,PITCH");
        checkRange("camera-orbit", v[0], -3600.0f, 3600.0f);
        checkRange("camera-orbit", v[1], -89.0f, 89.0f);
        add([v](Scene &s) {
            s.camera.yawDegrees = 0.0f;
            s.camera.pitchDegrees = 0.0f;
            s.camera.orbit(v[0], v[1]);
        });
    }
    if (given("model-rotate")) {
        const glm::vec3 r = vec3Option("model-rotate", value("model-rotate"), -3600.0f, 3600.0f);
        add([r](Scene &s) { s.selectedObject().rotationDegrees = r; });
    }
    if (given("model-scale")) {
        const glm::vec3 sc =
            vec3Option("model-scale", value("model-scale"), limits::kMinScale, limits::kMaxScale);
        add([sc](Scene &s) { s.selectedObject().scale = sc; });
    }
    if (given("model-translate")) {
        const float c = limits::kMaxCoordinate;
        const glm::vec3 t = vec3Option("model-translate", value("model-translate"), -c, c);
        add([t](Scene &s) { s.selectedObject().translation = t; });
    }
    if (given("light-object")) {
        // Checked against the objects where the command line knows them all.
        int known = kMaxObjects;
        if (given("object"))
            known = int(parser.values("object").size()) +
                    (cl.sceneFile ? int(cl.sceneFile->scene.objects.size()) : 0);
        else if (cl.sceneFile)
            known = int(cl.sceneFile->scene.objects.size());
        const int v = integer("light-object", value("light-object"), 0, known - 1);
        add([v](Scene &s) { s.lights[0].object = std::min(v, int(s.objects.size()) - 1); });
    }
    const std::pair<const char *, bool ShadingSettings::*> switches[] = {
        {"lighting", &ShadingSettings::lighting},
        {"vertex-colors", &ShadingSettings::vertexColors}};
    for (const auto &[name, member] : switches) {
        if (given(name)) {
            const bool on = onOff(name, value(name));
            add([on, member = member](Scene &s) { s.shading.*member = on; });
        }
    }
    if (given("texture-file")) {
        if (value("texture-file").isEmpty())
            fail("texture-file", "needs a file name");
        const QString path = QFileInfo(value("texture-file")).absoluteFilePath();
        add([path](Scene &s) {
            s.selectedObject().textureFile = path;
            s.selectedObject().texture = true;
        });
    }
    if (given("texture-wrap")) {
        const TextureWrap v =
            word("texture-wrap", value("texture-wrap"), parseTextureWrap, textureWrapNames());
        add([v](Scene &s) { s.selectedObject().sampling.wrap = v; });
    }
    if (given("texture-filter")) {
        const TextureFilter v = word("texture-filter", value("texture-filter"), parseTextureFilter,
                                     textureFilterNames());
        add([v](Scene &s) { s.selectedObject().sampling.filter = v; });
    }
    if (given("texture-mipmaps")) {
        const bool on = onOff("texture-mipmaps", value("texture-mipmaps"));
        add([on](Scene &s) { s.selectedObject().sampling.mipmaps = on; });
    }
    const std::pair<const char *, bool ObjectSettings::*> objectSwitches[] = {
        {"show-normals", &ObjectSettings::showNormals},
        {"cull-back-faces", &ObjectSettings::cullBackFaces},
        {"file-material", &ObjectSettings::adoptFileMaterial},
        {"texture", &ObjectSettings::texture}};
    for (const auto &[name, member] : objectSwitches) {
        if (given(name)) {
            const bool on = onOff(name, value(name));
            add([on, member = member](Scene &s) { s.selectedObject().*member = on; });
        }
    }
    if (given("show-light")) {
        const bool on = onOff("show-light", value("show-light"));
        add([on](Scene &s) { s.showLight = on; });
    }
}

} // namespace

ImportLimits CommandLine::importLimits() const
{
    ImportLimits limits;
    if (importMemoryMB)
        limits.memoryMB = *importMemoryMB;
    if (importSeconds)
        limits.seconds = *importSeconds;
    return limits;
}

void CommandLine::applyTo(Scene &scene) const
{
    for (const auto &f : sceneOverrides)
        f(scene);
}

Scene CommandLine::headlessScene() const
{
    Scene scene = sceneFile ? sceneFile->scene : Scene{};
    applyTo(scene);
    return scene;
}

std::optional<ProgramText> CommandLine::program() const
{
    if (programFromScene)
        return sceneFile->program;
    if (hasUserProgram())
        return ProgramText{QFileInfo(vertexPath).completeBaseName(), vertexSource, fragmentSource};
    return std::nullopt;
}

CommandLineResult parseCommandLine(const QStringList &arguments)
{
    QCommandLineParser parser;
    // The batch's child process: one submission (grade.h); not for people.
    QCommandLineOption gradeOne("grade-one", "One submission of --grade.", "SUBMISSION");
    gradeOne.setFlags(QCommandLineOption::HiddenFromHelp);
    parser.addOption(gradeOne);
    QCommandLineOption gradeName("grade-name", "Its name in the report.", "NAME");
    gradeName.setFlags(QCommandLineOption::HiddenFromHelp);
    parser.addOption(gradeName);
    parser.setApplicationDescription(
        "lightbench: a lighting workbench for the Phong and Blinn-Phong models.\n"
        "Without --render, --probe or --bench-frames it opens the window.");
    for (const OptionInfo &o : visibleOptions())
        parser.addOption(QCommandLineOption(o.names, o.description, o.valueName));
    parser.addPositionalArgument("FILE", fileArgumentsHelp(), "[FILE...]");

    CommandLineResult result;
    if (!parser.parse(arguments)) {
        result.exitCode = 2;
        result.message = echoed(parser.errorText(), 200) + " (see --help)";
        return result;
    }
    if (parser.isSet("help")) {
        // Parsed before QCoreApplication exists, which is where Qt would take the name from.
        result.message = parser.helpText().replace("<executable_name>", "lightbench");
        return result;
    }
    if (parser.isSet("version")) {
        result.message = QStringLiteral("lightbench " LIGHTBENCH_VERSION "\n");
        return result;
    }
    try {
        CommandLine cl;
        parseInto(parser, cl);
        const QStringList files = parser.positionalArguments();
        if (!files.isEmpty() && !cl.grade) {
            // Files open in the window (the desktop's `lightbench %F`); a headless run draws
            // --scene's or --lesson's scene, and one file opens there, not two.
            if (cl.headless())
                throw BadOption{
                    QString("unexpected argument '%1' (see --help)").arg(echoed(files.first()))};
            if (!cl.scenePath.isEmpty())
                fail(cl.lessonPath.isEmpty() ? "scene" : "lesson",
                     QString("opens one file in the window; '%1' is another (give one of them)")
                         .arg(echoed(files.first())));
            for (const QString &file : files)
                cl.filePaths << (file.isEmpty() ? file : QFileInfo(file).absoluteFilePath());
        }
        result.commandLine = std::move(cl);
    } catch (const BadOption &bad) {
        result.exitCode = 2;
        result.message = bad.message;
    }
    return result;
}

} // namespace lb
