// The scene's JSON (what QSettings keeps between runs) and the procedural meshes.
#include "frames.h"
#include "mesh.h"
#include "scene.h"
#include "scene_document.h"

#include <QJsonArray>
#include <QSignalSpy>
#include <QTest>

#include <glm/geometric.hpp>

#include <functional>

using namespace lb;

Q_DECLARE_METATYPE(std::function<void(lb::Scene &)>)

class TestScene : public QObject
{
    Q_OBJECT
private slots:
    void jsonRoundTrip()
    {
        Scene s;
        s.lights[0].position = {1, -2, 3, 0};
        s.lights[0].frame = LightFrame::Object;
        s.lights[0].colors.is = {0.1f, 0.2f, 0.3f};
        s.objects[0].material.shininess = 123;
        s.shading.shading = Shading::Gouraud;
        s.shading.specular = SpecularModel::Phong;
        s.shading.projection = Projection::Orthographic;
        s.objects[0].texture = true;
        s.objects[0].shape = Shape::Torus;
        s.objects[0].tessellation = 40;
        s.objects[0].scale = {2, 1, 0.5f};
        s.camera.orbit(10, 10);
        s.shaderValues["bands"] = {6.0f};
        s.shaderValues["tint"] = {0.1f, 0.2f, 0.3f, 1.0f};
        s.bindings["uWorldToClip"] = Semantic::ModelViewProjection;
        s.bindings["objectColor"] = std::nullopt; // its own value, not Kd
        const Scene back = Scene::fromJson(s.toJson());
        QVERIFY(back == s);
        QVERIFY(back != Scene{});
    }

