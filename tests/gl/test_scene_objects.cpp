// Scenes of several objects, each with its own transform, material and texture, lit by lights
// in the camera, world and object frames (object-frame lights attached to different objects),
// drawn by the built-in shaders and checked pixel by pixel against the CPU reference; and an
// object-frame light that turns with its own object and no other.
#include "import_process.h"
#include "reference_compare.h"

#include <QGuiApplication>
#include <QTest>

#include <glm/geometric.hpp>

using namespace lb;
using namespace lb::test;

namespace {

const QString kMeshFile = "/usr/share/assimp/models/glTF2/BoxTextured-glTF/BoxTextured.gltf";
const QSize kWide(480, 240); // three objects side by side

// Where an object's centre lands in a frame of `size`.
QPoint centreOf(const Scene &scene, int object, QSize size)
{
    const Frames f = computeFrames(scene, float(size.width()) / float(size.height()), object);
    const glm::vec2 p =
        pixelOf(f, glm::vec3(f.modelView[3]), float(size.width()), float(size.height()));
    return QPoint(int(p.x), int(p.y));
}

} // namespace

class TestSceneObjects : public QObject
{
    Q_OBJECT
private:
    OffscreenRenderer m_offscreen;
    QString m_meshPath;

    // A cube (the checker on it), a sphere and a mesh file (its own texture), each with its
    // own material and transform; light 1 in the camera frame, 2 in the world, 3 in the
    // cube's frame and 4 in the mesh file's.
    Scene threeObjects()
    {
        Scene s = testScene();
        ObjectSettings cube;
        cube.shape = Shape::Cube;
        cube.texture = true;
        cube.rotationDegrees = {15, 35, 0};
        cube.scale = glm::vec3(0.8f);
        cube.material.kd = cube.material.ka = {0.9f, 0.6f, 0.2f};
        ObjectSettings sphere;
        sphere.tessellation = 24;
        sphere.scale = {1.0f, 0.8f, 1.2f}; // non-uniform: the normal matrix matters
        sphere.material.kd = {0.2f, 0.4f, 0.9f};
        sphere.material.shininess = 30;
        ObjectSettings file;
        file.meshPath = m_meshPath;
        file.texture = true;
        file.rotationDegrees = {-20, 40, 10};
        file.scale = glm::vec3(0.8f);
        file.material.shininess = 12;
        s.objects = {cube, sphere, file};
        placeInRow(s.objects);
        s.objects[1].translation.y = 0.3f;
        frameScene(s);
        for (Light &l : s.lights)
            l.enabled = true;
        s.lights[0].frame = LightFrame::Camera;
        s.lights[0].position = {-1.0f, 2.0f, 3.0f, 1.0f};
        s.lights[1].frame = LightFrame::World;
        s.lights[1].position = {0.5f, 1.0f, 0.8f, 0.0f};
        s.lights[2].frame = LightFrame::Object;
        s.lights[2].object = 0;
        s.lights[2].position = {0.0f, 1.5f, 2.0f, 1.0f};
        s.lights[3].frame = LightFrame::Object;
        s.lights[3].object = 2;
        s.lights[3].position = {1.0f, 0.0f, 1.0f, 0.0f};
        s.lights[3].colors.id = {0.5f, 0.5f, 0.3f};
        return s;
    }

private slots:
    void initTestCase()
    {
        QVERIFY2(m_offscreen.initialize(kWide).isEmpty(), "no OpenGL");
        const ImportResult r = ImportProcess::import(kMeshFile);
        QVERIFY2(r.ok(), qPrintable(r.error));
        m_offscreen.addMeshFile(r.file);
        m_meshPath = r.file->path;
    }

    void threeObjectsMatchTheReference_data()
    {
        QTest::addColumn<int>("shading");
        QTest::addColumn<int>("specular");
        QTest::addColumn<int>("projection");
        QTest::addColumn<bool>("attenuated");
        for (int sh = 0; sh < 3; ++sh)
            for (int sp = 0; sp < 2; ++sp)
                for (int pr = 0; pr < 2; ++pr)
                    QTest::newRow(
                        qPrintable(QString("%1 %2 %3")
                                       .arg(toName(Shading(sh)), toName(SpecularModel(sp)),
                                            toName(Projection(pr)))))
                        << sh << sp << pr << false;
        QTest::newRow("phong, attenuated spot in the cube's frame") << 1 << 1 << 0 << true;
        QTest::newRow("gouraud, attenuated spot in the cube's frame") << 0 << 0 << 0 << true;
    }

