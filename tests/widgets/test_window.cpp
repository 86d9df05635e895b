// The main window driven as a user drives it: a control moves, the scene changes, and the
// viewport draws something different. Settings are kept in a temporary file.
#include "color_edit.h"
#include "editor_panel.h"
#include "light_panel.h"
#include "load_progress.h"
#include "main_window.h"
#include "material_panel.h"
#include "mesh_actions.h"
#include "object_loader.h"
#include "object_panel.h"
#include "offscreen.h"
#include "presets.h"
#include "probe_panel.h"
#include "recent_files.h"
#include "scene_actions.h"
#include "shader_editor.h"
#include "shading_panel.h"
#include "uniform_panel.h"
#include "viewport.h"

#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QListWidget>
#include <QMenu>
#include <QMessageBox>
#include <QMimeData>
#include <QMouseEvent>
#include <QProcess>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QSlider>
#include <QSpinBox>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QTest>

#include <csignal>

using namespace lb;

namespace {
const QString kCube = "/usr/share/assimp/models/PLY/cube.ply";
const QString kMalformed = "/usr/share/assimp/models/invalid/malformed.obj";

int imageDifference(const QImage &a, const QImage &b)
{
    if (a.size() != b.size())
        return 255;
    int worst = 0;
    for (int y = 0; y < a.height(); y += 2)
        for (int x = 0; x < a.width(); x += 2) {
            const QRgb p = a.pixel(x, y), q = b.pixel(x, y);
            worst = std::max({worst, std::abs(qRed(p) - qRed(q)), std::abs(qGreen(p) - qGreen(q)),
                              std::abs(qBlue(p) - qBlue(q))});
        }
    return worst;
}
} // namespace

class TestWindow : public QObject
{
    Q_OBJECT
private:
    QTemporaryDir m_dir;
    std::unique_ptr<QSettings> m_settings;
    std::unique_ptr<MainWindow> m_window;

    const Scene &scene() { return m_window->document().scene(); }
    QImage frame()
    {
        QCoreApplication::processEvents();
        return m_window->viewport()->grabFramebuffer();
    }
    // Runs `change` and checks that the viewport's image changed with it.
    template <typename F> void expectNewImage(F &&change, const char *what)
    {
        const QImage before = frame();
        change();
        const QImage after = frame();
        QVERIFY2(imageDifference(before, after) > 10, what);
    }
    // Opens a mesh as File > Open Mesh does; returns what the loader said.
    std::pair<bool, QString> openMesh(const QString &path)
    {
        QSignalSpy finished(m_window->objectLoader(), &ObjectLoader::loadFinished);
        m_window->meshActions()->open(path);
        if (finished.isEmpty() && !finished.wait(30000))
            return {false, "no answer"};
        QCoreApplication::processEvents();
        return {finished.first()[0].toBool(), finished.first()[1].toString()};
    }

private slots:
    void init()
    {
        m_settings =
            std::make_unique<QSettings>(m_dir.filePath("settings.ini"), QSettings::IniFormat);
        m_settings->clear();
        m_window = std::make_unique<MainWindow>(*m_settings);
        m_window->show();
        m_window->activateWindow(); // shortcuts only reach the active window
        QVERIFY(QTest::qWaitForWindowActive(m_window.get()));
        QVERIFY2(m_window->viewport()->renderError().isEmpty(),
                 qPrintable(m_window->viewport()->renderError()));
    }

    void cleanup() { m_window.reset(); }

