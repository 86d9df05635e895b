// The workbench's side of the import stream: whatever the helper writes (a whole mesh,
// a stream cut anywhere, flipped bytes, lying sizes), the reader gives a checked mesh or an
// error, never a crash or an index past the last vertex.
#include "import_process.h"
#include "wire.h"
#include "wire_reader.h"

#include <QFile>
#include <QRandomGenerator>
#include <QTest>

#include <cstring>
#include <limits>

using namespace lb;

namespace {

template <typename T> void append(QByteArray &bytes, const T &value)
{
    bytes.append(reinterpret_cast<const char *>(&value), sizeof value);
}

void record(QByteArray &bytes, wire::Record type, const QByteArray &payload)
{
    wire::RecordHeader h;
    h.type = std::uint32_t(type);
    h.size = std::uint64_t(payload.size());
    append(bytes, h);
    bytes += payload;
}

// A two-triangle quad with normals, as the helper writes it.
QByteArray quadStream(std::uint32_t badIndex = 0)
{
    QByteArray mesh;
    wire::MeshHeader h;
    h.vertexCount = 4;
    h.indexCount = 6;
    h.flags = wire::kHasNormals;
    append(mesh, h);
    const float positions[12] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
    const float normals[12] = {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1};
    const std::uint32_t indices[6] = {0, 1, 2, 0, 2, badIndex ? badIndex : 3};
    mesh.append(reinterpret_cast<const char *>(positions), sizeof positions);
    mesh.append(reinterpret_cast<const char *>(normals), sizeof normals);
    mesh.append(reinterpret_cast<const char *>(indices), sizeof indices);

    QByteArray s(wire::kMagic, sizeof wire::kMagic);
    QByteArray progress;
    append(progress, 0.5f);
    progress += "reading";
    record(s, wire::Record::Progress, progress);
    record(s, wire::Record::Mesh, mesh);
    record(s, wire::Record::Info, "meshes=1\nseconds=0.01\n");
    record(s, wire::Record::End, {});
    return s;
}

} // namespace

