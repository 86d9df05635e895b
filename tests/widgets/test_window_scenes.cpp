// Scene files, examples, export, compare views and the probe in the window.
#include "window_fixture.h"

#include <QRegularExpression>

using namespace lb;
using namespace lb::test;

class TestWindowScenes : public WindowTest
{
    Q_OBJECT
private slots:
    // An example opened from File > Examples is still the document after a restart, unchanged
    // (it came back as "untitled*", and quitting then asked about changes no one made); its
    // edits are still changes, and Save still asks for a file.
    void anExampleStaysTheDocumentAcrossARestart()
    {
        QVERIFY(m_window->sceneActions()->open(":/examples/toon.json"));
        QVERIFY(!m_window->sceneActions()->isModified());
        const Scene opened = scene();
        m_window->close(); // saves the session
        m_window = std::make_unique<MainWindow>(*m_settings);
        QVERIFY(scene() == opened);
        QCOMPARE(m_window->sceneActions()->documentName(), QString("toon.json"));
        QVERIFY(!m_window->sceneActions()->isModified());
        QVERIFY2(!m_window->windowTitle().contains('*') || !m_window->isWindowModified(),
                 qPrintable(m_window->windowTitle()));
        m_window->document().edit([](Scene &s) { s.objects[0].material.shininess = 3.0f; });
        QVERIFY(m_window->sceneActions()->isModified());
        QVERIFY(m_window->isWindowModified());
    }

    void savedSceneOpensAsTheSameImage()
    {
        // A scene with a program of the student's own, two lights and a changed camera.
        m_window->editorPanel()->loadPreset(presets().back()); // toon
        m_window->document().edit([](Scene &s) {
            s.lights[1].enabled = true;
            s.objects[0].material.kd = {0.2f, 0.5f, 0.9f};
            s.camera.orbit(25, 10);
        });
        const QImage before = frame();
        const Scene saved = scene();
        const auto program = m_window->editorPanel()->program();
        QVERIFY(program);
        const QString path = m_dir.filePath("lesson.json");
        QCOMPARE(m_window->sceneActions()->save(path), QString());
        QVERIFY(m_window->windowTitle().startsWith("lesson.json"));

        m_window->document().set(Scene{});
        m_window->editorPanel()->loadPreset(builtInPreset(false));
        QVERIFY(imageDifference(before, frame()) > 10);

        QVERIFY(m_window->sceneActions()->open(path));
        QVERIFY(scene() == saved);
        QVERIFY(m_window->editorPanel()->program()->vertex == program->vertex);
        QVERIFY(!m_window->sceneActions()->messageBox()); // nothing was ignored
        QVERIFY(imageDifference(before, frame()) <= 1);
        QCOMPARE(m_window->sceneActions()->recent()->files().first(),
                 QFileInfo(path).absoluteFilePath());
    }

    void badSceneFileChangesNothing()
    {
        m_window->document().edit([](Scene &s) { s.objects[0].material.shininess = 77; });
        const Scene before = scene();
        const QString path = m_dir.filePath("broken.json");
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("{\"lights\": [{\"enabled\": tru");
        f.close();
        QVERIFY(!m_window->sceneActions()->open(path));
        QVERIFY(scene() == before);
        QMessageBox *box = m_window->sceneActions()->messageBox();
        QVERIFY(box && box->isVisible());
        QVERIFY2(box->informativeText().startsWith(path + ": not a scene file"),
                 qPrintable(box->informativeText()));
        box->close();

        // Half-usable: opens, and one message lists what was ignored.
        QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
        f.write(R"({"version": 1, "material": {"shininess": -4, "kd": "red"}, "wobble": 1})");
        f.close();
        QVERIFY(m_window->sceneActions()->open(path));
        QCOMPARE(scene().objects[0].material.shininess, limits::kMinShininess);
        box = m_window->sceneActions()->messageBox();
        QVERIFY(box && box->isVisible());
        const QString listed = box->informativeText();
        QVERIFY2(listed.contains("material.kd (not an array of numbers)") &&
                     listed.contains("material.shininess (out of range, clamped)") &&
                     listed.contains("wobble (unknown field)"),
                 qPrintable(listed));
    }

