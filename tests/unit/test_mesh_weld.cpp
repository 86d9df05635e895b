// The weld (mesh_weld.h): the first vertex at each position, on one thread for small meshes
// and split by hash over the cores for big ones; both must give the lowest index at each
// position, -0 welded with 0, whatever order the duplicates come in.
#include "mesh_weld.h"

#include <QTest>

#include <map>
#include <random>
#include <tuple>

using namespace lb;

namespace {

// The lowest index at each position, the slow and obvious way.
std::vector<std::uint32_t> reference(const std::vector<glm::vec3> &positions)
{
    std::map<std::tuple<float, float, float>, std::uint32_t> first;
    std::vector<std::uint32_t> out(positions.size());
    for (std::size_t v = 0; v < positions.size(); ++v) {
        const glm::vec3 p = positions[v] + glm::vec3(0.0f); // -0 + 0 is +0
        out[v] = first.try_emplace({p.x, p.y, p.z}, std::uint32_t(v)).first->second;
    }
    return out;
}

// `distinct` positions on a grid, each `copies` times, shuffled; some at -0.
std::vector<glm::vec3> shuffledCopies(std::size_t distinct, int copies)
{
    std::vector<glm::vec3> p;
    for (std::size_t i = 0; i < distinct; ++i)
        for (int c = 0; c < copies; ++c)
            p.emplace_back(float(i % 97) * 0.25f, float(i / 97 % 89), float(i / (97 * 89)));
    std::mt19937 random(48);
    std::shuffle(p.begin(), p.end(), random);
    for (std::size_t v = 0; v < p.size(); v += 7)
        if (p[v].x == 0.0f)
            p[v].x = -0.0f;
    return p;
}

} // namespace

class TestMeshWeld : public QObject
{
    Q_OBJECT
private slots:
    void lowestIndexAtEachPosition_data()
    {
        QTest::addColumn<int>("distinct");
        QTest::addColumn<int>("copies");
        QTest::newRow("small: one thread") << 1000 << 3;
        QTest::newRow("big: split over the cores") << 300'000 << 2;
        QTest::newRow("big, all distinct") << 600'000 << 1;
        QTest::newRow("big, one position") << 1 << 600'000;
    }

    void lowestIndexAtEachPosition()
    {
        QFETCH(int, distinct);
        QFETCH(int, copies);
        const std::vector<glm::vec3> positions = shuffledCopies(std::size_t(distinct), copies);
        QVERIFY(weldPositions(positions) == reference(positions));
    }

    void emptyMesh() { QVERIFY(weldPositions({}).empty()); }
};

QTEST_GUILESS_MAIN(TestMeshWeld)
#include "test_mesh_weld.moc"