    // Every field changed at once (each to a value other than its default): the JSON keeps
    // them all, and the field-by-field comparison sees each one.
    void everyFieldRoundTripsAndIsCompared_data()
    {
        QTest::addColumn<int>("part");
        QTest::addColumn<std::function<void(Scene &)>>("change");
        using P = ScenePart;
        auto row = [](const char *name, SceneParts part, std::function<void(Scene &)> change) {
            QTest::newRow(name) << int(part.toInt()) << change;
        };
        row("light position", P::Lights, [](Scene &s) { s.lights[1].position.y = 7; });
        row("light frame", P::Lights, [](Scene &s) { s.lights[2].frame = LightFrame::Camera; });
        row("light colour", P::Lights, [](Scene &s) { s.lights[0].colors.ia.g = 0.5f; });
        row("light on", P::Lights, [](Scene &s) { s.lights[3].enabled = true; });
        row("light marker", P::Lights, [](Scene &s) { s.showLight = false; });
        row("attenuation", P::Lights, [](Scene &s) { s.lights[0].attenuation.z = 0.5f; });
        row("spot axis", P::Lights, [](Scene &s) { s.lights[1].spot.direction.x = 1; });
        row("spot cutoff", P::Lights, [](Scene &s) { s.lights[2].spot.cutoffDegrees = 30; });
        row("spot exponent", P::Lights, [](Scene &s) { s.lights[3].spot.exponent = 8; });
        row("ka", P::Material, [](Scene &s) { s.objects[0].material.ka.b = 0.5f; });
        row("kd", P::Material, [](Scene &s) { s.objects[0].material.kd.g = 0.5f; });
        row("ks", P::Material, [](Scene &s) { s.objects[0].material.ks.r = 0.5f; });
        row("shininess", P::Material, [](Scene &s) { s.objects[0].material.shininess = 7; });
        row("shading", P::Shading, [](Scene &s) { s.shading.shading = Shading::Gouraud; });
        row("specular", P::Shading, [](Scene &s) { s.shading.specular = SpecularModel::Phong; });
        row("projection", P::Shading,
            [](Scene &s) { s.shading.projection = Projection::Orthographic; });
        row("lighting", P::Shading, [](Scene &s) { s.shading.lighting = false; });
        row("ambient term", P::Shading, [](Scene &s) { s.shading.terms.ambient = false; });
        row("diffuse term", P::Shading, [](Scene &s) { s.shading.terms.diffuse = false; });
        row("specular term", P::Shading, [](Scene &s) { s.shading.terms.specular = false; });
        row("show", P::Shading, [](Scene &s) { s.shading.show = ShowChoice::Reflect; });
        row("vertex colours", P::Shading, [](Scene &s) { s.shading.vertexColors = true; });
        row("texture", P::Object, [](Scene &s) { s.objects[0].texture = true; });
        row("texture file", P::Object, [](Scene &s) { s.objects[0].textureFile = "/tmp/a.png"; });
        row("texture wrap", P::Object,
            [](Scene &s) { s.objects[0].sampling.wrap = TextureWrap::Clamp; });
        row("texture filter", P::Object,
            [](Scene &s) { s.objects[0].sampling.filter = TextureFilter::Nearest; });
        row("mipmaps", P::Object, [](Scene &s) { s.objects[0].sampling.mipmaps = true; });
        row("wrong normals", P::Shading, [](Scene &s) { s.shading.normalsByModelView = true; });
        row("shape", P::Object, [](Scene &s) { s.objects[0].shape = Shape::Torus; });
        row("tessellation", P::Object, [](Scene &s) { s.objects[0].tessellation = 33; });
        row("mesh", P::Object, [](Scene &s) { s.objects[0].meshPath = "/tmp/a.obj"; });
        row("normals", P::Object, [](Scene &s) { s.objects[0].normals = NormalMode::Flat; });
        row("crease", P::Object, [](Scene &s) { s.objects[0].creaseDegrees = 44; });
        row("normal lines", P::Object, [](Scene &s) { s.objects[0].showNormals = true; });
        row("back-face culling", P::Object, [](Scene &s) { s.objects[0].cullBackFaces = true; });
        row("file material", P::Object, [](Scene &s) { s.objects[0].adoptFileMaterial = true; });
        row("rotation", P::Object, [](Scene &s) { s.objects[0].rotationDegrees.z = 12; });
        row("scale", P::Object, [](Scene &s) { s.objects[0].scale.y = 0.5f; });
        row("auto-rotate", P::Object, [](Scene &s) { s.objects[0].autoRotate = true; });
        row("name", P::Object, [](Scene &s) { s.objects[0].name = plainText("teapot"); });
        row("visible", P::Object, [](Scene &s) { s.objects[0].visible = false; });
        row("translation", P::Object, [](Scene &s) { s.objects[0].translation.z = -2; });
        row("second object", P::Object | P::Material,
            [](Scene &s) { s.objects.push_back(ObjectSettings{}); });
        row("selected", P::Object | P::Material, [](Scene &s) {
            s.objects.push_back(ObjectSettings{});
            s.selected = 1;
        });
        row("light's object", P::Lights | P::Object | P::Material, [](Scene &s) {
            s.objects.push_back(ObjectSettings{});
            s.lights[2].object = 1;
        });
        row("target", P::Camera, [](Scene &s) { s.camera.target.x = 1; });
        row("distance", P::Camera, [](Scene &s) { s.camera.distance = 9; });
        row("yaw", P::Camera, [](Scene &s) { s.camera.yawDegrees = 3; });
        row("pitch", P::Camera, [](Scene &s) { s.camera.pitchDegrees = 3; });
        row("compare", P::Compare, [](Scene &s) { s.compare.mode = CompareMode::Wipe; });
        row("wipe", P::Compare, [](Scene &s) { s.compare.wipe = 0.25f; });
        row("side B shading", P::Compare, [](Scene &s) { s.compare.shading = Shading::Phong; });
        row("side B specular", P::Compare,
            [](Scene &s) { s.compare.specular = SpecularModel::Phong; });
        row("uniform value", P::Program, [](Scene &s) { s.shaderValues["k"] = {2.0f}; });
        row("binding", P::Bindings, [](Scene &s) { s.bindings["k"] = Semantic::Shininess; });
        row("binding to none", P::Bindings, [](Scene &s) { s.bindings["k"] = std::nullopt; });
    }
    void everyFieldRoundTripsAndIsCompared()
    {
        QFETCH(int, part);
        QFETCH(std::function<void(Scene &)>, change);
        const Scene before;
        Scene after;
        change(after);
        QCOMPARE(int(differingParts(before, after)), part);
        QVERIFY(before != after);
        QVERIFY(Scene::fromJson(after.toJson()) == after);

        SceneDocument document;
        QSignalSpy changed(&document, &SceneDocument::changed);
        document.set(before); // the same scene: nothing changed, nothing said
        QCOMPARE(changed.count(), 0);
        document.set(after);
        QCOMPARE(changed.count(), 1);
        QCOMPARE(int(changed.at(0).at(0).value<SceneParts>()), part);
    }

