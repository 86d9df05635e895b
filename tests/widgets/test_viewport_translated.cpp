// What the view and the Probe panel write goes through Qt's translation system (issue 31), read
// through a translator that marks what it is asked (translation_marks.h): the driver line, the
// banner over a program that did not build, the compare caption and the difference scale's
// numbers, the probe's rows and its equation. The equation is render/'s English (the command
// line prints it, the probe's JSON keeps it): the panel translates its phrases, and a phrase
// render/ rewords shows up here as words left unmarked. The bad inputs tried: a side's name
// glued to a sentence (", side A"), " of 255 (...)" appended to a colour, a choice's file word
// ("gouraud", "camera") shown as it is written to files, a banner made of two clauses, an
// equation with every phrase render/ writes (lighting off, flat and Gouraud shading, a Show
// choice, a term off, a light behind the surface, a texture's base colour, a spotlight).
#include "translation_marks.h"

#include "difference_scale_labels.h"
#include "object_loader.h"
#include "offscreen.h"
#include "probe_panel.h"
#include "viewport.h"

#include <QApplication>
#include <QHBoxLayout>
#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QSignalSpy>
#include <QTest>

using namespace lb;
using namespace lb::test;

class TestViewportTranslated : public QObject
{
    Q_OBJECT
    RecordingTranslator m_translator;
    SceneDocument m_document;
    QWidget m_window;
    Viewport *m_viewport = nullptr;
    ObjectLoader *m_loader = nullptr;
    ProbePanel *m_probe = nullptr;
    QString m_glInfo;

    static void expectNone(const QStringList &found)
    {
        QVERIFY2(found.isEmpty(), qPrintable(found.join('\n')));
    }

    // Applies `change` and waits for the frame it brings (the probe's text follows it).
    bool drawn(const std::function<void(Scene &)> &change)
    {
        QSignalSpy swapped(m_viewport, &QOpenGLWidget::frameSwapped);
        m_document.edit(change);
        return swapped.wait(10000);
    }