    void savedSceneOpensAsTheSameImage()
    {
        // A scene with a program of the student's own, two lights and a changed camera.
        m_window->editorPanel()->loadPreset(presets().back()); // toon
        m_window->document().edit([](Scene &s) {
            s.lights[1].enabled = true;
            s.material.kd = {0.2f, 0.5f, 0.9f};
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
        m_window->document().edit([](Scene &s) { s.material.shininess = 77; });
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
        QCOMPARE(scene().material.shininess, limits::kMinShininess);
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
        }
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

    void materialColourChangesSceneAndPixels()
    {
        ColorEdit *kd = m_window->materialPanel()->colorEdit(1);
        expectNewImage([&] { kd->channel(1)->setValue(1.0); }, "Kd green");
        QCOMPARE(scene().material.kd, glm::vec3(1, 1, 0));
    }

    void shininessSliderIsLogarithmic()
    {
        QSlider *slider = m_window->materialPanel()->shininessSlider();
        expectNewImage([&] { slider->setValue(MaterialPanel::kSliderSteps / 2); }, "shininess");
        // Half way on a log scale from 1 to 1000 is about 31.6.
        QVERIFY(std::abs(scene().material.shininess - 31.62f) < 0.1f);
        QVERIFY(std::abs(m_window->materialPanel()->shininessBox()->value() - 31.6) < 0.1);
        m_window->materialPanel()->shininessBox()->setValue(1000);
        QCOMPARE(slider->value(), MaterialPanel::kSliderSteps);
    }

    void shadingChoicesChangeSceneAndPixels()
    {
        ShadingPanel *p = m_window->shadingPanel();
        expectNewImage([&] { p->shadingCombo()->setCurrentIndex(0); }, "Gouraud");
        QCOMPARE(scene().shading.shading, Shading::Gouraud);
        expectNewImage([&] { p->specularCombo()->setCurrentIndex(0); }, "Phong specular");
        QCOMPARE(scene().shading.specular, SpecularModel::Phong);
        expectNewImage([&] { p->projectionCombo()->setCurrentIndex(1); }, "orthographic");
        QCOMPARE(scene().shading.projection, Projection::Orthographic);
        expectNewImage([&] { p->textureCheck()->setChecked(true); }, "texture");
        QVERIFY(scene().shading.texture);
        expectNewImage([&] { p->vertexColorsCheck()->setChecked(true); }, "vertex colours");
        expectNewImage([&] { p->lightingCheck()->setChecked(false); }, "lighting off");
        QVERIFY(!scene().shading.lighting);
    }

    void lightControlsChangeSceneAndPixels()
    {
        LightPanel *p = m_window->lightPanel();
        expectNewImage([&] { p->coordinate(0)->setValue(-2.0); }, "light x");
        QCOMPARE(scene().lights[0].position.x, -2.0f);
        expectNewImage([&] { p->wCombo()->setCurrentIndex(1); }, "directional");
        QCOMPARE(scene().lights[0].position.w, 0.0f);
        expectNewImage([&] { p->frameCombo()->setCurrentIndex(0); }, "camera frame");
        QCOMPARE(scene().lights[0].frame, LightFrame::Camera);
        // The model is not transformed yet, so object and world frame agree until it turns.
        m_window->objectPanel()->rotation(1)->setValue(90);
        expectNewImage([&] { p->frameCombo()->setCurrentIndex(2); }, "object frame");
        QCOMPARE(scene().lights[0].frame, LightFrame::Object);
        expectNewImage([&] { p->colorEdit(2)->channel(0)->setValue(0.0); }, "Is red");
        QCOMPARE(scene().lights[0].colors.is.r, 0.0f);

        // Light 3: its own values in the same controls; switching it on adds its light.
        p->setCurrentLight(2);
        QVERIFY(!p->enabledCheck()->isChecked());
        QCOMPARE(p->coordinate(0)->value(), double(defaultLights()[2].position.x));
        expectNewImage([&] { p->enabledCheck()->setChecked(true); }, "light 3 on");
        QVERIFY(scene().lights[2].enabled);
        expectNewImage([&] { p->coordinate(1)->setValue(1.0); }, "light 3 y");
        QCOMPARE(scene().lights[2].position.y, 1.0f);
        QCOMPARE(scene().lights[0].position.x, -2.0f); // light 1 kept its own
        p->setCurrentLight(0);
        QCOMPARE(p->coordinate(0)->value(), -2.0);
    }

    void objectControlsChangeSceneAndPixels()
    {
        ObjectPanel *p = m_window->objectPanel();
        expectNewImage([&] { p->shapeCombo()->setCurrentIndex(0); }, "cube");
        QCOMPARE(scene().object.shape, Shape::Cube);
        QVERIFY(!p->tessellationBox()->isEnabled());
        expectNewImage([&] { p->scale(0)->setValue(0.5); }, "scale x");
        QCOMPARE(scene().object.scale.x, 0.5f);
        expectNewImage([&] { p->rotation(1)->setValue(45); }, "rotate y");
        p->shapeCombo()->setCurrentIndex(1);
        expectNewImage([&] { p->tessellationBox()->setValue(64); }, "tessellation");
        QCOMPARE(scene().object.tessellation, 64);
    }

    void autoRotateTurnsTheModelAndTheSessionIsStillSaved()
    {
        m_window->objectPanel()->autoRotateCheck()->setChecked(true);
        QTRY_VERIFY(scene().object.rotationDegrees.y > 3.0f);
        // While it turns, the scene still reaches the settings (a kill loses little).
        QTRY_VERIFY(m_settings->value("scene").toByteArray().contains("\"autoRotate\": true"));
        m_window->objectPanel()->autoRotateCheck()->setChecked(false);
    }

    void keysToggleShading()
    {
        m_window->viewport()->setFocus();
        QTest::keyClick(m_window.get(), Qt::Key_G);
        QCOMPARE(scene().shading.shading, Shading::Gouraud);
        QCOMPARE(m_window->shadingPanel()->shadingCombo()->currentIndex(), 0);
        QTest::keyClick(m_window.get(), Qt::Key_B);
        QCOMPARE(scene().shading.specular, SpecularModel::Phong);
        QTest::keyClick(m_window.get(), Qt::Key_P);
        QCOMPARE(scene().shading.projection, Projection::Orthographic);
    }

    void mouseOrbitsZoomsAndResetsTheCamera()
    {
        Viewport *v = m_window->viewport();
        const float yaw = scene().camera.yawDegrees;
        const QPointF a(100, 100), b(160, 100);
        QMouseEvent press(QEvent::MouseButtonPress, a, v->mapToGlobal(a), Qt::LeftButton,
                          Qt::LeftButton, Qt::NoModifier);
        QMouseEvent move(QEvent::MouseMove, b, v->mapToGlobal(b), Qt::NoButton, Qt::LeftButton,
                         Qt::NoModifier);
        expectNewImage(
            [&] {
                QApplication::sendEvent(v, &press);
                QApplication::sendEvent(v, &move);
            },
            "orbit");
        QVERIFY(std::abs(scene().camera.yawDegrees - yaw) > 10.0f);
        const float distance = scene().camera.distance;
        QWheelEvent wheel(QPointF(50, 50), v->mapToGlobal(QPointF(50, 50)), QPoint(),
                          QPoint(0, 240), Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
        QApplication::sendEvent(v, &wheel);
        QVERIFY(scene().camera.distance < distance);
        QTest::keyClick(m_window.get(), Qt::Key_R);
        QCOMPARE(scene().camera.yawDegrees, OrbitCamera{}.yawDegrees);
        QCOMPARE(scene().camera.distance, OrbitCamera{}.distance);
    }

    void settingsSurviveARestart()
    {
        m_window->shadingPanel()->shadingCombo()->setCurrentIndex(0);
        m_window->materialPanel()->shininessBox()->setValue(77);
        m_window->lightPanel()->frameCombo()->setCurrentIndex(0);
        const Scene before = scene();
        m_window->close(); // saves
        m_window = std::make_unique<MainWindow>(*m_settings);
        QVERIFY(scene() == before);
        QCOMPARE(m_window->materialPanel()->shininessBox()->value(), 77.0);
        QCOMPARE(m_window->shadingPanel()->shadingCombo()->currentIndex(), 0);
    }

    void editorStartsWithTheProgramOnScreen()
    {
        EditorPanel *e = m_window->editorPanel();
        QVERIFY(e->source(ShaderStage::Fragment).contains("uSpecularModel")); // built-in Phong
        QTRY_VERIFY(e->statusLabel()->text().contains("linked"));
        // G switches to Gouraud: the untouched built-in follows.
        QTest::keyClick(m_window.get(), Qt::Key_G);
        QTRY_VERIFY(e->source(ShaderStage::Vertex).contains("fAmbientDiffuse"));
    }

    void anErrorKeepsTheLastGoodProgramUntilFixed()
    {
        EditorPanel *e = m_window->editorPanel();
        Viewport *v = m_window->viewport();
        // Both stages in WebGL 1, so that line numbers cross the implicit "#version 100".
        e->loadPreset(presets()[3]);
        QVERIFY(e->source(ShaderStage::Vertex).contains("attribute vec4 vPosition"));
        QTRY_VERIFY(e->statusLabel()->text().contains("linked"));
        const QImage good = frame();
        ShaderEditor *fragment = e->editor(ShaderStage::Fragment);
        const QString original = fragment->text();

        // A typo on the editor's line 5 of a WebGL 1 shader (no #version).
        const QString broken = "precision mediump float;\n"
                               "uniform vec3 materialDif; // the Material panel's Kd\n"
                               "void main()\n"
                               "{\n"
                               "    gl_FragColor = vec4(materialDif * 0.5, 1.0)\n"
                               "}\n";
        fragment->setText(broken); // live: compiles after the pause
        QTRY_VERIFY(e->statusLabel()->text().contains("error"));
        QVERIFY(!v->banner().isEmpty());
        QCOMPARE(fragment->markedLineCount(), 1);
        QVERIFY(fragment->annotation(5).contains("error")); // 0-based: line 6, the brace
        QVERIFY(e->diagnosticsList()->count() >= 1);
        QVERIFY(e->diagnosticsList()->item(0)->text().contains("fragment 6:"));
        // Below the banner strip at the top, the picture is exactly the last good one.
        const QRect belowBanner(0, 40, good.width(), good.height() - 40);
        QVERIFY2(imageDifference(frame().copy(belowBanner), good.copy(belowBanner)) == 0,
                 "the last good program must keep drawing");
        QCOMPARE(fragment->text(), broken); // the user's text is untouched

        // Clicking the message goes to its line.
        e->diagnosticsList()->setCurrentRow(0);
        emit e->diagnosticsList()->itemClicked(e->diagnosticsList()->item(0));
        int line = 0, column = 0;
        fragment->getCursorPosition(&line, &column);
        QCOMPARE(line, 5);

        // The fix brings the new program with no other action: half-bright flat red.
        fragment->insertAt(";", 4, fragment->text(4).indexOf(")\n") + 1);
        QTRY_VERIFY(e->statusLabel()->text().contains("linked"));
        QVERIFY(v->banner().isEmpty());
        QCOMPARE(fragment->markedLineCount(), 0);
        const QImage fixed = frame();
        const QRgb centre = fixed.pixel(fixed.width() / 2, fixed.height() / 2);
        QVERIFY(std::abs(qRed(centre) - 128) <= 1 && qGreen(centre) == 0);
        fragment->setText(original);
    }

    void manualCompileWithCtrlEnter()
    {
        EditorPanel *e = m_window->editorPanel();
        e->liveCheck()->setChecked(false);
        ShaderEditor *fragment = e->editor(ShaderStage::Fragment);
        QTRY_VERIFY(e->statusLabel()->text().contains("linked"));
        // The built-in vertex stage is GLSL 330 core; the fragment must be too to link.
        fragment->setText("#version 330 core\nout vec4 c;\nvoid main() { c = vec4(0.0, 1.0, 0.0, "
                          "1.0); }\n");
        QTest::qWait(400); // past any pause: nothing compiles by itself
        QRgb centre = frame().pixel(frame().width() / 2, frame().height() / 2);
        QVERIFY(qGreen(centre) != 255);
        e->findChild<QTabWidget *>()->setCurrentWidget(fragment); // typing happens in a shown tab
        fragment->setFocus();
        QTest::keyClick(fragment, Qt::Key_Return, Qt::ControlModifier);
        QTRY_VERIFY(qGreen(frame().pixel(frame().width() / 2, frame().height() / 2)) == 255);
        e->liveCheck()->setChecked(true);
    }

    void presetsLoadAndDraw()
    {
        EditorPanel *e = m_window->editorPanel();
        QCOMPARE(e->presetsMenu()->actions().size(), int(presets().size()));
        for (QAction *a : e->presetsMenu()->actions()) {
            const QImage before = frame();
            a->trigger();
            QTRY_VERIFY2(e->statusLabel()->text().contains("linked"), qPrintable(a->text()));
            QVERIFY(e->diagnosticsList()->count() == 0);
            Q_UNUSED(before);
        }
        // The toon preset draws something the built-in does not.
        e->presetsMenu()->actions().first()->trigger();
        QTRY_VERIFY(e->statusLabel()->text().contains("linked"));
        expectNewImage([&] { e->presetsMenu()->actions().last()->trigger(); }, "toon");
    }

    void ownUniformsGetControlsThatSurviveRecompiles()
    {
        EditorPanel *e = m_window->editorPanel();
        e->loadPreset(presets().back()); // toon: bands, rimWidth, outlineColour
        QTRY_VERIFY(e->statusLabel()->text().contains("linked"));
        UniformPanel *u = m_window->uniformPanel();
        QCOMPARE(u->controlCount(), 3);
        QVERIFY(u->findChild<ColorEdit *>()); // outlineColour gets a colour picker
        // The control starts from the shader's initializer.
        QList<QDoubleSpinBox *> boxes;
        for (QDoubleSpinBox *b : u->findChildren<QDoubleSpinBox *>())
            if (b->toolTip().isEmpty() && b->parentWidget()->toolTip().contains("float bands"))
                boxes << b;
        QCOMPARE(boxes.size(), 1);
        QCOMPARE(boxes[0]->value(), 3.0);
        expectNewImage([&] { boxes[0]->setValue(6.0); }, "six bands");
        QCOMPARE(scene().shaderValues.at("bands"), std::vector<float>{6.0f});

        // A recompile (a comment added) keeps the value, in the scene and on screen.
        const QImage six = frame();
        ShaderEditor *fragment = e->editor(ShaderStage::Fragment);
        fragment->append("\n// edited\n");
        e->compileNow();
        QTRY_VERIFY(e->statusLabel()->text().contains("linked"));
        QCOMPARE(imageDifference(frame(), six), 0);
        QCOMPARE(scene().shaderValues.at("bands"), std::vector<float>{6.0f});
    }

    void controlsTheProgramDoesNotReadAreMarkedUnused()
    {
        EditorPanel *e = m_window->editorPanel();
        ShadingPanel *shading = m_window->shadingPanel();
        // The slides' Gouraud shader hard-codes its material as constants.
        e->loadPreset(presets()[2]);
        QTRY_VERIFY(e->statusLabel()->text().contains("linked"));
        ColorEdit *kd = m_window->materialPanel()->colorEdit(1);
        QVERIFY(!kd->isEnabled());
        QVERIFY(kd->toolTip().contains("materialDif"));
        QVERIFY(kd->toolTip().startsWith("Unused"));
        QVERIFY(!shading->specularCombo()->isEnabled());
        QVERIFY(m_window->lightPanel()->coordinate(0)->isEnabled() == false); // a const too
        // The built-in program reads them all.
        e->loadPreset(builtInPreset(false));
        QTRY_VERIFY(kd->isEnabled());
        QVERIFY(shading->specularCombo()->isEnabled());
        QVERIFY(!kd->toolTip().startsWith("Unused"));
    }

    void saveAsWritesThePairAndSaveClearsTheMarker()
    {
        EditorPanel *e = m_window->editorPanel();
        QTabWidget *tabs = e->findChild<QTabWidget *>();
        ShaderEditor *fragment = e->editor(ShaderStage::Fragment);
        fragment->append("// mine\n");
        const QString base = m_dir.filePath("pair");
        QCOMPARE(e->saveAs(base + ".frag"), QString());
        for (const char *suffix : {".vert", ".frag"}) {
            QFile f(base + suffix);
            QVERIFY(f.open(QIODevice::ReadOnly));
            const ShaderStage stage =
                QByteArray(suffix) == ".vert" ? ShaderStage::Vertex : ShaderStage::Fragment;
            QCOMPARE(QString::fromUtf8(f.readAll()), e->source(stage));
        }
        QVERIFY(tabs->tabText(1).contains("pair.frag"));
        QVERIFY(!tabs->tabText(1).contains('*'));
        fragment->append("// more\n");
        QVERIFY(tabs->tabText(1).endsWith('*') || tabs->tabText(1).contains("* "));
        QCOMPARE(e->save(), QString());
        QVERIFY(!tabs->tabText(1).contains('*'));
        QVERIFY(!e->isModified());
        // A file that cannot be written gives a message and keeps the text.
        const QString text = e->source(ShaderStage::Vertex);
        QVERIFY(!e->saveAs("/nonexistent/dir/x.vert").isEmpty());
        QCOMPARE(e->source(ShaderStage::Vertex), text);
    }

    void openFindsThePartnerAndFollowsTheDisk()
    {
        const Preset &slides = presets()[3];
        const QString vert = m_dir.filePath("lecture.vert"), frag = m_dir.filePath("lecture.frag");
        auto write = [](const QString &path, const QString &text) {
            QFile f(path);
            QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
            f.write(text.toUtf8());
        };
        write(vert, slides.vertexSource());
        write(frag, slides.fragmentSource());
        EditorPanel *e = m_window->editorPanel();
        QCOMPARE(e->openFiles({frag}), QString()); // the .vert comes along
        QCOMPARE(e->filePath(ShaderStage::Vertex), QFileInfo(vert).absoluteFilePath());
        QCOMPARE(e->source(ShaderStage::Vertex), slides.vertexSource());
        QTRY_VERIFY(e->statusLabel()->text().contains("linked"));

        // Another editor changes the file: the unmodified tab follows and recompiles.
        const QString greener = slides.fragmentSource().replace(
            "gl_FragColor = vec4(ambientColor + diffuse + specular, 1.0);",
            "gl_FragColor = vec4(0.0, 1.0, 0.0, 1.0);");
        write(frag, greener);
        QTRY_COMPARE(e->source(ShaderStage::Fragment), greener);
        QTRY_VERIFY(qGreen(frame().pixel(frame().width() / 2, frame().height() / 2)) == 255);

        // With unsaved edits in the tab, the disk does not overwrite them.
        e->editor(ShaderStage::Fragment)->append("// my edit\n");
        const QString mine = e->source(ShaderStage::Fragment);
        write(frag, slides.fragmentSource());
        QTRY_VERIFY(e->statusLabel()->text().contains("changed on disk"));
        QCOMPARE(e->source(ShaderStage::Fragment), mine);

        QVERIFY(e->openFiles({m_dir.filePath("missing.vert")}).contains("Cannot open"));
        QCOMPARE(e->source(ShaderStage::Fragment), mine);
    }

    void unsavedEditsComeBackAfterARestart()
    {
        EditorPanel *e = m_window->editorPanel();
        e->editor(ShaderStage::Vertex)->append("// unsaved work\n");
        // Autosaved within half a second, without closing the window (as before a kill).
        QTRY_VERIFY(m_settings->value("editor/vertex").toString().contains("// unsaved work"));
        const QString text = e->source(ShaderStage::Vertex);
        m_window.reset(); // no close event: like a crash, nothing more is written
        m_window = std::make_unique<MainWindow>(*m_settings);
        QCOMPARE(m_window->editorPanel()->source(ShaderStage::Vertex), text);
        QVERIFY(m_window->editorPanel()->isModified());
    }

    void completionOffersGlslWordsAndTheFilesNames()
    {
        EditorPanel *e = m_window->editorPanel();
        ShaderEditor *fragment = e->editor(ShaderStage::Fragment);
        e->liveCheck()->setChecked(false);
        e->findChild<QTabWidget *>()->setCurrentWidget(fragment);
        fragment->setText("uniform float myShininess;\nvoid main() { float x = my");
        fragment->setCursorPosition(1, fragment->text(1).size());
        fragment->setFocus();
        QTest::keyClicks(fragment, "S");
        QVERIFY(fragment->isListActive());
        QTest::keyClick(fragment, Qt::Key_Return);
        QVERIFY2(fragment->text(1).endsWith("myShininess"), qPrintable(fragment->text(1)));
        QTest::keyClicks(fragment, " + normali");
        QVERIFY(fragment->isListActive());
        QTest::keyClick(fragment, Qt::Key_Return);
        QVERIFY2(fragment->text(1).endsWith("normalize"), qPrintable(fragment->text(1)));
        e->liveCheck()->setChecked(true);
    }

    void editorsComeAndGoWithoutCrashing()
    {
        // QScintilla's QsciAPIs prepared completion on a thread that crashed when the editor
        // went first; the editors must survive being made and dropped at once.
        for (int i = 0; i < 30; ++i) {
            ShaderEditor editor;
            editor.setText("void main() {}\n");
        }
    }

    void openedMeshIsDrawnAndDescribed()
    {
        const QImage sphere = frame();
        const auto [ok, message] = openMesh(kCube);
        QVERIFY2(ok, qPrintable(message));
        QCOMPARE(scene().object.meshPath, kCube);
        QVERIFY(imageDifference(sphere, frame()) > 10);
        const QString summary = m_window->meshActions()->summaryLabel()->toolTip();
        QVERIFY2(summary.startsWith("cube.ply: ") && summary.contains("triangles") &&
                     summary.contains("loaded in"),
                 qPrintable(summary));
        QCOMPARE(m_window->objectPanel()->shapeCombo()->currentText(), QString("File: cube.ply"));
        QCOMPARE(m_window->meshActions()->recent()->files().value(0), kCube);
        // A built-in shape is one click away.
        m_window->objectPanel()->shapeCombo()->setCurrentIndex(int(Shape::Torus));
        QVERIFY(scene().object.meshPath.isEmpty());
        QTRY_VERIFY(m_window->meshActions()->summaryLabel()->text().startsWith("torus: "));
        // The status bar has the short form; the whole summary is the tooltip.
        QVERIFY(!m_window->meshActions()->summaryLabel()->text().contains("vertices"));
        QVERIFY(m_window->meshActions()->summaryLabel()->toolTip().contains("vertices"));
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
        QCOMPARE(scene().object.meshPath, kCube);
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
        QVERIFY(scene().object.showNormals);
        QCOMPARE(started.count(), 0);
    }

    void slowLoadShowsProgressAndCancelStopsTheHelper()
    {
        const QString helper = m_dir.filePath("slow-helper.sh");
        QFile f(helper);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("#!/bin/sh\nexec sleep 600\n");
        f.close();
        f.setPermissions(QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner);
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
        QCOMPARE(scene().material.shininess, 12.0f);
        QTest::mouseClick(progress->cancelButton(), Qt::LeftButton);
        QTRY_COMPARE(finished.count(), 1);
        QVERIFY(!progress->isVisible());
        QVERIFY(::kill(pid_t(pid), 0) != 0); // the helper is gone
        QCOMPARE(scene().object.meshPath, before.object.meshPath);
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
        QCOMPARE(scene().object.meshPath, kCube);
    }

    void meshComesBackAfterARestart()
    {
        QVERIFY(openMesh(kCube).first);
        m_window->close(); // saves
        m_window = std::make_unique<MainWindow>(*m_settings);
        QCOMPARE(scene().object.meshPath, kCube);
        QTRY_VERIFY(m_window->objectLoader()->file() &&
                    m_window->objectLoader()->file()->path == kCube);
        // A file gone since then: the shape comes back, with a message.
        m_window->close();
        const QByteArray saved = m_settings->value("scene").toByteArray();
        m_settings->setValue("scene", QByteArray(saved).replace(kCube.toUtf8(), "/gone/away.ply"));
        m_window = std::make_unique<MainWindow>(*m_settings);
        QTRY_VERIFY(scene().object.meshPath.isEmpty());
        QTRY_VERIFY(m_window->meshActions()->errorBox());
        QVERIFY(m_window->meshActions()->errorBox()->informativeText().contains("/gone/away.ply"));
    }

    void resetButtonsRestoreDefaults()
    {
        m_window->materialPanel()->shininessBox()->setValue(500);
        const auto buttons = m_window->materialPanel()->findChildren<QPushButton *>();
        QCOMPARE(buttons.size(), 1);
        buttons.first()->click();
        QCOMPARE(scene().material.shininess, Material{}.shininess);
    }
};

int main(int argc, char **argv)
{
    setDefaultGlFormat();
    QApplication app(argc, argv);
    TestWindow test;
    return QTest::qExec(&test, argc, argv);
}
#include "test_window.moc"