    void severalLightsRoundTrip()
    {
        Scene s;
        s.lights[2].enabled = true;
        s.lights[2].frame = LightFrame::Camera;
        s.lights[2].colors.id = {0.2f, 0.7f, 0.9f}; // not exact in a float either
        s.lights[3].position = {0, 1, 0, 0};
        s.compare.mode = CompareMode::Wipe;
        s.compare.wipe = 0.3f; // not exact in a float: no "out of range" for that
        s.compare.specular = SpecularModel::Phong;
        QStringList ignored;
        const Scene back = Scene::fromJson(s.toJson(), &ignored);
        QVERIFY(back == s);
        QVERIFY(back.lights[2].enabled);
        QCOMPARE(back.compare.wipe, 0.3f);
        QVERIFY2(ignored.isEmpty(), qPrintable(ignored.join(", ")));
    }

    void versionOneLightIsLightOne()
    {
        // Version 1 (and the settings it left) held one light under "light".
        QJsonObject json;
        json["light"] = QJsonObject{{"position", QJsonArray{1, 2, 3, 0}}, {"frame", "camera"}};
        QStringList ignored;
        const Scene s = Scene::fromJson(json, &ignored);
        QCOMPARE(s.lights[0].position, glm::vec4(1, 2, 3, 0));
        QCOMPARE(s.lights[0].frame, LightFrame::Camera);
        QVERIFY(s.lights[0].enabled);
        QVERIFY(!s.lights[1].enabled);
        QVERIFY2(ignored.isEmpty(), qPrintable(ignored.join(", ")));
    }

