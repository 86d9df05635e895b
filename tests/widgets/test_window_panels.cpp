// The panels, keys and mouse: a control moves, the scene changes, the picture follows;
// the session survives a restart.
#include "window_fixture.h"

#include "frames.h"
#include "probe_panel.h"
#include "texture_controls.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDropEvent>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMimeData>
#include <QPushButton>
#include <QToolButton>

using namespace lb;
using namespace lb::test;

class TestWindowPanels : public WindowTest
{
    Q_OBJECT
private slots:
    void materialColourChangesSceneAndPixels()
    {
        ColorEdit *kd = m_window->materialPanel()->colorEdit(1);
        expectNewImage([&] { kd->channel(1)->setValue(1.0); }, "Kd green");
        QCOMPARE(scene().objects[0].material.kd, glm::vec3(1, 1, 0));
    }

    void shininessSliderIsLogarithmic()
    {
        QSlider *slider = m_window->materialPanel()->shininessSlider();
        expectNewImage([&] { slider->setValue(MaterialPanel::kSliderSteps / 2); }, "shininess");
        // Half way on a log scale from 1 to 1000 is about 31.6.
        QVERIFY(std::abs(scene().objects[0].material.shininess - 31.62f) < 0.1f);
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
        expectNewImage(
            [&] { m_window->objectPanel()->texture()->textureCheck()->setChecked(true); },
            "texture");
        QVERIFY(scene().objects[0].texture);
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

    // Issue 15's controls: terms, Show, attenuation and spot, each reaching the pixels; the
    // spot's axis and exponent apply only to a spot; an attenuation of 0, 0, 0 is refused and
    // the panel shows the value that holds.
    void modelControlsChangeSceneAndPixels()
    {
        ShadingPanel *sp = m_window->shadingPanel();
        expectNewImage([&] { sp->termCheck(2)->setChecked(false); }, "specular off");
        QVERIFY(!scene().shading.terms.specular);
        expectNewImage([&] { sp->showCombo()->setCurrentIndex(1); }, "show N");
        QCOMPARE(scene().shading.show, ShowChoice::Normal);
        sp->showCombo()->setCurrentIndex(0);
        sp->lightingCheck()->setChecked(false);
        QVERIFY(!sp->termCheck(0)->isEnabled()); // terms of an unlit surface
        sp->lightingCheck()->setChecked(true);
        QVERIFY(sp->termCheck(0)->isEnabled());

        LightPanel *p = m_window->lightPanel();
        QVERIFY(!p->spotAxis(0)->isEnabled() && !p->spotExponent()->isEnabled());
        expectNewImage([&] { p->spotCutoff()->setValue(20.0); }, "spot");
        QCOMPARE(scene().lights[0].spot.cutoffDegrees, 20.0f);
        QVERIFY(p->spotAxis(0)->isEnabled() && p->spotExponent()->isEnabled());
        expectNewImage([&] { p->attenuation(1)->setValue(1.0); }, "kl 1");
        QCOMPARE(scene().lights[0].attenuation, glm::vec3(1.0f, 1.0f, 0.0f));
        p->attenuation(0)->setValue(0.0);
        p->attenuation(1)->setValue(0.0); // all three 0: refused
        QCOMPARE(scene().lights[0].attenuation, glm::vec3(0.0f, 1.0f, 0.0f));
        QCOMPARE(p->attenuation(1)->value(), 1.0);

        // The wheel over a spin box not clicked first scrolls the panel, not the value.
        QDoubleSpinBox *kc = p->attenuation(0);
        const double before = kc->value();
        m_window->viewport()->setFocus();
        const QPointF at(kc->width() / 2.0, kc->height() / 2.0);
        QWheelEvent wheel(at, kc->mapToGlobal(at), QPoint(), QPoint(0, 120), Qt::NoButton,
                          Qt::NoModifier, Qt::NoScrollPhase, false);
        QCoreApplication::sendEvent(kc, &wheel);
        QCOMPARE(kc->value(), before);
        kc->setFocus();
        QWheelEvent focused(at, kc->mapToGlobal(at), QPoint(), QPoint(0, 120), Qt::NoButton,
                            Qt::NoModifier, Qt::NoScrollPhase, false);
        QCoreApplication::sendEvent(kc, &focused);
        QVERIFY(kc->value() != before); // clicked first: the wheel edits it
    }

    // Issue 28: under a German or Portuguese default locale, 2.5 typed into the light's x is
    // two and a half (German read the point as a thousands separator: 25), and so is 2,5;
    // the boxes show the locale's comma; text with both separators moves nothing.
    void typedNumbersAreReadAsMeant_data()
    {
        QTest::addColumn<QString>("locale");
        QTest::addColumn<QString>("typed");
        for (const char *locale : {"de_DE", "pt_PT"})
            for (const char *typed : {"2.5", "2,5"})
                QTest::addRow("%s %s", locale, typed) << locale << typed;
    }
    void typedNumbersAreReadAsMeant()
    {
        QFETCH(QString, locale);
        QFETCH(QString, typed);
        struct Restore
        {
            QLocale old;
            ~Restore() { QLocale::setDefault(old); }
        } restore;
        QLocale::setDefault(QLocale(locale));
        cleanup();
        init(); // a window made under that default, as a German desktop makes it
        const auto type = [](QAbstractSpinBox *box, const QString &text) {
            box->setFocus();
            box->selectAll();
            QTest::keyClicks(box, text);
            QTest::keyClick(box, Qt::Key_Return);
        };
        const auto shown = [](QAbstractSpinBox *box) {
            return box->findChild<QLineEdit *>()->text();
        };

        QDoubleSpinBox *x = m_window->lightPanel()->coordinate(0);
        type(x, typed);
        QCOMPARE(scene().lights[0].position.x, 2.5f);
        QCOMPARE(shown(x), QString("2,50"));
        type(x, "1.000,5"); // neither 1000.5 nor 10005 nor 1
        QCOMPARE(scene().lights[0].position.x, 2.5f);
        QCOMPARE(shown(x), QString("1.000,5")); // kept as typed, in red with the reason

        QDoubleSpinBox *green = m_window->materialPanel()->colorEdit(1)->channel(1);
        type(green, QString(typed).replace('2', '0')); // 0.5 or 0,5
        QCOMPARE(scene().objects[0].material.kd.g, 0.5f);
        QCOMPARE(shown(green), QString("0,50"));

        QSpinBox *tessellation = m_window->objectPanel()->tessellationBox();
        const int subdivisions = scene().objects[0].tessellation;
        type(tessellation, "2.5"); // a whole number: neither 25 nor 2
        QCOMPARE(scene().objects[0].tessellation, subdivisions);
        QCOMPARE(shown(tessellation), QString("2.5"));
    }

    void objectControlsChangeSceneAndPixels()
    {
        ObjectPanel *p = m_window->objectPanel();
        expectNewImage([&] { p->shapeCombo()->setCurrentIndex(0); }, "cube");
        QCOMPARE(scene().objects[0].shape, Shape::Cube);
        QVERIFY(!p->tessellationBox()->isEnabled());
        expectNewImage([&] { p->scale(0)->setValue(0.5); }, "scale x");
        QCOMPARE(scene().objects[0].scale.x, 0.5f);
        expectNewImage([&] { p->rotation(1)->setValue(45); }, "rotate y");
        p->shapeCombo()->setCurrentIndex(1);
        expectNewImage([&] { p->tessellationBox()->setValue(64); }, "tessellation");
        QCOMPARE(scene().objects[0].tessellation, 64);
    }

    // An image opened (as File > Open Texture Image or a drop does) is drawn once decoded;
    // the sampling controls edit the selected object and change the pixels; a file that is
    // no image leaves the scene as it was and says so; x goes back to the checker.
    void textureImageAndSampling()
    {
        QImage image(512, 512, QImage::Format_RGB32);
        for (int y = 0; y < 512; ++y)
            for (int x = 0; x < 512; ++x)
                image.setPixel(x, y, (x / 2 + y / 2) % 2 ? qRgb(250, 250, 250) : qRgb(10, 60, 10));
        const QString path = m_dir.filePath("fine.png");
        QVERIFY(image.save(path));
        TextureControls *t = m_window->objectPanel()->texture();
        t->textureCheck()->setChecked(true);
        const QImage checker = frame();
        // A point probed on the checker follows the image when it comes in.
        Viewport *v = m_window->viewport();
        QTest::mouseClick(v, Qt::LeftButton, Qt::ControlModifier, v->rect().center());
        frame();
        ProbePanel *probe = m_window->probePanel();
        QVERIFY(probe->isActive());
        const glm::vec3 checkerBase = probe->result().base;
        m_window->meshActions()->openImage(path);
        QTRY_COMPARE(scene().objects[0].textureFile, path);
        QTRY_VERIFY(imageDifference(checker, frame()) > 10);
        QVERIFY(probe->isActive());
        QVERIFY(probe->result().base != checkerBase);
        frame();
        QVERIFY(probe->gpuColour());
        const glm::vec3 ref = probe->result().reference * 255.0f;
        for (int c = 0; c < 3; ++c)
            QVERIFY2(std::abs((*probe->gpuColour())[c] - int(std::lround(ref[c]))) <= 2,
                     qPrintable(probe->textLabel()->text()));
        QTest::keyClick(m_window.get(), Qt::Key_Escape);
        QCOMPARE(t->imageLabel()->text(), QString("fine.png"));
        // 2-texel stripes on the sphere: minified, so mipmaps and the filter show.
        expectNewImage([&] { t->mipmapsCheck()->setChecked(true); }, "mipmaps");
        QVERIFY(scene().objects[0].sampling.mipmaps);
        expectNewImage([&] { t->filterCombo()->setCurrentIndex(0); }, "nearest");
        QCOMPARE(scene().objects[0].sampling.filter, TextureFilter::Nearest);
        t->wrapCombo()->setCurrentIndex(1);
        QCOMPARE(scene().objects[0].sampling.wrap, TextureWrap::Clamp);

        const QString notAnImage = m_dir.filePath("notes.png");
        QFile notes(notAnImage);
        QVERIFY(notes.open(QIODevice::WriteOnly) && notes.write("vec3 n;\n") > 0);
        notes.close();
        const Scene before = scene();
        m_window->meshActions()->openImage(notAnImage);
        QTRY_VERIFY(m_window->meshActions()->errorBox());
        QVERIFY2(m_window->meshActions()->errorBox()->informativeText().contains("notes.png"),
                 qPrintable(m_window->meshActions()->errorBox()->informativeText()));
        QVERIFY(scene() == before);

        t->clearButton()->click();
        QVERIFY(scene().objects[0].textureFile.isEmpty());
        QCOMPARE(t->imageLabel()->text(), QString("the checker"));

        // An image the scene names that is missing stays named, and the panel says so.
        const QString gone = m_dir.filePath("gone.png");
        m_window->document().edit([&](Scene &s) { s.objects[0].textureFile = gone; });
        QTRY_COMPARE(t->imageLabel()->text(), QString("gone.png (not shown)"));
        QCOMPARE(scene().objects[0].textureFile, gone);
    }

    // An image dropped on an object is that object's texture (it becomes the selected one).
    void anImageDroppedOnAnObjectTexturesThatOne()
    {
        m_window->document().edit([](Scene &s) {
            s.objects.resize(2);
            s.objects[0].translation.x = -1.3f;
            s.objects[1].translation.x = 1.3f;
            s.selected = 0;
            s.showLight = false;
        });
        frame();
        QImage image(16, 16, QImage::Format_RGB32);
        image.fill(Qt::yellow);
        const QString path = m_dir.filePath("yellow.png");
        QVERIFY(image.save(path));
        // Where object 1's centre is drawn, in the window's coordinates.
        Viewport *v = m_window->viewport();
        const QSize size = v->size() * v->devicePixelRatio();
        const Frames f = computeFrames(scene(), float(size.width()) / float(size.height()), 1);
        const glm::vec2 p =
            pixelOf(f, glm::vec3(f.modelView[3]), float(size.width()), float(size.height()));
        const QPoint at =
            v->mapTo(m_window.get(), (QPointF(p.x, p.y) / v->devicePixelRatio()).toPoint());
        QMimeData mime;
        mime.setUrls({QUrl::fromLocalFile(path)});
        QDragEnterEvent enter(at, Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
        QApplication::sendEvent(m_window.get(), &enter); // Qt drops only where a drag entered
        QDropEvent drop(QPointF(at), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
        QApplication::sendEvent(m_window.get(), &drop);
        QCOMPARE(scene().selected, 1);
        QTRY_COMPARE(scene().objects[1].textureFile, path);
        QVERIFY(scene().objects[0].textureFile.isEmpty());
    }

    // The list: Add draws a second object and selects it (the Material panel edits its
    // material), a click on the first in the view selects that one, Remove takes it away.
    void objectListAddsSelectsAndRemoves()
    {
        ObjectPanel *p = m_window->objectPanel();
        QVERIFY(!p->removeButton()->isEnabled()); // the last object stays
        expectNewImage([&] { p->addButton()->click(); }, "second object");
        QCOMPARE(int(scene().objects.size()), 2);
        QCOMPARE(scene().selected, 1);
        QCOMPARE(p->objectList()->count(), 2);
        QCOMPARE(p->objectList()->currentRow(), 1);
        expectNewImage([&] { m_window->materialPanel()->colorEdit(1)->channel(1)->setValue(1.0); },
                       "second object's Kd");
        QCOMPARE(scene().objects[1].material.kd.g, 1.0f);
        QCOMPARE(scene().objects[0].material.kd, Material{}.kd);
        expectNewImage([&] { p->translation(1)->setValue(1.0); }, "moved up");
        QCOMPARE(scene().objects[1].translation.y, 1.0f);

        // A click on the first object's centre selects it.
        Viewport *view = m_window->viewport();
        const QSize frame = view->size() * view->devicePixelRatio();
        const Frames f = computeFrames(scene(), float(frame.width()) / float(frame.height()), 0);
        const glm::vec2 centre =
            pixelOf(f, glm::vec3(f.modelView[3]), float(frame.width()), float(frame.height()));
        const QPoint at = (QPointF(centre.x, centre.y) / view->devicePixelRatio()).toPoint();
        QTest::mouseClick(view, Qt::LeftButton, Qt::NoModifier, at);
        QTRY_COMPARE(scene().selected, 0);
        QCOMPARE(p->objectList()->currentRow(), 0);
        QCOMPARE(m_window->materialPanel()->colorEdit(1)->color(), Material{}.kd);

        // Hidden by its tick, then renamed and removed.
        expectNewImage([&] { p->objectList()->item(1)->setCheckState(Qt::Unchecked); }, "hidden");
        QVERIFY(!scene().objects[1].visible);
        p->objectList()->item(1)->setText("moon");
        QCOMPARE(scene().objects[1].name, plainText("moon"));
        p->objectList()->setCurrentRow(1);
        QCOMPARE(scene().selected, 1);
        p->removeButton()->click();
        QCOMPARE(int(scene().objects.size()), 1);
        QCOMPARE(p->objectList()->count(), 1);
        QVERIFY(!p->removeButton()->isEnabled());
    }

    void autoRotateTurnsTheModelAndTheSessionIsStillSaved()
    {
        m_window->objectPanel()->autoRotateCheck()->setChecked(true);
        QTRY_VERIFY(scene().objects[0].rotationDegrees.y > 3.0f);
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
        QTest::keyClick(m_window.get(), Qt::Key_B, Qt::ControlModifier); // B blanks the screen
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

    void resetButtonsRestoreDefaults()
    {
        m_window->materialPanel()->shininessBox()->setValue(500);
        const auto buttons = m_window->materialPanel()->findChildren<QPushButton *>();
        QCOMPARE(buttons.size(), 1);
        buttons.first()->click();
        QCOMPARE(scene().objects[0].material.shininess, Material{}.shininess);
    }
};

LB_WINDOW_TEST_MAIN(TestWindowPanels)
#include "test_window_panels.moc"