    // The probe's rows and equation have no word a translator was not asked for.
    void expectProbeTranslated(const char *state)
    {
        QVERIFY2(m_probe->isActive(), state);
        const QString rows =
            QTextDocumentFragment::fromHtml(m_probe->textLabel()->text()).toPlainText();
        QVERIFY2(!m_probe->equation().isEmpty(), state);
        QStringList found = problems(rows);
        found << problems(m_probe->equation());
        QVERIFY2(found.isEmpty(), qPrintable(QString(state) + ":\n" + found.join('\n')));
    }

private slots:
    void initTestCase()
    {
        // Programs are compiled in this process: no trial helper is needed for a banner.
        qputenv("LIGHTBENCH_PROGRAM_TRIAL", "off");
        QCoreApplication::installTranslator(&m_translator);
        auto *row = new QHBoxLayout(&m_window);
        m_viewport = new Viewport(&m_document, &m_window);
        m_viewport->setFixedSize(480, 360);
        m_probe = new ProbePanel(&m_document, m_viewport, &m_window);
        row->addWidget(m_viewport);
        row->addWidget(m_probe);
        connect(m_viewport, &Viewport::glInfo, this,
                [this](const QString &info) { m_glInfo = info; });
        m_loader = new ObjectLoader(&m_document, this);
        connect(m_loader, &ObjectLoader::meshReady, m_viewport, &Viewport::setObject);
        connect(m_loader, &ObjectLoader::objectCountChanged, m_viewport, &Viewport::setObjectCount);
        m_viewport->setObjectCount(m_loader->objectCount());
        for (int i = 0; i < m_loader->objectCount(); ++i)
            m_viewport->setObject(i, m_loader->mesh(i), m_loader->texture(i));
        QSignalSpy swapped(m_viewport, &QOpenGLWidget::frameSwapped);
        m_window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&m_window));
        QVERIFY(swapped.wait(10000));
        QVERIFY2(m_viewport->renderError().isEmpty(), qPrintable(m_viewport->renderError()));
    }

    void cleanupTestCase() { QCoreApplication::removeTranslator(&m_translator); }

    // The driver line, one sentence around the driver's own words; the banner over a
    // program that does not build, one sentence with what draws instead.
    void driverAndBanner()
    {
        m_viewport->makeCurrent();
        const QString renderer = reinterpret_cast<const char *>(
            QOpenGLContext::currentContext()->functions()->glGetString(GL_RENDERER));
        m_viewport->doneCurrent();
        QVERIFY2(oneSentence(m_glInfo), qPrintable(m_glInfo));
        expectNone(problems(m_glInfo, wordsOf(renderer)));

        m_viewport->compileProgram("#version 330 core\nvoid main() { oops }\n",
                                   "#version 330 core\nvoid main() {}\n");
        const QString banner = m_viewport->banner();
        QVERIFY2(oneSentence(banner), qPrintable(banner));
        expectNone(problems(banner));
        QVERIFY(m_translator.asked(
            "lb::Viewport",
            "The shader has errors (see the editor): the built-in program is drawing"));
    }

    // The compare caption in each view, and the difference scale's numbers and title.
    void compareTexts()
    {
        for (CompareMode mode :
             {CompareMode::SideBySide, CompareMode::Wipe, CompareMode::Difference})
            for (Shading shading : {Shading::Gouraud, Shading::Phong, Shading::Flat}) {
                QVERIFY(drawn([&](Scene &s) {
                    s.compare.mode = mode;
                    s.compare.shading = shading;
                }));
                const QString caption = m_viewport->compareText();
                QVERIFY2(oneSentence(caption), qPrintable(caption));
                expectNone(problems(caption));
            }
        const auto *scale = m_viewport->findChild<DifferenceScaleLabels *>();
        QVERIFY(scale && scale->isVisible());
        for (const DifferenceScaleLabels::Tick &tick : scale->ticks())
            expectNone(problems(tick.text));
        QVERIFY(drawn([](Scene &s) { s.compare.mode = CompareMode::Off; }));
    }

    // The probe at the middle of the view, then with every phrase its equation may write.
    void probe()
    {
        const QPoint middle = QPoint(m_viewport->width() / 2, m_viewport->height() / 2) *
                              m_viewport->devicePixelRatio();
        QSignalSpy swapped(m_viewport, &QOpenGLWidget::frameSwapped);
        m_probe->probeAt(middle);
        QVERIFY(swapped.wait(10000));
        expectProbeTranslated("as the scene starts");

        QVERIFY(drawn([](Scene &s) {
            s.shading.lighting = false;
            s.shading.shading = Shading::Flat;
            s.shading.show = ShowChoice::NDotL;
            s.shading.terms.ambient = false;
            s.selectedObject().texture = true; // the checker: a base colour that is not 1
            Light &behind = s.lights[0];
            behind.frame = LightFrame::Camera;
            behind.position = glm::vec4(0.0f, 0.0f, -20.0f, 1.0f); // N·L < 0 at the middle
            behind.spot.cutoffDegrees = 170.0f;
            s.lights[1].enabled = true;
            s.lights[1].frame = LightFrame::Object;
        }));
        expectProbeTranslated("lighting off, flat, N·L shown, ambient off, textured, spot");
        for (const char *phrase :
             {"Lighting is off: the surface shows Kd times the base colour instead.", "[off]",
              "(0: the light is behind the surface)", "(base multiplies ambient and diffuse only)",
              "The surface shows %1, not this colour.", "light %1: %2",
              "pixel = %1 of 255 (clamped to 0..1)"})
            QVERIFY2(m_translator.asked("lb::ProbeEquation", phrase), phrase);
        QVERIFY(m_translator.asked("lb::ChoiceLabels", "object", "light frame"));
        QVERIFY(m_translator.asked("lb::ChoiceLabels", "ndotl", "show"));

        QVERIFY(drawn([](Scene &s) {
            s.shading.shading = Shading::Gouraud;
            s.compare.mode = CompareMode::SideBySide;
        }));
        expectProbeTranslated("Gouraud, side by side");
        QVERIFY(m_translator.asked("lb::ProbePanel", "pixel (%1, %2), %3, triangle %4, side A"));
        QVERIFY(m_translator.asked("lb::ProbePanel", "%1 of 255 (%2 shading)"));
        QVERIFY(m_translator.asked("lb::ChoiceLabels", "gouraud", "shading"));
        // The vectors' names are symbols, never sent to translators.
        QVERIFY(!m_translator.asked("lb::ProbePanel", "N"));
    }
};

int main(int argc, char **argv)
{
    setDefaultGlFormat(); // before the application, as the window's main() does
    QApplication app(argc, argv);
    TestViewportTranslated test;
    return QTest::qExec(&test, argc, argv);
}

#include "test_viewport_translated.moc"