    void badFieldsKeepTheirDefaultsAndAreNamed()
    {
        QJsonObject json = Scene{}.toJson();
        QJsonArray lights = json["lights"].toArray();
        QJsonObject light = lights[0].toObject();
        light["position"] = QJsonArray{1, 2, 3, 0.5}; // w must be 0 or 1
        light["frame"] = "sideways";
        light["ia"] = QJsonArray{1, "x", 0};
        light["colour"] = "red";                    // no such field
        light["attenuation"] = QJsonArray{0, 0, 0}; // an infinite light
        light["spot"] = QJsonObject{{"direction", QJsonArray{0, 0, 0}}, {"cutoff", 200}};
        lights[0] = light;
        lights[1] = 12;
        lights.append(QJsonObject{}); // a fifth light
        json["lights"] = lights;
        // Version 2's single object and its material, apart (version 3 files: below).
        json.remove("objects");
        QJsonObject material;
        material["shininess"] = 1e9;
        json["material"] = material;
        QJsonObject object;
        object["tessellation"] = -5;
        object["scale"] = QJsonArray{0, 1, 1};
        json["object"] = object;
        json["camera"] = 7;
        json["future"] = true;
        json["shaderValues"] = QJsonObject{{"five", QJsonArray{1, 2, 3, 4, 5}},
                                           {"word", QJsonArray{"x"}},
                                           {"ok", QJsonArray{2.5}}};
        json["bindings"] = QJsonObject{{"uMine", "model-veiw"},
                                       {"uNumber", 3},
                                       {"uOk", "light-position-world"},
                                       {"uOwn", "none"}};

        QStringList ignored;
        const Scene s = Scene::fromJson(json, &ignored);
        const Scene defaults;
        QCOMPARE(s.lights[0].position, defaults.lights[0].position);
        QCOMPARE(s.lights[0].frame, defaults.lights[0].frame);
        QCOMPARE(s.lights[0].colors.ia, defaults.lights[0].colors.ia);
        QCOMPARE(s.lights[0].attenuation, defaults.lights[0].attenuation);
        QCOMPARE(s.lights[0].spot.direction, defaults.lights[0].spot.direction);
        QCOMPARE(s.lights[0].spot.cutoffDegrees, limits::kMaxSpotCutoff); // clamped
        QCOMPARE(s.objects[0].material.shininess, limits::kMaxShininess);
        QCOMPARE(s.objects[0].tessellation, limits::kMinTessellation);
        QCOMPARE(s.objects[0].scale.x, limits::kMinScale);
        QCOMPARE(s.camera.distance, defaults.camera.distance);
        QCOMPARE(int(s.shaderValues.size()), 1);
        QCOMPARE(s.shaderValues.at("ok"), std::vector<float>{2.5f});
        QVERIFY(s.bindings ==
                (UniformBindings{{"uOk", Semantic::LightPositionWorld}, {"uOwn", std::nullopt}}));
        QVERIFY(Scene::fromJson(QJsonObject{}) == defaults);

        const QString all = ignored.join('\n');
        for (const char *path :
             {"lights[0].position", "lights[0].frame", "lights[0].ia", "lights[0].colour",
              "lights[0].attenuation (kc, kl and kq all 0 (the light would be infinite))",
              "lights[0].spot.direction (a direction of length 0)",
              "lights[0].spot.cutoff (out of range, clamped)", "lights[1] (not an object)",
              "lights[4]", "material.shininess", "object.tessellation", "object.scale",
              "camera (not an object)", "future (unknown field)", "shaderValues.five",
              "shaderValues.word", "bindings.uMine (not one of the values the scene feeds",
              "bindings.uNumber"})
            QVERIFY2(all.contains(QLatin1String(path)), path);
        QCOMPARE(ignored.size(), 18);
    }

    // Version 3's list: bad entries are named and left out, the rest opens.
    void badObjectListsAreNamed()
    {
        QJsonObject json = Scene{}.toJson();
        QJsonArray objects;
        objects.append(7);
        QJsonObject cube;
        cube["shape"] = "cube";
        cube["translation"] = QJsonArray{1, "x", 0};
        cube["material"] = QJsonObject{{"shininess", -4}};
        cube["textureFile"] = 5;
        cube["textureWrap"] = "mirror";
        cube["textureFilter"] = "cubic";
        cube["textureMipmaps"] = "yes";
        objects.append(cube);
        for (int i = 0; i < kMaxObjects + 3; ++i)
            objects.append(QJsonObject{{"shape", "torus"}});
        json["objects"] = objects;
        QJsonArray lights = json["lights"].toArray();
        QJsonObject light = lights[1].toObject();
        light["object"] = 40;
        lights[1] = light;
        json["lights"] = lights;
        json["selected"] = 99;
        QStringList ignored;
        const Scene s = Scene::fromJson(json, &ignored);
        QCOMPARE(int(s.objects.size()), kMaxObjects);
        QCOMPARE(s.objects[0].shape, Shape::Sphere); // in place of the 7: indices stay
        QCOMPARE(s.objects[1].shape, Shape::Cube);
        QCOMPARE(s.objects[1].translation, glm::vec3(0.0f));
        QCOMPARE(s.objects[1].material.shininess, limits::kMinShininess);
        QVERIFY(s.objects[1].textureFile.isEmpty());
        QVERIFY(s.objects[1].sampling == TextureSampling{});
        QCOMPARE(s.objects[2].shape, Shape::Torus);
        QCOMPARE(s.selected, kMaxObjects - 1);
        QCOMPARE(s.lights[1].object, 0); // no object 40: the first one
        const QString all = ignored.join('\n');
        for (const char *path :
             {"objects[0] (not an object; a sphere in its place)",
              "objects[1].translation (not an array of numbers)",
              "objects[1].material.shininess (out of range, clamped)", "objects[1].textureFile",
              "objects[1].textureWrap", "objects[1].textureFilter", "objects[1].textureMipmaps",
              "objects[32] (at most 32 objects", "selected (out of range, clamped)",
              "lights[1].object (no such object; the first one)"})
            QVERIFY2(all.contains(QLatin1String(path)), qPrintable(all));
        QCOMPARE(all.count("lights[1].object"), 1); // one message, not two

        for (const QJsonValue &bad : {QJsonValue(3), QJsonValue(QJsonArray{})}) {
            json = Scene{}.toJson();
            json["objects"] = bad;
            ignored.clear();
            QVERIFY(Scene::fromJson(json, &ignored) == Scene{});
            QCOMPARE(ignored.size(), 1);
            QVERIFY(ignored[0].startsWith("objects ("));
        }
        // A light naming an object the file does not have goes to the first one.
        json = Scene{}.toJson();
        lights = json["lights"].toArray();
        light = lights[0].toObject();
        light["object"] = 3;
        lights[0] = light;
        json["lights"] = lights;
        ignored.clear();
        QCOMPARE(Scene::fromJson(json, &ignored).lights[0].object, 0);
        QVERIFY(ignored.join(' ').contains("lights[0].object (no such object"));
    }

