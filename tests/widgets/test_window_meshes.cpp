// Mesh files in the window: open, refuse, normals, progress and cancel, drops, restart.
#include "window_fixture.h"

#include <QFile>
#include <QTemporaryDir>

using namespace lb;
using namespace lb::test;

class TestWindowMeshes : public WindowTest
{
    Q_OBJECT
private slots:
    void openedMeshIsDrawnAndDescribed()
    {
        const QImage sphere = frame();
        const auto [ok, message] = openMesh(kCube);
        QVERIFY2(ok, qPrintable(message));
        QCOMPARE(scene().objects[0].meshPath, kCube);
        QVERIFY(imageDifference(sphere, frame()) > 10);
        const QString summary = m_window->meshActions()->summaryLabel()->toolTip();
        QVERIFY2(summary.startsWith("cube.ply: ") && summary.contains("triangles") &&
                     summary.contains("loaded in"),
                 qPrintable(summary));
        QCOMPARE(m_window->objectPanel()->shapeCombo()->currentText(), QString("File: cube.ply"));
        QCOMPARE(m_window->meshActions()->recent()->files().value(0), kCube);
        // A built-in shape is one click away.
        m_window->objectPanel()->shapeCombo()->setCurrentIndex(int(Shape::Torus));
        QVERIFY(scene().objects[0].meshPath.isEmpty());
        QTRY_VERIFY(m_window->meshActions()->summaryLabel()->text().startsWith("torus: "));
        // The status bar has the short form; the whole summary is the tooltip.
        QVERIFY(!m_window->meshActions()->summaryLabel()->text().contains("vertices"));
        QVERIFY(m_window->meshActions()->summaryLabel()->toolTip().contains("vertices"));
    }