    void threeObjectsMatchTheReference()
    {
        QFETCH(int, shading);
        QFETCH(int, specular);
        QFETCH(int, projection);
        QFETCH(bool, attenuated);
        Scene s = threeObjects();
        s.shading.shading = Shading(shading);
        s.shading.specular = SpecularModel(specular);
        s.shading.projection = Projection(projection);
        if (attenuated) {
            s.lights[2].attenuation = {1.0f, 0.1f, 0.05f};
            s.lights[2].spot = {glm::vec3(0.0f, -1.0f, -1.0f), 40.0f, 4.0f};
        }
        const QImage frame = m_offscreen.render(s);
        const Comparison c = compareWithReference(m_offscreen, s, frame, 3);
        const QString name = QTest::currentDataTag();
        if (qEnvironmentVariableIsSet("LB_SAVE_FRAMES"))
            saveForInspection(frame, "objects " + name);
        qInfo("%s: %d pixels compared (%d with a highlight), worst %d/255", qPrintable(name),
              c.compared, c.withSpecular, c.worst);
        QVERIFY2(c.worst <= kTolerance,
                 qPrintable(QString("(%1, %2) off by %3: %4; frame in %5")
                                .arg(c.worstAt.x())
                                .arg(c.worstAt.y())
                                .arg(c.worst)
                                .arg(c.worstText, saveForInspection(frame, name))));
        QVERIFY2(c.compared >= ofThisGrid(300), qPrintable(QString::number(c.compared)));
        // Every object is drawn where the probe finds it, with its own colour.
        const ProbedObjects objects = m_offscreen.probedObjects(s);
        for (int i = 0; i < 3; ++i) {
            const QPoint centre = centreOf(s, i, kWide);
            const ProbeResult p = probePixel(s, objects, kWide, centre);
            QVERIFY2(p.hit && p.object == i,
                     qPrintable(QString("object %1 not at its centre").arg(i)));
            QVERIFY(channelDifference(frame.pixel(centre), p.reference) <= kTolerance);
        }
    }

    void hiddenObjectsAreNeitherDrawnNorProbed()
    {
        Scene s = threeObjects();
        const QPoint centre = centreOf(s, 1, kWide);
        const QRgb background = m_offscreen.render(s).pixel(0, 0);
        QVERIFY(m_offscreen.render(s).pixel(centre) != background);
        s.objects[1].visible = false;
        QCOMPARE(m_offscreen.render(s).pixel(centre), background);
        QVERIFY(!probePixel(s, m_offscreen.probedObjects(s), kWide, centre).hit);
    }

    // Light 1 belongs to the left object, light 2 to the right one; a point on the right
    // object is probed while the left one turns: light 1's L there turns, light 2's does not.
    void anObjectFrameLightTurnsWithItsOwnObject()
    {
        Scene s = testScene();
        s.objects = {ObjectSettings{}, ObjectSettings{}};
        placeInRow(s.objects);
        frameScene(s);
        for (int i = 0; i < 2; ++i) {
            Light &l = s.lights[std::size_t(i)];
            l.enabled = true;
            l.frame = LightFrame::Object;
            l.object = i;
            l.position = {0.0f, 1.0f, 2.0f, 1.0f};
        }
        const QPoint point = centreOf(s, 1, kWide);
        const auto lOf = [&](const Scene &scene, int light) {
            const ProbeResult p = probePixel(scene, m_offscreen.probedObjects(scene), kWide, point);
            if (!p.hit || p.object != 1 || int(p.lights.size()) != 2)
                qFatal("the right object is not at its centre");
            return p.lights[std::size_t(light)].terms.L;
        };
        const glm::vec3 before1 = lOf(s, 0), before2 = lOf(s, 1);
        Scene turned = s;
        turned.objects[0].rotationDegrees.y = 90.0f;
        const glm::vec3 after1 = lOf(turned, 0), after2 = lOf(turned, 1);
        QVERIFY2(glm::dot(before1, after1) < 0.99f, "light 1 stayed where it was");
        QVERIFY(glm::length(before2 - after2) < 1e-5f);
        // And the pixels agree with the reference in both.
        for (const Scene *scene : {&s, &turned}) {
            const QImage frame = m_offscreen.render(*scene);
            const Comparison c = compareWithReference(m_offscreen, *scene, frame, 3);
            QVERIFY2(c.worst <= kTolerance, qPrintable(c.worstText));
            QVERIFY(c.compared >= ofThisGrid(300));
        }
    }
};

QTEST_MAIN(TestSceneObjects)
#include "test_scene_objects.moc"
