// The command line's options that change the scene (--object, --mesh, --light, --material,
// --shading, ...): each becomes an override applied on top of the scene file, the saved
// session or the defaults (CommandLine::applyTo).
#include "command_line_scene.h"

#include "option_values.h"

#include <QFileInfo>

#include <glm/geometric.hpp>

#include <cmath>

namespace lb {

using namespace options;

void parseSceneOptions(const QCommandLineParser &parser, CommandLine &cl)
{
    auto given = [&](const char *name) { return parser.isSet(QString::fromLatin1(name)); };
    auto value = [&](const char *name) { return parser.value(QString::fromLatin1(name)); };
    auto add = [&](std::function<void(Scene &)> f) { cl.sceneOverrides.push_back(std::move(f)); };
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
    if (given("faces")) {
        const Faces v = word("faces", value("faces"), parseFaces, facesNames());
        add([v](Scene &s) { s.selectedObject().faces = v; });
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
    // Light 1's and the selected object's numbers, each row of the lighting model's table
    // that has an option (lighting_parameters.h): its count, range and refusal.
    for (const LightingParameter &p : lightingParameters()) {
        if (!p.option || !given(p.option))
            continue;
        const std::vector<float> v = parameterOption(p, p.option, value(p.option));
        add([v, row = &p](Scene &s) {
            float *to = row->owner == ParameterOwner::Light
                            ? row->numbers(s.lights[0])
                            : row->numbers(s.selectedObject().material);
            std::copy(v.begin(), v.end(), to);
        });
    }
    if (given("spot")) {
        // The spot's three rows in one option: DX,DY,DZ then the cutoff and the exponent.
        const auto v = numbers("spot", value("spot"), 5, "DX,DY,DZ,CUTOFF,EXPONENT");
        Light light;
        std::size_t at = 0;
        for (const char *key : {"spot.direction", "spot.cutoff", "spot.exponent"}) {
            const LightingParameter &p = *lightingParameter(ParameterOwner::Light, key);
            std::vector<float> part(v.begin() + long(at), v.begin() + long(at) + p.count);
            checkParameter(p, "spot", part);
            std::copy(part.begin(), part.end(), p.numbers(light));
            at += std::size_t(p.count);
        }
        add([spot = light.spot](Scene &s) { s.lights[0].spot = spot; });
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
    if (given("bind")) {
        UniformBindings bindings;
        for (const QString &pair : parser.values("bind")) {
            const QString name = pair.section('=', 0, 0).trimmed();
            const QString key = pair.section('=', 1).trimmed();
            if (name.isEmpty() || !pair.contains('='))
                fail("bind",
                     QString("needs NAME=KEY, a uniform's name and what feeds it, not \"%1\"")
                         .arg(echoed(pair)));
            if (name.size() > limits::kMaxShaderValueName)
                fail("bind", QString("a uniform's name is at most %1 characters")
                                 .arg(limits::kMaxShaderValueName));
            bool unbound = false;
            const std::optional<Semantic> semantic = semanticFromKey(key, &unbound);
            if (!semantic && !unbound)
                fail("bind",
                     QString("\"%1\" is not what the scene gives; KEY is one of: %2")
                         .arg(echoed(key), QStringList(semanticKeys() << kUnboundKey).join(", ")));
            bindings[name] = semantic;
        }
        if (int(bindings.size()) > limits::kMaxBindings)
            fail("bind", QString("at most %1 bindings").arg(limits::kMaxBindings));
        add([bindings](Scene &s) {
            for (const auto &[name, semantic] : bindings)
                s.bindings[name] = semantic;
        });
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

} // namespace lb