class TestWireReader : public QObject
{
    Q_OBJECT
private slots:
    void readsAWholeStream()
    {
        WireReader r;
        double lastProgress = -1;
        r.onProgress = [&](double f, const QString &) { lastProgress = f; };
        QVERIFY(r.feed(quadStream().constData(), quadStream().size()));
        QVERIFY(r.complete());
        QCOMPARE(lastProgress, 1.0); // the mesh arrived in full
        QCOMPARE(r.info().value("meshes"), QString("1"));
        const Mesh m = r.takeMesh();
        QCOMPARE(m.vertexCount(), std::size_t(4));
        QCOMPARE(m.indices, (std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3}));
        QCOMPARE(m.normals.size(), std::size_t(4));
        QVERIFY(m.colors.empty() && m.uvs.empty());
        QCOMPARE(m.positions[2], glm::vec3(1, 1, 0));
    }

    void readsByteByByte()
    {
        const QByteArray s = quadStream();
        WireReader r;
        for (char c : s)
            QVERIFY(r.feed(&c, 1));
        QVERIFY(r.complete());
        QCOMPARE(r.takeMesh().triangleCount(), std::size_t(2));
    }

    void aStreamCutAnywhereIsNeverComplete()
    {
        const QByteArray s = quadStream();
        for (int cut = 0; cut < s.size(); ++cut) {
            WireReader r;
            r.feed(s.constData(), cut);
            QVERIFY2(!r.complete(), qPrintable(QString("cut at %1").arg(cut)));
        }
    }

    void refusesAnIndexPastTheLastVertex()
    {
        WireReader r;
        const QByteArray s = quadStream(4);
        QVERIFY(!r.feed(s.constData(), s.size()));
        QVERIFY(r.malformed());
        QVERIFY2(r.error().contains("index"), qPrintable(r.error()));
    }

    // The helper drops what is not finite; a stream that still holds it (another helper, a
    // bug) is refused rather than drawn. Tried: NaN and +inf in a position, -inf in a normal.
    void refusesCoordinatesThatAreNotFinite_data()
    {
        QTest::addColumn<int>("at"); // a float of the positions (0-11) or normals (12-23)
        QTest::addColumn<float>("value");
        QTest::newRow("NaN position") << 4 << std::numeric_limits<float>::quiet_NaN();
        QTest::newRow("inf position") << 0 << std::numeric_limits<float>::infinity();
        QTest::newRow("-inf normal") << 14 << -std::numeric_limits<float>::infinity();
    }

    void refusesCoordinatesThatAreNotFinite()
    {
        QFETCH(int, at);
        QFETCH(float, value);
        QByteArray s = quadStream();
        // The first float follows the magic, the progress record and the mesh's two headers.
        const qsizetype first = sizeof wire::kMagic + sizeof(wire::RecordHeader) + 4 + 7 +
                                sizeof(wire::RecordHeader) + sizeof(wire::MeshHeader);
        float x1 = 0;
        std::memcpy(&x1, s.constData() + first + 3 * 4, 4);
        QCOMPARE(x1, 1.0f); // the second vertex's x: the offset is right
        std::memcpy(s.data() + first + at * 4, &value, 4);
        WireReader r;
        QVERIFY(!r.feed(s.constData(), s.size()));
        QVERIFY2(r.error().contains("not finite"), qPrintable(r.error()));
    }

    void refusesSizesThatDontAddUp()
    {
        // A vertex count the payload cannot hold, and one of 2^40 (must fail before
        // allocating anything).
        for (std::uint64_t vertices : {std::uint64_t(5), std::uint64_t(1) << 40}) {
            QByteArray s = quadStream();
            // magic, progress record (header, float, "reading"), mesh record header
            const int at = int(sizeof wire::kMagic) + int(sizeof(wire::RecordHeader)) + 4 + 7 +
                           int(sizeof(wire::RecordHeader));
            std::memcpy(s.data() + at, &vertices, sizeof vertices);
            WireReader r;
            QVERIFY(!r.feed(s.constData(), s.size()));
            QVERIFY2(r.error().contains("don't add up"), qPrintable(r.error()));
        }
    }

    // A stream that announces 2^31 indices (8 GB) and sends a few bytes: the window reached
    // 8.4 GB before any data came. Now room is made as bytes arrive, and an announcement over
    // the helper's own memory limit fails before anything is allocated.
    void announcedSizesAllocateNothing()
    {
        auto residentMB = [] {
            QFile statm("/proc/self/statm");
            if (!statm.open(QIODevice::ReadOnly))
                return 0.0;
            return statm.readAll().split(' ').value(1).toDouble() * 4096.0 / (1 << 20);
        };
        const std::uint64_t indices = std::uint64_t(1) << 31;
        QByteArray s(wire::kMagic, sizeof wire::kMagic);
        wire::MeshHeader h;
        h.vertexCount = 3;
        h.indexCount = indices - indices % 3;
        wire::RecordHeader r;
        r.type = std::uint32_t(wire::Record::Mesh);
        r.size = sizeof h + 3 * 12 + h.indexCount * 4;
        append(s, r);
        append(s, h);
        s += QByteArray(3 * 12 + 4096, '\0'); // the positions and a few indices

        const double before = residentMB();
        WireReader open;
        // Fine so far (only incomplete), or, where the system lends no address space for the
        // whole announcement, failed with a message; never 8 GB taken.
        if (!open.feed(s.constData(), s.size()))
            QVERIFY2(open.error().startsWith("not enough memory"), qPrintable(open.error()));
        QVERIFY(!open.complete());
        QVERIFY2(residentMB() - before < 64.0,
                 qPrintable(QString("%1 MB more").arg(residentMB() - before)));

        WireReader limited;
        limited.setMaxMeshBytes(std::uint64_t(512) << 20); // the helper's limit
        QVERIFY(!limited.feed(s.constData(), s.size()));
        QVERIFY2(limited.error().contains("more than the helper may use (512 MB)"),
                 qPrintable(limited.error()));

        // The window's cap: the helper's limit, and never more than the machine has, even
        // with no limit or one past the machine's memory (Preferences, --import-memory-limit).
        const std::uint64_t machine = std::uint64_t(ImportLimits::machineMemoryMB()) << 20;
        QVERIFY(machine > 0);
        ImportLimits limits;
        limits.memoryMB = 512;
        QCOMPARE(limits.meshByteCap(), std::uint64_t(512) << 20);
        for (qint64 mb : {qint64(0), ImportLimits::machineMemoryMB() * 4}) {
            limits.memoryMB = mb;
            QCOMPARE(limits.meshByteCap(), machine);
        }
    }

    void refusesOtherStreams()
    {
        const QByteArray notAStream = "hello, I am a helper gone wrong\n";
        WireReader r;
        QVERIFY(!r.feed(notAStream.constData(), notAStream.size()));
        QVERIFY(r.error().contains("not a mesh stream"));

        QByteArray twoMeshes = quadStream();
        twoMeshes.chop(int(sizeof(wire::RecordHeader))); // drop End, add the mesh again
        const QByteArray again = quadStream();
        twoMeshes += again.mid(int(sizeof wire::kMagic));
        WireReader r2;
        QVERIFY(!r2.feed(twoMeshes.constData(), twoMeshes.size()));

        QByteArray unknown(wire::kMagic, sizeof wire::kMagic);
        record(unknown, wire::Record(99), "x");
        WireReader r3;
        QVERIFY(!r3.feed(unknown.constData(), unknown.size()));
        QVERIFY(r3.error().contains("unknown"));

        QByteArray endWithoutMesh(wire::kMagic, sizeof wire::kMagic);
        record(endWithoutMesh, wire::Record::End, {});
        WireReader r4;
        QVERIFY(!r4.feed(endWithoutMesh.constData(), endWithoutMesh.size()));
    }

    void passesTheHelpersErrorOn()
    {
        QByteArray s(wire::kMagic, sizeof wire::kMagic);
        record(s, wire::Record::Error, "PLY: unexpected end of file");
        WireReader r;
        QVERIFY(!r.feed(s.constData(), s.size()));
        QVERIFY(!r.malformed());
        QCOMPARE(r.error(), QString("PLY: unexpected end of file"));
    }

    void flippedBytesNeverGiveABadMesh()
    {
        const QByteArray good = quadStream();
        QRandomGenerator random(1234);
        for (int round = 0; round < 5000; ++round) {
            QByteArray s = good;
            const int flips = 1 + int(random.bounded(4));
            for (int i = 0; i < flips; ++i)
                s[int(random.bounded(s.size()))] = char(random.bounded(256));
            WireReader r;
            r.feed(s.constData(), s.size());
            if (!r.complete())
                continue;
            const Mesh m = r.takeMesh();
            for (std::uint32_t index : m.indices)
                QVERIFY(index < m.vertexCount());
            QCOMPARE(m.indices.size() % 3, std::size_t(0));
        }
    }
};

QTEST_APPLESS_MAIN(TestWireReader)
#include "test_wire_reader.moc"
