// The scene budget in the window (issue 29): the 32-spheres-at-2000 scene opens lowered,
// says so, stays up and draws; the file is not overwritten and the document is marked
// modified; the tessellation box stops at the budget and says why; a shape change that would
// go over is lowered too; a build that runs out of memory anyway is a message, and the
// object keeps what it drew. Bad inputs tried: the 17 KB scene of 32 spheres at 2000, 2000
// typed into the 32nd object's box, a sphere turned into a torus (4 times the triangles), a
// torus at 2000 built with the budget off under an address-space limit.

#include "address_space.h"
#include "number_box.h"
#include "window_fixture.h"

#include <QLineEdit>

#include <sys/resource.h>

using namespace lb;
using namespace lb::test;

namespace {

QByteArray spheres(int count, int tessellation)
{
    QJsonArray objects;
    for (int i = 0; i < count; ++i)
        objects.append(QJsonObject{
            {"shape", "sphere"},
            {"tessellation", tessellation},
            {"translation", QJsonArray{(i % 8) * 2.5 - 8.75, (i / 8) * 2.5 - 3.75, 0}}});
    return QJsonDocument(
               QJsonObject{{"format", "lightbench-scene"}, {"version", 3}, {"objects", objects}})
        .toJson();
}

} // namespace

class TestWindowBudget : public WindowTest
{
    Q_OBJECT
private:
    QString writeScene(const QByteArray &bytes)
    {
        const QString path = m_dir.filePath("huge.json");
        QFile f(path);
        if (!f.open(QIODevice::WriteOnly | QIODevice::Truncate) || f.write(bytes) != bytes.size())
            return {};
        return path;
    }
    void waitForMeshes()
    {
        QTRY_VERIFY_WITH_TIMEOUT(!m_window->objectLoader()->isBuilding(), 120000);
    }

private slots:
    void hugeSceneOpensLoweredAndStaysUp()
    {
        const QByteArray bytes = spheres(32, 2000);
        const QString path = writeScene(bytes);
        QVERIFY(m_window->sceneActions()->open(path));
        // Lowered before anything was built, all 32 to one value.
        QCOMPARE(int(scene().objects.size()), 32);
        const int lowered = scene().objects[0].tessellation;
        QVERIFY(lowered >= limits::kMinTessellation && lowered < 2000);
        for (const ObjectSettings &o : scene().objects)
            QCOMPARE(o.tessellation, lowered);
        // Said in the scene's message and on the status line.
        QMessageBox *box = m_window->sceneActions()->messageBox();
        QVERIFY(box && box->isVisible());
        QVERIFY2(box->text().contains("opened with less tessellation"), qPrintable(box->text()));
        const QString said = QString("32 objects at tessellation 2000 would make 128 million "
                                     "triangles");
        QVERIFY2(box->informativeText().startsWith(said), qPrintable(box->informativeText()));
        QVERIFY(
            box->informativeText().contains(QString("lowered to %1 on 32 objects").arg(lowered)));
        QVERIFY(m_window->statusLine()->message().startsWith(said));
        qInfo().noquote() << box->informativeText();
        box->close();
        // Not the file's values: the document is modified, the file untouched.
        QVERIFY(m_window->sceneActions()->isModified());
        QVERIFY(m_window->isWindowModified());
        QFile f(path);
        QVERIFY(f.open(QIODevice::ReadOnly));
        QCOMPARE(f.readAll(), bytes);
        // Every mesh built at the lowered value, the window up and drawing them.
        waitForMeshes();
        QVERIFY(m_window->isVisible());
        for (int i = 0; i < 32; ++i) {
            const std::shared_ptr<const Mesh> mesh = m_window->objectLoader()->mesh(i);
            QVERIFY(mesh);
            QCOMPARE(mesh->triangleCount(), shapeTriangleCount(Shape::Sphere, lowered));
        }
        QVERIFY(!frame().isNull());
    }