    // A closed mesh wound inwards (as the Stanford bunny is) is turned, and the status line
    // says so where a narrow window still shows it: the message place, which has the most
    // room while it shows; the mesh's own place keeps it too.
    void turnedFacesAreSaidWhereThereIsRoom()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath("inward.ply");
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
                "property float z\nelement face 4\nproperty list uchar int vertex_indices\n"
                "end_header\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n3 0 3 1\n3 0 2 3\n3 1 3 2\n");
        f.close();
        m_window->resize(1024, 768);
        const auto [ok, message] = openMesh(path);
        QVERIFY2(ok, qPrintable(message));
        StatusLine *line = m_window->statusLine();
        QTRY_VERIFY(line->messageLabel()->isVisible());
        QVERIFY2(line->message().startsWith("inward.ply: faces turned: the file winds them"),
                 qPrintable(line->message()));
        QVERIFY(line->meshLabel()->text().contains("faces turned"));
        QTRY_VERIFY(line->messageLabel()->width() > line->programLabel()->width());
        QVERIFY(line->messageLabel()->width() > 2 * line->meshLabel()->width());
    }

    void badMeshKeepsThePreviousOneAndSaysWhy()
    {
        QVERIFY(openMesh(kCube).first);
        const QImage cube = frame();
        const auto [ok, message] = openMesh(kMalformed);
        QVERIFY(!ok);
        QMessageBox *box = m_window->meshActions()->errorBox();
        QVERIFY(box && box->isVisible());
        QVERIFY2(box->informativeText().contains("malformed.obj") &&
                     box->informativeText().contains("Invalid face index"),
                 qPrintable(box->informativeText()));
        QCOMPARE(scene().objects[0].meshPath, kCube);
        QVERIFY(imageDifference(cube, frame()) <= 2);
        box->close();
    }

    void normalsChangeWithoutReloading()
    {
        QVERIFY(openMesh(kCube).first);
        QSignalSpy started(m_window->objectLoader(), &ObjectLoader::loadStarted);
        ObjectPanel *panel = m_window->objectPanel();
        panel->normalsCombo()->setCurrentIndex(int(NormalMode::Smooth));
        auto settle = [&] { QTRY_VERIFY(!m_window->objectLoader()->isBuilding()); };
        expectNewImage(
            [&] {
                panel->creaseBox()->setValue(180); // every cube edge smoothed
                settle();
            },
            "smooth cube");
        expectNewImage(
            [&] {
                panel->normalsCombo()->setCurrentIndex(int(NormalMode::Flat));
                settle();
            },
            "flat cube");
        QVERIFY(!panel->creaseBox()->isEnabled()); // flat has no crease angle
        expectNewImage([&] { QTest::keyClick(m_window.get(), Qt::Key_N); }, "normal lines");
        QVERIFY(scene().objects[0].showNormals);
        QCOMPARE(started.count(), 0);
    }

    void slowLoadShowsProgressAndCancelStopsTheHelper()
    {
        const QString helper = writeSlowImportHelper(m_dir);
        QVERIFY(!helper.isEmpty());
        const QByteArray saved = qgetenv("LIGHTBENCH_IMPORT_HELPER");
        qputenv("LIGHTBENCH_IMPORT_HELPER", helper.toLocal8Bit());
        const Scene before = scene();
        QSignalSpy finished(m_window->objectLoader(), &ObjectLoader::loadFinished);
        m_window->meshActions()->open(kCube);
        LoadProgress *progress = m_window->meshActions()->progress();
        QVERIFY(!progress->isVisible()); // not for the first half second
        QTRY_VERIFY_WITH_TIMEOUT(progress->isVisible(), 3000);
        const qint64 pid = m_window->objectLoader()->helperPid();
        QVERIFY(pid > 0 && ::kill(pid_t(pid), 0) == 0);
        // The window answers meanwhile.
        m_window->materialPanel()->shininessBox()->setValue(12);
        QCOMPARE(scene().objects[0].material.shininess, 12.0f);
        QTest::mouseClick(progress->cancelButton(), Qt::LeftButton);
        QTRY_COMPARE(finished.count(), 1);
        QVERIFY(!progress->isVisible());
        QVERIFY(::kill(pid_t(pid), 0) != 0); // the helper is gone
        QCOMPARE(scene().objects[0].meshPath, before.objects[0].meshPath);
        QVERIFY(!m_window->meshActions()->errorBox()); // cancelling is no error
        qputenv("LIGHTBENCH_IMPORT_HELPER", saved);
    }

    void droppedFileIsOpened()
    {
        QMimeData data;
        data.setUrls({QUrl::fromLocalFile(kCube)});
        QDragEnterEvent enter(QPoint(10, 10), Qt::CopyAction, &data, Qt::LeftButton,
                              Qt::NoModifier);
        QApplication::sendEvent(m_window.get(), &enter);
        QVERIFY(enter.isAccepted());
        QDropEvent drop(QPointF(10, 10), Qt::CopyAction, &data, Qt::LeftButton, Qt::NoModifier);
        QSignalSpy finished(m_window->objectLoader(), &ObjectLoader::loadFinished);
        QApplication::sendEvent(m_window.get(), &drop);
        QVERIFY(finished.wait(30000));
        QCOMPARE(scene().objects[0].meshPath, kCube);
    }

    // A slow program kept with a mesh file: at the next start the file is read by the helper
    // after the program is built, so the program is tried again on the mesh once it is there,
    // and refused; the built-in program draws the mesh.
    void slowProgramIsTriedAgainOnTheLoadedMesh()
    {
        QVERIFY(openMesh(kCube).first);
        const Preset &slides = presets()[3];
        QString fragment = slides.fragmentSource();
        fragment.insert(int(fragment.indexOf("    gl_FragColor")),
                        "    float k = N.x + 2.0;\n    while (k > 0.0) { k = k * 1.0 + 0.0001; }\n"
                        "    diffuse *= k;\n");
        m_window->shaderDocument().setSources(slides.vertexSource(), fragment);
        m_window->close(); // saves
        m_window = std::make_unique<MainWindow>(*m_settings);
        m_window->show();
        QTRY_VERIFY_WITH_TIMEOUT(m_window->objectLoader()->file() &&
                                     m_window->objectLoader()->file()->path == kCube,
                                 30000);
        frame();
        QTRY_VERIFY_WITH_TIMEOUT(m_window->viewport()->banner().startsWith("Refused:"), 10000);
        QVERIFY(!m_window->viewport()->renderer().hasUserProgram());
        QCOMPARE(m_window->editorPanel()->source(ShaderStage::Fragment), fragment);
    }

    void meshComesBackAfterARestart()
    {
        QVERIFY(openMesh(kCube).first);
        m_window->close(); // saves
        m_window = std::make_unique<MainWindow>(*m_settings);
        QCOMPARE(scene().objects[0].meshPath, kCube);
        QTRY_VERIFY(m_window->objectLoader()->file() &&
                    m_window->objectLoader()->file()->path == kCube);
        // A file gone since then: the shape is drawn, with a message; the scene still names
        // the file (a save keeps it), and the Object panel and the status bar say so.
        m_window->close();
        const QByteArray saved = m_settings->value("scene").toByteArray();
        m_settings->setValue("scene", QByteArray(saved).replace(kCube.toUtf8(), "/gone/away.ply"));
        m_window = std::make_unique<MainWindow>(*m_settings);
        QTRY_VERIFY(m_window->meshActions()->errorBox());
        QVERIFY(m_window->meshActions()->errorBox()->informativeText().contains("/gone/away.ply"));
        QCOMPARE(scene().objects[0].meshPath, QString("/gone/away.ply"));
        QTRY_VERIFY(!m_window->objectLoader()->isBuilding());
        QCOMPARE(m_window->objectLoader()->file(), nullptr);
        QCOMPARE(m_window->objectPanel()->shapeCombo()->currentText(),
                 QString("File: away.ply (not loaded)"));
        QVERIFY(
            m_window->objectPanel()
                ->shapeCombo()
                ->itemData(m_window->objectPanel()->shapeCombo()->currentIndex(), Qt::ToolTipRole)
                .toString()
                .contains("/gone/away.ply: no such file"));
        QCOMPARE(m_window->statusLine()->meshLabel()->text(),
                 QString("away.ply not loaded (sphere drawn)"));
    }
};

LB_WINDOW_TEST_MAIN(TestWindowMeshes)
#include "test_window_meshes.moc"
