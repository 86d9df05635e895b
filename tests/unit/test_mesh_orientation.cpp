// Which way a mesh's faces look (issue 48): closed parts wound inwards are turned, winding
// and normals, part by part; open sheets are left alone; flipped and two-sided meshes; and
// what buildObjectMesh makes of a mesh file for each Faces choice, with its remark. The
// meshes are our own: the shapes, wound the wrong way on purpose.
#include "mesh.h"
#include "mesh_file.h"
#include "mesh_orientation.h"
#include "object_mesh.h"

#include <QTest>

#include <glm/geometric.hpp>

using namespace lb;

namespace {

// Six times the signed volume the mesh's triangles enclose (about the origin).
double signedVolume(const Mesh &m)
{
    double v = 0.0;
    for (std::size_t t = 0; t < m.triangleCount(); ++t) {
        const glm::dvec3 a = m.positions[m.indices[3 * t]], b = m.positions[m.indices[3 * t + 1]],
                         c = m.positions[m.indices[3 * t + 2]];
        v += glm::dot(a, glm::cross(b, c));
    }
    return v;
}

// The share of vertices whose normal points away from `centre` (1: all outwards).
double outwardNormals(const Mesh &m, const glm::vec3 &centre = glm::vec3(0.0f))
{
    std::size_t out = 0;
    for (std::size_t v = 0; v < m.vertexCount(); ++v)
        out += glm::dot(m.normals[v], m.positions[v] - centre) > 0.0f;
    return double(out) / double(m.vertexCount());
}

// Only the winding reversed (the normals kept), or only the normals negated.
Mesh windingReversed(Mesh m)
{
    for (std::size_t t = 0; t < m.triangleCount(); ++t)
        std::swap(m.indices[3 * t + 1], m.indices[3 * t + 2]);
    return m;
}
Mesh normalsNegated(Mesh m)
{
    for (glm::vec3 &n : m.normals)
        n = -n;
    return m;
}

Mesh moved(Mesh m, const glm::vec3 &by)
{
    for (glm::vec3 &p : m.positions)
        p += by;
    return m;
}

Mesh joined(const Mesh &a, const Mesh &b)
{
    Mesh m = a;
    const std::uint32_t offset = std::uint32_t(a.vertexCount());
    m.positions.insert(m.positions.end(), b.positions.begin(), b.positions.end());
    m.normals.insert(m.normals.end(), b.normals.begin(), b.normals.end());
    for (std::uint32_t i : b.indices)
        m.indices.push_back(i + offset);
    return m;
}

OrientationCheck checked(const Mesh &m)
{
    const std::optional<OrientationCheck> c = checkOrientation(m);
    if (!c)
        qFatal("checkOrientation cancelled without a cancel flag");
    return *c;
}

MeshFile fileOf(const Mesh &m)
{
    MeshFile f;
    f.path = QStringLiteral("/tmp/inside_out.ply");
    f.mesh = std::make_shared<const Mesh>(m);
    return f;
}

} // namespace

class TestMeshOrientation : public QObject
{
    Q_OBJECT
private slots:
    // The cube's faces are split at its edges (24 vertices): the parts are found through
    // shared positions, as for a file whose seams split its vertices.
    void cubeWoundInwardsIsTurned()
    {
        const Mesh cube = makeCube();
        QVERIFY(signedVolume(cube) > 0.0);
        const Mesh inside = windingReversed(cube);
        const OrientationCheck c = checked(inside);
        QCOMPARE(c.parts, std::size_t(1));
        QCOMPARE(c.enclosing, std::size_t(1));
        QCOMPARE(c.turnedFaces, std::size_t(1));
        QCOMPARE(c.turnedNormals, std::size_t(0)); // its normals point outwards already
        const Mesh fixed = orientedMesh(inside, c);
        QCOMPARE(fixed.indices, cube.indices);
        QCOMPARE(fixed.normals, cube.normals);
        QCOMPARE(orientationRemark(c),
                 QStringLiteral("faces turned: the file winds them clockwise"));
    }

    void outwardCubeIsLeftAlone()
    {
        const OrientationCheck c = checked(makeCube());
        QCOMPARE(c.enclosing, std::size_t(1));
        QVERIFY(!c.changes());
        QVERIFY(c.part.empty());
        QVERIFY(orientationRemark(c).isEmpty());
    }

    // Normals against an outward winding, and normals that follow an inward one.
    void normalsThatPointInwardsAreTurned()
    {
        const Mesh cube = makeCube();
        OrientationCheck c = checked(normalsNegated(cube));
        QCOMPARE(c.turnedFaces, std::size_t(0));
        QCOMPARE(c.turnedNormals, std::size_t(1));
        QCOMPARE(orientedMesh(normalsNegated(cube), c).normals, cube.normals);
        QCOMPARE(orientationRemark(c), QStringLiteral("normals turned: the file's point inwards"));

        c = checked(flippedMesh(cube)); // winding and normals inwards
        QCOMPARE(c.turnedFaces, std::size_t(1));
        QCOMPARE(c.turnedNormals, std::size_t(1));
        const Mesh fixed = orientedMesh(flippedMesh(cube), c);
        QCOMPARE(fixed.indices, cube.indices);
        QCOMPARE(fixed.normals, cube.normals);
    }

    // A sheet encloses nothing: which way it faces is the file's to say.
    void openSheetIsLeftAlone()
    {
        const OrientationCheck c = checked(flippedMesh(makePlane(8)));
        QCOMPARE(c.parts, std::size_t(1));
        QCOMPARE(c.enclosing, std::size_t(0));
        QVERIFY(!c.changes());
    }

