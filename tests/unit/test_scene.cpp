// The scene's JSON (what QSettings keeps between runs) and the procedural meshes.
#include "mesh.h"
#include "scene.h"

#include <QJsonArray>
#include <QTest>

#include <glm/geometric.hpp>

using namespace lb;

class TestScene : public QObject
{
    Q_OBJECT
private slots:
    void jsonRoundTrip()
    {
        Scene s;
        s.light.position = {1, -2, 3, 0};
        s.light.frame = LightFrame::Object;
        s.light.colors.is = {0.1f, 0.2f, 0.3f};
        s.material.shininess = 123;
        s.shading.shading = Shading::Gouraud;
        s.shading.specular = SpecularModel::Phong;
        s.shading.projection = Projection::Orthographic;
        s.shading.texture = true;
        s.object.shape = Shape::Torus;
        s.object.tessellation = 40;
        s.object.scale = {2, 1, 0.5f};
        s.camera.orbit(10, 10);
        s.shaderValues["bands"] = {6.0f};
        s.shaderValues["tint"] = {0.1f, 0.2f, 0.3f, 1.0f};
        const Scene back = Scene::fromJson(s.toJson());
        QVERIFY(back == s);
        QVERIFY(back != Scene{});
    }

    void badFieldsKeepTheirDefaults()
    {
        QJsonObject json = Scene{}.toJson();
        QJsonObject light = json["light"].toObject();
        light["position"] = QJsonArray{1, 2, 3, 0.5}; // w must be 0 or 1
        light["frame"] = "sideways";
        light["ia"] = QJsonArray{1, "x", 0};
        json["light"] = light;
        QJsonObject material = json["material"].toObject();
        material["shininess"] = 1e9;
        json["material"] = material;
        QJsonObject object = json["object"].toObject();
        object["tessellation"] = -5;
        object["scale"] = QJsonArray{0, 1, 1};
        json["object"] = object;
        json["camera"] = 7;
        json["shaderValues"] = QJsonObject{{"five", QJsonArray{1, 2, 3, 4, 5}},
                                           {"word", QJsonArray{"x"}},
                                           {"ok", QJsonArray{2.5}}};

        const Scene s = Scene::fromJson(json);
        const Scene defaults;
        QCOMPARE(s.light.position.w, 1.0f);
        QCOMPARE(s.light.frame, defaults.light.frame);
        QCOMPARE(s.light.colors.ia, defaults.light.colors.ia);
        QCOMPARE(s.material.shininess, limits::kMaxShininess);
        QCOMPARE(s.object.tessellation, limits::kMinTessellation);
        QCOMPARE(s.object.scale.x, limits::kMinScale);
        QCOMPARE(s.camera.distance, defaults.camera.distance);
        QCOMPARE(int(s.shaderValues.size()), 1);
        QCOMPARE(s.shaderValues.at("ok"), std::vector<float>{2.5f});
        QVERIFY(Scene::fromJson(QJsonObject{}) == defaults);
    }

    void namesRoundTrip()
    {
        for (const QString &n : shapeNames())
            QCOMPARE(toName(*parseShape(n)), n);
        for (const QString &n : lightFrameNames())
            QCOMPARE(toName(*parseLightFrame(n)), n);
        QVERIFY(!parseShading("flat"));
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