    void everyExampleOpensAndDraws()
    {
        for (const auto &[text, resource] : SceneActions::examples()) {
            const QImage before = frame();
            QVERIFY2(m_window->sceneActions()->open(resource), qPrintable(resource));
            QVERIFY2(!m_window->sceneActions()->messageBox(), qPrintable(resource));
            QVERIFY2(m_window->viewport()->banner().isEmpty(), qPrintable(resource));
            QVERIFY2(imageDifference(before, frame()) > 10, qPrintable(resource));
            // Every image an example names is built in and comes in (not the checker).
            for (int i = 0; i < int(scene().objects.size()); ++i)
                if (!scene().objects[std::size_t(i)].textureFile.isEmpty())
                    QTRY_VERIFY2(m_window->objectLoader()->texture(i), qPrintable(resource));
            QVERIFY2(!m_window->meshActions()->errorBox(), qPrintable(resource));
        }
        // Saved and opened again, the example's image is still the built-in one.
        QVERIFY(m_window->sceneActions()->open(":/examples/texture_filtering.json"));
        const QString saved = m_dir.filePath("floors.json");
        QCOMPARE(m_window->sceneActions()->save(saved), QString());
        QVERIFY(m_window->sceneActions()->open(saved));
        QCOMPARE(scene().objects[0].textureFile, QString(":/examples/bricks.png"));
        QTRY_VERIFY(m_window->objectLoader()->texture(0));
        QVERIFY(!m_window->meshActions()->errorBox());
    }

    // An exercise opened and saved keeps its reference and grading (the window does not
    // show them yet; a teacher's save must not lose them).
    void anExerciseKeepsItsReferenceWhenSaved()
    {
        const QString exercise =
            QStringLiteral(LB_TEST_DATA "/../../resources/examples/exercise_lighting.json");
        QVERIFY(m_window->sceneActions()->open(exercise));
        const QString saved = m_dir.filePath("lesson.json");
        QCOMPARE(m_window->sceneActions()->save(saved), QString());
        const SceneFileRead read = readSceneFile(saved);
        QVERIFY(read.file && read.file->exercise);
        QVERIFY(!read.file->exercise->reference.builtIn());
        QCOMPARE(read.file->exercise->grading.cases, 20);
    }

    // An exercise's reference is side B: the student's program against it in the difference
    // view, without the teacher's source in the editor.
    void anExercisesReferenceIsSideB()
    {
        const QString exercise =
            QStringLiteral(LB_TEST_DATA "/../../resources/examples/exercise_lighting.json");
        QVERIFY(buildAfter([&] { QVERIFY(m_window->sceneActions()->open(exercise)); }));
        QVERIFY(m_window->viewport()->hasSideBProgram());
        m_window->document().edit([](Scene &s) { s.compare.mode = CompareMode::Difference; });
        frame();
        // The starting point (the ambient term alone) is far from the reference.
        QVERIFY2(m_window->viewport()->renderer().difference().largest > 20,
                 qPrintable(m_window->viewport()->compareText()));
        QVERIFY(m_window->viewport()->compareText().contains("the exercise's reference"));
        QVERIFY(!m_window->editorPanel()
                     ->editor(ShaderStage::Fragment)
                     ->text()
                     .contains("specularFactor = pow")); // the teacher's source is not shown
        // The correct answer: no difference.
        QFile answer(LB_TEST_DATA "/grading/correct/lighting.frag");
        QVERIFY(answer.open(QIODevice::ReadOnly));
        const QString text = QString::fromUtf8(answer.readAll());
        const std::optional<ProgramBuild> built = buildAfter(
            [&] { m_window->editorPanel()->editor(ShaderStage::Fragment)->setText(text); });
        QVERIFY(built && built->ok());
        frame();
        QVERIFY2(m_window->viewport()->renderer().difference().largest <= 2,
                 qPrintable(m_window->viewport()->compareText()));
        // Another scene: the built-in program is side B again.
        QVERIFY(m_window->sceneActions()->open(":/examples/toon.json"));
        QVERIFY(!m_window->viewport()->hasSideBProgram());
    }

    void exportWritesTheChosenSize()
    {
        const QString path = m_dir.filePath("view.png");
        QCOMPARE(m_window->sceneActions()->exportImage(path, QSize(1000, 400)), QString());
        QCOMPARE(QImage(path).size(), QSize(1000, 400));
        QVERIFY(
            !m_window->sceneActions()->exportImage("/nowhere/view.png", QSize(10, 10)).isEmpty());
    }