    void tessellationBoxStopsAtTheBudget()
    {
        // 31 spheres at 560 and a 32nd at 16: room for about 1100 on the 32nd (unit test).
        Scene s = scene();
        s.objects.assign(32, ObjectSettings{});
        for (ObjectSettings &o : s.objects)
            o.tessellation = 560;
        s.objects[31].tessellation = 16;
        s.selected = 31;
        QVERIFY(m_window->document().set(s).isEmpty());
        auto *box = qobject_cast<IntegerBox *>(m_window->objectPanel()->tessellationBox());
        QVERIFY(box);
        const int most = box->maximum();
        QVERIFY2(most > 16 && most < 2000, qPrintable(QString::number(most)));
        // 2000 typed and Enter pressed: refused, with the reason, and nothing changes.
        auto *edit = box->findChild<QLineEdit *>();
        QVERIFY(edit);
        box->setFocus();
        edit->selectAll();
        QTest::keyClicks(edit, "2000");
        QVERIFY2(box->problem().contains("memory"), qPrintable(box->problem()));
        QVERIFY(box->problem().contains(QString::number(most)));
        QTest::keyClick(edit, Qt::Key_Return);
        QCOMPARE(scene().objects[31].tessellation, 16);
        // The most it shows is taken.
        edit->selectAll();
        QTest::keyClicks(edit, QString::number(most));
        QTest::keyClick(edit, Qt::Key_Return);
        QCOMPARE(scene().objects[31].tessellation, most);
        // A sphere made a torus asks four times the triangles: lowered, and said.
        m_window->objectPanel()->shapeCombo()->setCurrentIndex(int(Shape::Torus));
        QCOMPARE(scene().objects[31].shape, Shape::Torus);
        QVERIFY(scene().objects[31].tessellation < most);
        QVERIFY2(m_window->statusLine()->message().contains("tessellation lowered to"),
                 qPrintable(m_window->statusLine()->message()));
        QVERIFY(m_window->isVisible()); // its meshes are built meanwhile (the first test waits)
    }

#ifndef LIGHTBENCH_SANITIZE // ASan cannot run under an address-space limit (moc sees this one)
    void outOfMemoryInTheWorkerIsAMessage()
    {
        QTRY_VERIFY(!m_window->objectLoader()->isBuilding());
        const std::shared_ptr<const Mesh> before = m_window->objectLoader()->mesh(0);
        QVERIFY(before);
        // The budget off, and 48 MB more address space than the process has: the torus's
        // first array (8 M vertices, 96 MB) cannot be had, even if a few tens of MB were given
        // back meanwhile (CI once saw the build pass under 128 MB more).
        m_window->document().setLimit({});
        rlimit old{};
        QVERIFY(getrlimit(RLIMIT_AS, &old) == 0);
        const rlim_t now = lb::test::addressSpaceInUse();
        QVERIFY(now > 0);
        rlimit tight = old;
        tight.rlim_cur = now + (48u << 20);
        QSignalSpy failed(m_window->objectLoader(), &ObjectLoader::buildFailed);
        QVERIFY(setrlimit(RLIMIT_AS, &tight) == 0);
        m_window->document().edit([](Scene &s) {
            s.objects[0].shape = Shape::Torus;
            s.objects[0].tessellation = 2000;
        });
        // The limit holds for the whole process: the window must not paint (llvmpipe's
        // allocations then failed in an event handler, under load) until it is lifted.
        m_window->objectLoader()->waitForBuildThread();
        setrlimit(RLIMIT_AS, &old);
        const bool said = failed.wait(30000) || !failed.isEmpty();
        QVERIFY2(
            said,
            qPrintable(QString("no failure: address space %1 MB at the start, %2 MB "
                               "now; the mesh has %3 vertices")
                           .arg(now >> 20)
                           .arg(lb::test::addressSpaceInUse() >> 20)
                           .arg(m_window->objectLoader()->mesh(0)
                                    ? qlonglong(m_window->objectLoader()->mesh(0)->vertexCount())
                                    : -1)));
        QCOMPARE(failed.first().at(1).toString(),
                 QString("out of memory building the torus at tessellation 2000"));
        QMessageBox *box = m_window->meshActions()->errorBox();
        QVERIFY(box && box->isVisible());
        QVERIFY(box->informativeText().contains("out of memory building the torus"));
        box->close();
        // Up, drawing what it had, and not building it again.
        QVERIFY(m_window->isVisible());
        QCOMPARE(m_window->objectLoader()->mesh(0), before);
        QVERIFY(!m_window->objectLoader()->isBuilding());
        QVERIFY(!frame().isNull());
        QCOMPARE(failed.size(), 1);
    }
#endif
};

LB_WINDOW_TEST_MAIN(TestWindowBudget)
#include "test_window_budget.moc"
