// The helper's own PLY and STL readers (fast_mesh_readers.h) on files a stranger made: small
// valid files mutated (bytes flipped, bytes set to digits, cut anywhere, counts in the header
// made huge), each read from memory. Every read must end (read, declined or refused), without
// a crash, in bounded memory: what a read file holds stays within a small multiple of its
// bytes, and the whole test runs with its address space capped (RLIMIT_AS, not under the
// sanitizers, whose shadow memory needs terabytes of it).
#include "address_space.h"
#include "fast_mesh_readers.h"

#include <assimp/MemoryIOWrapper.h>

#include <QTest>

#include <random>

using namespace lb;

namespace {

QByteArray binaryPly(bool big)
{
    QByteArray b = QByteArray("ply\nformat ") +
                   (big ? "binary_big_endian" : "binary_little_endian") +
                   " 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
                   "property uchar red\nproperty uchar green\nproperty uchar blue\n"
                   "element face 2\nproperty list uchar int vertex_indices\nend_header\n";
    const float v[4][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    auto put = [&](const void *p, int n) {
        QByteArray x(static_cast<const char *>(p), n);
        if (big)
            std::reverse(x.begin(), x.end());
        b += x;
    };
    for (const auto &p : v) {
        for (float c : p)
            put(&c, 4);
        b += QByteArray("\x10\x80\xff", 3);
    }
    const int faces[2][3] = {{0, 1, 2}, {0, 2, 3}};
    for (const auto &f : faces) {
        b += '\x03';
        for (int i : f)
            put(&i, 4);
    }
    return b;
}

QByteArray asciiPly()
{
    return "ply\nformat ascii 1.0\ncomment seed\nelement vertex 4\nproperty double x\n"
           "property double y\nproperty double z\nproperty float nx\nproperty float ny\n"
           "property float nz\nelement face 3\nproperty list uchar int vertex_indices\n"
           "end_header\n0 0 0 0 0 1\n1 0 0 0 0 1\n1 1 0.5 0 0 1\n0 1 0 0 0 1\n3 0 1 2\n"
           "3 0 2 3\n2 0 1\n";
}

QByteArray binaryStl()
{
    QByteArray b = QByteArray("COLOR=\x20\x40\x80\xff").leftJustified(80, ' ');
    const std::uint32_t n = 2;
    b.append(reinterpret_cast<const char *>(&n), 4);
    const float facet[12] = {0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0};
    for (std::uint16_t attribute : {std::uint16_t(0x801f), std::uint16_t(0)}) {
        b.append(reinterpret_cast<const char *>(facet), sizeof facet);
        b.append(reinterpret_cast<const char *>(&attribute), 2);
    }
    return b;
}

QByteArray mutate(QByteArray b, std::mt19937 &random)
{
    if (b.isEmpty())
        return b;
    std::uniform_int_distribution<int> kind(0, 4), byte(0, 255);
    auto at = [&] { return std::uniform_int_distribution<qsizetype>(0, b.size() - 1)(random); };
    switch (kind(random)) {
    case 0: // bytes flipped
        for (int i = 0; i < 4; ++i)
            b[at()] = char(byte(random));
        break;
    case 1: // a digit where there was one, or anywhere: counts and values change
        b[at()] = char('0' + byte(random) % 10);
        break;
    case 2: // cut anywhere
        b.truncate(at());
        break;
    case 3: { // a header count made huge
        const qsizetype e =
            b.indexOf("element ", at() % std::max<qsizetype>(1, b.indexOf("end_header")));
        if (e >= 0) {
            const qsizetype space = b.indexOf(' ', e + 8);
            if (space > 0)
                b.insert(space + 1, QByteArray::number(byte(random) * 99999991ll));
        }
        break;
    }
    default: // a byte inserted
        b.insert(at(), char(byte(random)));
    }
    return b;
}

} // namespace

class TestFastReadersFuzz : public QObject
{
    Q_OBJECT
private slots:
    void initTestCase()
    {
#ifndef LIGHTBENCH_SANITIZE
        // 512 MB above what the test holds: a reader that allocated for a header's counts
        // instead of the file's bytes would fail here, not take the machine's memory.
        const rlim_t cap = lb::test::addressSpaceInUse() + (512ull << 20);
        const rlimit limit{cap, cap};
        QVERIFY(setrlimit(RLIMIT_AS, &limit) == 0);
#endif
    }

    void mutatedFiles_data()
    {
        QTest::addColumn<QByteArray>("seed");
        QTest::addColumn<bool>("stl");
        QTest::newRow("binary little-endian PLY") << binaryPly(false) << false;
        QTest::newRow("binary big-endian PLY") << binaryPly(true) << false;
        QTest::newRow("ASCII PLY") << asciiPly() << false;
        QTest::newRow("binary STL") << binaryStl() << true;
    }

    void mutatedFiles()
    {
        QFETCH(QByteArray, seed);
        QFETCH(bool, stl);
        std::mt19937 random(20261207);
        int counts[3] = {};
        for (int i = 0; i < 3000; ++i) {
            QByteArray bytes = mutate(seed, random);
            if (i % 3 == 0) // mutations on mutations
                bytes = mutate(bytes, random);
            Assimp::MemoryIOStream file(reinterpret_cast<const std::uint8_t *>(bytes.constData()),
                                        std::size_t(bytes.size()));
            FastMesh mesh;
            std::string why;
            const FastRead r =
                stl ? readBinaryStl(file, mesh, why, {}) : readPly(file, mesh, why, {});
            ++counts[int(r)];
            if (r != FastRead::Read) {
                QVERIFY2(!why.empty(), "a file declined or refused without a reason");
                continue;
            }
            // Twelve floats a vertex at most (position, normal, colour) for the fewest bytes
            // a vertex takes (three, as int8 coordinates), plus three corners a face.
            const std::size_t held = 4 * (mesh.positions.size() + mesh.normals.size() +
                                          mesh.colors.size() + mesh.triangles.size());
            QVERIFY2(held <= 16 * std::size_t(bytes.size()) + 4096,
                     qPrintable(QString::number(held)));
            QVERIFY(mesh.positions.size() % 3 == 0 && mesh.triangles.size() % 3 == 0);
            QVERIFY(mesh.normals.empty() || mesh.normals.size() == mesh.positions.size());
            QVERIFY(mesh.colors.empty() || mesh.colors.size() == mesh.positions.size());
        }
        qInfo("read %d, declined %d, refused %d", counts[0], counts[1], counts[2]);
        QVERIFY(counts[0] > 0); // the mutations are not all fatal: the readers are exercised
    }
};

QTEST_GUILESS_MAIN(TestFastReadersFuzz)
#include "test_fast_readers_fuzz.moc"