    void compareControlsSplitTheView()
    {
        ShadingPanel *p = m_window->shadingPanel();
        QVERIFY(!p->compareShadingCombo()->isEnabled());
        expectNewImage([&] { p->compareModeCombo()->setCurrentIndex(1); }, "side by side");
        QCOMPARE(scene().compare.mode, CompareMode::SideBySide);
        QVERIFY(m_window->viewport()->compareText().contains("B: built-in Gouraud"));
        QVERIFY(m_window->viewport()->compareText().contains("A (left): Built-in: Phong"));
        expectNewImage([&] { p->compareModeCombo()->setCurrentIndex(3); }, "difference");
        frame();
        QVERIFY2(m_window->viewport()->compareText().contains("largest"),
                 qPrintable(m_window->viewport()->compareText()));
        QVERIFY(m_window->viewport()->renderer().difference().largest >= 20);
        // B = A: nothing differs.
        p->compareShadingCombo()->setCurrentIndex(1);
        frame();
        QCOMPARE(m_window->viewport()->renderer().difference().largest, 0);
        // The wipe follows a drag of its line.
        p->compareModeCombo()->setCurrentIndex(2);
        Viewport *v = m_window->viewport();
        const QPoint line(v->width() / 2, v->height() / 2);
        QTest::mousePress(v, Qt::LeftButton, {}, line);
        QMouseEvent move(QEvent::MouseMove, QPointF(v->width() / 4, line.y()),
                         v->mapToGlobal(QPointF(v->width() / 4, line.y())), Qt::NoButton,
                         Qt::LeftButton, {});
        QApplication::sendEvent(v, &move);
        QTest::mouseRelease(v, Qt::LeftButton, {}, QPoint(v->width() / 4, line.y()));
        QVERIFY(std::abs(scene().compare.wipe - 0.25f) < 0.01f);
        QCOMPARE(scene().camera.yawDegrees, Scene{}.camera.yawDegrees); // no orbit meanwhile
    }

    void windowProbeEqualsTheCommandLineProbe()
    {
        m_window->document().edit([](Scene &s) {
            s.showLight = false;
            s.lights[1].enabled = true; // two lights: both listed
            s.shading.shading = Shading::Gouraud;
            s.objects[0].texture = true; // the checker, mipmapped: the texture row shows
            s.objects[0].sampling.mipmaps = true;
        });
        frame();
        Viewport *v = m_window->viewport();
        const QPoint click(v->width() / 2 + 10, v->height() / 2 - 15);
        QTest::mouseClick(v, Qt::LeftButton, Qt::ControlModifier, click);
        frame();
        ProbePanel *probe = m_window->probePanel();
        QVERIFY(probe->isActive());
        QVERIFY(probe->gpuColour());
        const ProbeResult &r = probe->result();
        QCOMPARE(int(r.lights.size()), 2);
        QVERIFY(probe->textLabel()->text().contains("Light 2"));
        QVERIFY2(probe->textLabel()->text().contains(
                     QString("level of detail %1").arg(double(r.lod), 0, 'f', 2)),
                 qPrintable(probe->textLabel()->text()));
        QCOMPARE(scene().camera.yawDegrees, Scene{}.camera.yawDegrees); // the click did not orbit

        const QString path = m_dir.filePath("probe.json");
        QCOMPARE(m_window->sceneActions()->save(path), QString());
        const QSize size = v->size() * v->devicePixelRatio();
        const QPoint pixel = (QPointF(click) * v->devicePixelRatio()).toPoint();
        QProcess cli;
        cli.start(LIGHTBENCH_EXE,
                  {"--scene", path, "--probe", QString("%1,%2").arg(pixel.x()).arg(pixel.y()),
                   "--size", QString("%1x%2").arg(size.width()).arg(size.height())});
        QVERIFY(cli.waitForFinished(60000));
        const QJsonObject o = QJsonDocument::fromJson(cli.readAllStandardOutput()).object();
        QVERIFY2(o["hit"].toBool(), cli.readAllStandardError().constData());
        auto near = [](const QJsonValue &json, const glm::vec3 &v) {
            const QJsonArray a = json.toArray();
            return a.size() == 3 && std::abs(a[0].toDouble() - v.x) < 1e-4 &&
                   std::abs(a[1].toDouble() - v.y) < 1e-4 && std::abs(a[2].toDouble() - v.z) < 1e-4;
        };
        QCOMPARE(o["triangle"].toInteger(), qint64(r.triangle));
        QVERIFY(std::abs(o["levelOfDetail"].toDouble() - double(r.lod)) < 1e-3);
        QVERIFY(std::abs(o["uv"][0].toDouble() - double(r.uv.x)) < 1e-4);
        QVERIFY(near(o["position"], r.position));
        QVERIFY(near(o["normal"], r.normal));
        QVERIFY(near(o["specular"], r.total.specular));
        const QJsonArray lights = o["lights"].toArray();
        QCOMPARE(lights.size(), 2);
        for (int i = 0; i < 2; ++i) {
            QVERIFY(near(lights[i]["L"], r.lights[std::size_t(i)].terms.L));
            QVERIFY(std::abs(lights[i]["NdotL"].toDouble() - r.lights[std::size_t(i)].terms.nDotL) <
                    1e-4);
        }
        for (int c = 0; c < 3; ++c) {
            QCOMPARE(o["reference"][c].toInt(), int(std::lround(r.reference[c] * 255.0f)));
            QVERIFY(std::abs(o["gpu"][c].toInt() - (*probe->gpuColour())[c]) <= 2);
        }

        // The point stays on the surface while the light moves: new numbers, same triangle.
        const glm::vec3 before = r.lights[0].terms.L;
        m_window->lightPanel()->coordinate(0)->setValue(-3.0);
        frame();
        QCOMPARE(probe->result().triangle, qint64(o["triangle"].toInteger()));
        QVERIFY(glm::length(probe->result().lights[0].terms.L - before) > 0.05f);
        QTest::keyClick(m_window.get(), Qt::Key_Escape);
        QVERIFY(!probe->isActive());
    }