    // A closed mesh with a small hole (a scan's) still encloses a volume.
    void sphereWithAHoleIsTurned()
    {
        Mesh sphere = windingReversed(makeSphere(32, 16));
        sphere.indices.erase(sphere.indices.begin(), sphere.indices.begin() + 3 * 64); // the cap
        const OrientationCheck c = checked(sphere);
        QCOMPARE(c.enclosing, std::size_t(1));
        QCOMPARE(c.turnedFaces, std::size_t(1));
        QVERIFY(signedVolume(orientedMesh(sphere, c)) > 0.0);
    }

    // Part by part: the inward cube is turned, the outward sphere beside it is not.
    void eachPartOnItsOwn()
    {
        const Mesh sphere = moved(makeSphere(16, 8), {3.0f, 0.0f, 0.0f});
        const Mesh both = joined(windingReversed(makeCube()), sphere);
        const OrientationCheck c = checked(both);
        QCOMPARE(c.parts, std::size_t(2));
        QCOMPARE(c.enclosing, std::size_t(2));
        QCOMPARE(c.turnedFaces, std::size_t(1));
        const Mesh fixed = orientedMesh(both, c);
        const std::size_t cubeCorners = makeCube().indices.size();
        QVERIFY(std::equal(fixed.indices.begin(), fixed.indices.begin() + long(cubeCorners),
                           makeCube().indices.begin()));
        QVERIFY(std::equal(fixed.indices.begin() + long(cubeCorners), fixed.indices.end(),
                           both.indices.begin() + long(cubeCorners)));
        QCOMPARE(
            orientationRemark(c),
            QStringLiteral("faces of 1 of 2 closed parts turned: the file winds them clockwise"));
    }

    void degenerateInputs()
    {
        QCOMPARE(checked(Mesh{}).parts, std::size_t(0));
        Mesh dot; // three triangles at one point: no area, no volume
        dot.positions.assign(3, glm::vec3(0.0f));
        dot.indices = {0, 1, 2, 0, 1, 2, 2, 1, 0};
        QVERIFY(!checked(dot).changes());
        std::atomic_bool cancel{true};
        QVERIFY(!checkOrientation(makeSphere(64, 32), &cancel));
    }

    void twoSidedMeshHasAReversedCopy()
    {
        const Mesh cube = makeCube();
        const Mesh both = twoSidedMesh(cube);
        QCOMPARE(both.triangleCount(), 2 * cube.triangleCount());
        QCOMPARE(both.vertexCount(), 2 * cube.vertexCount());
        const std::size_t n = cube.vertexCount();
        for (std::size_t v = 0; v < n; ++v) {
            QCOMPARE(both.positions[n + v], cube.positions[v]);
            QCOMPARE(both.normals[n + v], -cube.normals[v]);
        }
        // The copy encloses the same volume the other way round.
        QCOMPARE(signedVolume(both), 0.0);
        QVERIFY(signedVolume(flippedMesh(cube)) < 0.0);
    }

    // What the object panel's Faces choice draws of an inside-out file, generated normals and
    // the file's own.
    void buildObjectMeshFollowsTheChoice_data()
    {
        QTest::addColumn<int>("faces");
        QTest::addColumn<bool>("fileNormals");
        QTest::addColumn<double>("outward"); // the share of normals pointing outwards
        QTest::addColumn<bool>("remark");
        QTest::newRow("outward, generated") << int(Faces::Outward) << false << 1.0 << true;
        QTest::newRow("outward, file's") << int(Faces::Outward) << true << 1.0 << true;
        QTest::newRow("file, generated") << int(Faces::File) << false << 0.0 << false;
        QTest::newRow("file, file's") << int(Faces::File) << true << 0.0 << false;
        QTest::newRow("flipped, generated") << int(Faces::Flipped) << false << 1.0 << false;
        QTest::newRow("two-sided, generated") << int(Faces::TwoSided) << false << 0.5 << false;
    }
    void buildObjectMeshFollowsTheChoice()
    {
        QFETCH(int, faces);
        QFETCH(bool, fileNormals);
        QFETCH(double, outward);
        QFETCH(bool, remark);
        Mesh inside = flippedMesh(makeSphere(24, 12)); // winding and normals inwards
        if (!fileNormals)
            inside.normals.clear();
        const MeshFile file = fileOf(inside);
        ObjectSettings object;
        object.faces = Faces(faces);
        object.normals = NormalMode::File;
        QString said;
        const std::shared_ptr<const Mesh> mesh = buildObjectMesh(object, &file, nullptr, &said);
        QVERIFY(mesh);
        QCOMPARE(outwardNormals(*mesh), outward);
        QCOMPARE(!said.isEmpty(), remark);
        if (remark)
            QVERIFY2(said.startsWith(QStringLiteral("faces turned")), qPrintable(said));
        QCOMPARE(objectMeshKey(object, &file).faces, Faces(faces));
        if (faces == int(Faces::Outward))
            QVERIFY(signedVolume(*mesh) > 0.0);
    }

    // The shapes are outward already: outward and as-is are one mesh; the others differ.
    void shapesKeepTheirKeyWhenOutward()
    {
        ObjectSettings a, b;
        a.faces = Faces::Outward;
        b.faces = Faces::File;
        QVERIFY(objectMeshKey(a, nullptr) == objectMeshKey(b, nullptr));
        b.faces = Faces::TwoSided;
        QVERIFY(objectMeshKey(a, nullptr) != objectMeshKey(b, nullptr));
        QCOMPARE(buildObjectMesh(b, nullptr)->triangleCount(),
                 2 * buildObjectMesh(a, nullptr)->triangleCount());
    }
};

QTEST_APPLESS_MAIN(TestMeshOrientation)
#include "test_mesh_orientation.moc"