    // Removing an object keeps every light on the object it was attached to (or, for the
    // removed one's, the one before it) and the selection on the same object.
    void objectListEditsKeepAttachments()
    {
        Scene s;
        s.objects[0].name = plainText("a");
        for (const char *name : {"b", "c", "d"}) {
            ObjectSettings o;
            o.name = plainText(name);
            QVERIFY(addObject(s, o));
        }
        QCOMPARE(s.selected, 3);
        s.lights[0].object = 3; // d
        s.lights[1].object = 2; // c, removed below
        s.lights[2].object = 0; // a
        s.selected = 3;
        QVERIFY(removeObject(s, 2));
        QCOMPARE(int(s.objects.size()), 3);
        QCOMPARE(displayName(s.objects[s.lights[0].object]), QString("d"));
        QCOMPARE(displayName(s.objects[s.lights[1].object]), QString("b"));
        QCOMPARE(displayName(s.objects[s.lights[2].object]), QString("a"));
        QCOMPARE(displayName(s.selectedObject()), QString("d"));
        QVERIFY(!removeObject(s, 3));
        QVERIFY(removeObject(s, 0) && removeObject(s, 0));
        QVERIFY(!removeObject(s, 0)); // the last one stays
        while (int(s.objects.size()) < kMaxObjects)
            QVERIFY(addObject(s, ObjectSettings{}));
        QVERIFY(!addObject(s, ObjectSettings{}));
        QCOMPARE(displayName(ObjectSettings{}), QString("sphere"));
        ObjectSettings file;
        file.meshPath = "/x/teapot.obj";
        QCOMPARE(displayName(file), QString("teapot.obj"));
    }

    void framingSeesEveryObject()
    {
        Scene s;
        s.objects.resize(5);
        placeInRow(s.objects);
        QCOMPARE(s.objects[0].translation.x, -5.0f);
        QCOMPARE(s.objects[4].translation.x, 5.0f);
        frameScene(s);
        QCOMPARE(s.camera.target, glm::vec3(0.0f));
        QVERIFY(s.camera.distance > OrbitCamera{}.distance);
        for (const ObjectSettings &o : s.objects) {
            const Frames f = computeFrames(s, 16.0f / 9.0f);
            const glm::vec4 clip = f.projection * f.view * glm::vec4(o.translation, 1.0f);
            QVERIFY(std::abs(clip.x / clip.w) < 1.0f && std::abs(clip.y / clip.w) < 1.0f);
        }
        // Add and Duplicate: the first free place near the centre, never inside another.
        Scene two;
        two.objects.resize(2);
        two.objects[1].translation = {2.5f, 0, 0};
        QCOMPARE(freePlace(two), glm::vec3(-2.5f, 0, 0));
        Scene full;
        while (int(full.objects.size()) < kMaxObjects) {
            const glm::vec3 p = freePlace(full);
            for (const ObjectSettings &o : full.objects)
                QVERIFY(glm::length(o.translation - p) >= 2.0f);
            ObjectSettings o;
            o.translation = p;
            QVERIFY(addObject(full, o));
        }
        frameScene(full); // 32 objects on the grid are all in sight
        for (const ObjectSettings &o : full.objects) {
            const Frames f = computeFrames(full, 16.0f / 9.0f);
            const glm::vec4 clip = f.projection * f.view * glm::vec4(o.translation, 1.0f);
            QVERIFY(std::abs(clip.x / clip.w) < 1.0f && std::abs(clip.y / clip.w) < 1.0f);
        }

        Scene one;
        frameScene(one);
        QVERIFY(one.camera == OrbitCamera{}); // one unit object: the default view
    }