    // Issue 13: a full disk or a read-only config lost edits silently. Here a regular file
    // stands where the settings folder would be made (root may write anywhere else).
    void failedAutosaveIsSaidOnceAndRetried()
    {
        const QString blocker = m_dir.filePath("blocked");
        QVERIFY(QFile(blocker).open(QIODevice::WriteOnly));
        const QString path = blocker + "/settings.ini";
        QSettings settings(path, QSettings::IniFormat);
        MainWindow window(settings);
        window.show();
        window.document().edit([](Scene &s) { s.objects[0].material.shininess = 77.0f; });
        QTRY_VERIFY_WITH_TIMEOUT(window.autosave()->isFailing(), 3000);
        const QString said = window.statusLine()->message();
        QVERIFY2(said.contains("Your work is not saved, trying again") && said.contains(path),
                 qPrintable(said));

        // Said once: a later save that fails too leaves the status line to other messages.
        window.statusLine()->showMessage("something else", 0);
        window.document().edit([](Scene &s) { s.objects[0].material.shininess = 78.0f; });
        QTest::qWait(SettingsAutosave::kDelayMs * 3);
        QCOMPARE(window.statusLine()->message(), QString("something else"));
        QVERIFY(window.autosave()->isFailing());

        // Closed meanwhile, the window keeps the session in a scene file in the temporary
        // folder instead of losing it.
        const QByteArray tmp = qgetenv("TMPDIR");
        qputenv("TMPDIR", QFile::encodeName(m_dir.path()));
        window.close();
        if (tmp.isEmpty())
            qunsetenv("TMPDIR");
        else
            qputenv("TMPDIR", tmp);
        const QStringList kept = QDir(m_dir.path()).entryList({"lightbench-unsaved-*.json"});
        QCOMPARE(kept.size(), 1);
        const SceneFileRead read = readSceneFile(m_dir.filePath(kept[0]));
        QVERIFY2(read.file, qPrintable(read.error));
        QCOMPARE(read.file->scene.objects[0].material.shininess, 78.0f);
        window.show();

        // The way cleared, the retry keeps the work without another edit, and says so.
        QVERIFY(QFile::remove(blocker));
        QTRY_VERIFY_WITH_TIMEOUT(!window.autosave()->isFailing(),
                                 SettingsAutosave::kRetryMs + 3000);
        QVERIFY2(window.statusLine()->message().contains("saved again"),
                 qPrintable(window.statusLine()->message()));
        // Read as bytes: another QSettings on this file would answer from the first one's cache.
        QFile disk(path);
        QVERIFY(disk.open(QIODevice::ReadOnly));
        const QByteArray ini = disk.readAll();
        const QRegularExpression shininess("shininess\\\\*\"?\\s*:\\s*78\\b");
        QVERIFY2(shininess.match(QString::fromUtf8(ini)).hasMatch(), ini.left(2000).constData());
    }
};

LB_WINDOW_TEST_MAIN(TestWindowScenes)
#include "test_window_scenes.moc"