    void namesRoundTrip()
    {
        for (const QString &n : shapeNames())
            QCOMPARE(toName(*parseShape(n)), n);
        for (const QString &n : lightFrameNames())
            QCOMPARE(toName(*parseLightFrame(n)), n);
        QCOMPARE(*parseShading("flat"), Shading::Flat);
        QVERIFY(!parseShading("toon"));
        QCOMPARE(showChoiceNames().size(), int(ShowChoice::Attenuation) + 1);
        for (const QString &n : showChoiceNames())
            QCOMPARE(toName(*parseShowChoice(n)), n);
        QCOMPARE(textureWrapNames(), QStringList({"repeat", "clamp"}));
        QCOMPARE(textureFilterNames(), QStringList({"nearest", "linear"}));
        for (const QString &n : textureWrapNames())
            QCOMPARE(toName(*parseTextureWrap(n)), n);
        for (const QString &n : textureFilterNames())
            QCOMPARE(toName(*parseTextureFilter(n)), n);
    }

    void meshes_data()
    {
        QTest::addColumn<int>("shape");
        for (const QString &n : shapeNames())
            QTest::newRow(qPrintable(n)) << int(*parseShape(n));
    }

    void meshes()
    {
        QFETCH(int, shape);
        const Mesh m = makeShape(Shape(shape), 12);
        QVERIFY(m.triangleCount() > 0);
        QCOMPARE(m.normals.size(), m.positions.size());
        QCOMPARE(m.colors.size(), m.positions.size());
        QCOMPARE(m.uvs.size(), m.positions.size());
        for (std::uint32_t i : m.indices)
            QVERIFY(i < m.vertexCount());
        for (const glm::vec3 &n : m.normals)
            QVERIFY(std::abs(glm::length(n) - 1.0f) < 1e-4f);
    }

    void cubeIsFlatAndSphereIsSmooth()
    {
        const Mesh cube = makeCube();
        for (std::size_t t = 0; t < cube.triangleCount(); ++t) {
            const auto *i = &cube.indices[t * 3];
            const glm::vec3 face =
                glm::normalize(glm::cross(cube.positions[i[1]] - cube.positions[i[0]],
                                          cube.positions[i[2]] - cube.positions[i[0]]));
            for (int k = 0; k < 3; ++k)
                QVERIFY(std::abs(std::abs(glm::dot(face, cube.normals[i[k]])) - 1.0f) < 1e-5f);
        }
        const Mesh sphere = makeSphere(16, 8);
        for (std::size_t v = 0; v < sphere.vertexCount(); ++v)
            QVERIFY(glm::length(sphere.normals[v] - sphere.positions[v]) < 1e-5f);
    }

    void tessellationSetsTheTriangleCount()
    {
        QCOMPARE(makeShape(Shape::Torus, 500).triangleCount(), std::size_t(1000000));
        QCOMPARE(makeShape(Shape::Sphere, 16).triangleCount(), std::size_t(16 * 8 * 2));
    }
};

QTEST_APPLESS_MAIN(TestScene)
#include "test_scene.moc"
