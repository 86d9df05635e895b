// The Plots panel in the window: it follows the material and the lights as they move, marks
// the probed point's own values, draws the lobe as a polar chart, says why a plot is empty,
// exports PNG, SVG and CSV (and refuses a FIFO and a missing folder, leaving them as they
// were), and keeps the chosen plot across a restart.
#include "window_fixture.h"

#include "plot_chart.h"
#include "plots_panel.h"

#include <QDockWidget>
#include <QFontMetrics>
#include <QRegularExpression>
#include <QXmlStreamReader>
#include <QtCharts/QChart>
#include <QtCharts/QChartView>
#include <QtCharts/QLineSeries>
#include <QtCharts/QPolarChart>
#include <QtCharts/QScatterSeries>
#include <glm/trigonometric.hpp>

#include <sys/stat.h>

using namespace lb;
using namespace lb::test;

namespace {

const PlotSeries *seriesNamed(const Plot &plot, const char *key)
{
    for (const PlotSeries &s : plot.series)
        if (s.key == QLatin1String(key))
            return &s;
    return nullptr;
}

// The chart's line named `name` (its legend's), or null.
QLineSeries *lineNamed(QChart *chart, const QString &name)
{
    for (QAbstractSeries *s : chart->series())
        if (auto *line = qobject_cast<QLineSeries *>(s);
            line && line->name() == name && !qobject_cast<QScatterSeries *>(s))
            return line;
    return nullptr;
}

} // namespace

class TestWindowPlots : public WindowTest
{
    Q_OBJECT
private:
    PlotsPanel *panel() { return m_window->plotsPanel(); }
    QDockWidget *dock()
    {
        for (QDockWidget *d : m_window->panelDocks())
            if (d->objectName() == "plotsDock")
                return d;
        return nullptr;
    }
    // The Plots tab brought forward, and its chart drawn for what the scene is now.
    void showPlots()
    {
        QVERIFY(dock());
        dock()->show();
        dock()->raise();
        QTRY_VERIFY(panel()->isVisible());
        QTRY_VERIFY(panel()->chartView()->chart() && !panel()->plot().series.empty());
    }

private slots:
    void followsTheShininessAndMarksTheProbedPoint()
    {
        showPlots();
        QCOMPARE(panel()->kind(), PlotKind::Specular);
        QChart *chart = panel()->chartView()->chart();
        QLineSeries *phong = lineNamed(chart, "(R·V)^6");
        QVERIFY2(phong, "no line for Phong at n = 6");
        const double at30 = phong->at(60).y(); // half a degree a sample
        QVERIFY(std::abs(at30 - std::pow(std::cos(M_PI / 6), 6.0)) < 1e-4);

        // The shininess slider halfway: n = 31.6, the curves narrower.
        m_window->materialPanel()->shininessSlider()->setValue(MaterialPanel::kSliderSteps / 2);
        QTRY_VERIFY(std::abs(panel()->plot().shininess - 31.62f) < 0.1f);
        chart = panel()->chartView()->chart();
        phong = nullptr;
        for (QAbstractSeries *s : chart->series())
            if (s->name().startsWith("(R·V)^31.6"))
                phong = qobject_cast<QLineSeries *>(s);
        QVERIFY2(phong, "no line for Phong at n = 31.6");
        QVERIFY(phong->at(60).y() < at30 / 10);
        QCOMPARE(panel()->plot().markers.size(), std::size_t(0));

        // Ctrl+click the sphere: the probe's own N·H is a dot on the Blinn-Phong curve.
        Viewport *v = m_window->viewport();
        QTest::mouseClick(v, Qt::LeftButton, Qt::ControlModifier, v->rect().center());
        QVERIFY(m_window->probePanel()->isActive());
        showPlots(); // probing brought the Probe tab forward
        QTRY_COMPARE(panel()->plot().markers.size(), std::size_t(1));
        const PlotMarker mark = panel()->plot().markers[0];
        const LightingTerms &t = m_window->probePanel()->result().lights.at(0).terms;
        QCOMPARE(mark.at.y, t.specularFactor);
        QCOMPARE(panel()->plot().series[std::size_t(mark.series)].key, QString("blinn"));
        QVERIFY(std::abs(mark.at.x - 2.0f * glm::degrees(std::acos(t.specularAngle))) < 1e-3f);
        int dots = 0;
        for (QAbstractSeries *s : panel()->chartView()->chart()->series())
            if (auto *scatter = qobject_cast<QScatterSeries *>(s)) {
                QCOMPARE(scatter->count(), 1);
                QVERIFY(std::abs(scatter->at(0).y() - double(t.specularFactor)) < 1e-6);
                ++dots;
            }
        QCOMPARE(dots, 1);

        // The light moves: the probed point's angle, and its dot, move with it.
        const float before = mark.at.x;
        m_window->document().edit([](Scene &s) { s.lights[0].position.x = 1.5f; });
        QTRY_VERIFY(std::abs(panel()->plot().markers.at(0).at.x - before) > 1.0f);
        // Esc clears the probe, and the dots go.
        QTest::keyClick(m_window.get(), Qt::Key_Escape);
        QTRY_VERIFY(panel()->plot().markers.empty());
    }

    // Two lights of one hue (light 1's grey, light 4's): their dots differ in shape.
    // Each plot's title whole in the panel a 1024x768 screen leaves: its details broken into
    // lines, none wider than the chart (issue 49, item 19: Qt Charts elided the specular
    // plot's "...; dashed: Blinn-Phong at 4n" to "; das...").
    void titlesAreWholeInANarrowPanel()
    {
        m_window->fitToScreen(QRect(0, 0, 1024, 744));
        showPlots();
        for (PlotKind kind : {PlotKind::Specular, PlotKind::Diffuse, PlotKind::Attenuation,
                              PlotKind::Spot, PlotKind::Lobe}) {
            panel()->setKind(kind);
            QTRY_VERIFY(panel()->chartView()->chart() && panel()->plot().kind == kind);
            QChart *chart = panel()->chartView()->chart();
            QString shown = chart->title();
            const QFontMetrics metrics(chart->titleFont());
            for (QString line : shown.split("<br>")) {
                line.remove(QRegularExpression("<[^>]*>"));
                QVERIFY2(metrics.horizontalAdvance(line) <= panel()->chartView()->width(),
                         qPrintable(line));
            }
            shown.replace("<br>", " ").remove(QRegularExpression("<[^>]*>"));
            QString whole = plotTitle(kind);
            whole.replace("<br>", " ").remove(QRegularExpression("<[^>]*>"));
            QCOMPARE(shown.simplified(), whole.simplified());
        }
    }

    void severalLightsDotsDiffer()
    {
        m_window->document().edit([](Scene &s) { s.lights[3].enabled = true; });
        Viewport *v = m_window->viewport();
        QTest::mouseClick(v, Qt::LeftButton, Qt::ControlModifier, v->rect().center());
        QVERIFY(m_window->probePanel()->isActive());
        showPlots();
        panel()->setKind(PlotKind::Diffuse);
        QTRY_COMPARE(panel()->plot().markers.size(), std::size_t(2));
        QList<QScatterSeries::MarkerShape> shapes;
        for (QAbstractSeries *s : panel()->chartView()->chart()->series())
            if (auto *scatter = qobject_cast<QScatterSeries *>(s))
                shapes << scatter->markerShape();
        QCOMPARE(shapes.size(), 2);
        QVERIFY(shapes[0] != shapes[1]);
    }

    void lobeAndEmptyPlotsSaySo()
    {
        showPlots();
        panel()->setKind(PlotKind::Lobe);
        QTRY_VERIFY(panel()->plot().polar);
        QVERIFY(qobject_cast<QPolarChart *>(panel()->chartView()->chart()));
        QVERIFY2(panel()->noteLabel()->text().contains("Ctrl+click"),
                 qPrintable(panel()->noteLabel()->text()));
        QVERIFY(seriesNamed(panel()->plot(), "specular"));

        panel()->setKind(PlotKind::Attenuation);
        QTRY_COMPARE(panel()->plot().kind, PlotKind::Attenuation);
        QVERIFY(seriesNamed(panel()->plot(), "light1"));
        m_window->document().edit([](Scene &s) { s.lights[0].position.w = 0.0f; });
        QTRY_COMPARE(panel()->plot().gap, PlotGap::NoPointLight);
        QVERIFY2(panel()->noteLabel()->text().contains("No point light"),
                 qPrintable(panel()->noteLabel()->text()));

        panel()->setKind(PlotKind::Spot);
        QTRY_COMPARE(panel()->plot().gap, PlotGap::NoSpotlight);
        m_window->document().edit([](Scene &s) { s.lights[0].spot.cutoffDegrees = 30.0f; });
        QTRY_COMPARE(panel()->plot().gap, PlotGap::None);
        QVERIFY(seriesNamed(panel()->plot(), "light1"));
    }

    void exportsAndRefusesWhatIsNoFile()
    {
        showPlots();
        const QString csv = m_dir.filePath("specular.csv");
        QCOMPARE(panel()->exportTo(csv), QString());
        QFile f(csv);
        QVERIFY(f.open(QIODevice::ReadOnly));
        QVERIFY(f.readLine().startsWith("angle_degrees,phong,blinn,blinn_4n"));
        f.close();
        const QString svg = m_dir.filePath("specular.svg");
        QCOMPARE(panel()->exportTo(svg), QString());
        QFile s(svg);
        QVERIFY(s.open(QIODevice::ReadOnly));
        QXmlStreamReader xml(&s);
        int lines = 0, texts = 0;
        while (!xml.atEnd())
            if (xml.readNext() == QXmlStreamReader::StartElement) {
                lines += xml.name() == u"polyline" || xml.name() == u"path";
                texts += xml.name() == u"text";
            }
        QVERIFY2(!xml.hasError(), qPrintable(xml.errorString()));
        QVERIFY(lines > 3);  // the curves, axes and grid
        QVERIFY(texts > 10); // the title, the axes' titles and labels, the legend
        const QString png = m_dir.filePath("specular.png");
        QCOMPARE(panel()->exportTo(png), QString());
        QCOMPARE(QImage(png).size(), QSize(1200, 900));
        // Export... confirms what it wrote on the status line (issue 49, item 19).
        const QString confirmed = m_dir.filePath("confirmed.png");
        QCOMPARE(panel()->exportAndSay(confirmed), QString());
        QVERIFY(QFileInfo::exists(confirmed));
        QVERIFY2(m_window->statusLine()->message().contains(confirmed),
                 qPrintable(m_window->statusLine()->message()));

        // A FIFO and a folder that is not there: a message, and nothing written.
        const QString fifo = m_dir.filePath("pipe.png");
        QCOMPARE(mkfifo(QFile::encodeName(fifo).constData(), 0600), 0);
        QVERIFY(!panel()->exportTo(fifo).isEmpty());
        QVERIFY(QFileInfo(fifo).exists() && !QFileInfo(fifo).isFile());
        QVERIFY(!panel()->exportTo(m_dir.filePath("missing/plot.csv")).isEmpty());
    }

    void theChosenPlotSurvivesARestart()
    {
        showPlots();
        panel()->kindBox()->setCurrentIndex(panel()->kindBox()->findData(int(PlotKind::Diffuse)));
        QCOMPARE(panel()->kind(), PlotKind::Diffuse);
        m_window->saveSettings();
        m_window.reset();
        m_window = std::make_unique<MainWindow>(*m_settings);
        m_window->show();
        QCOMPARE(panel()->kind(), PlotKind::Diffuse);
    }
};

LB_WINDOW_TEST_MAIN(TestWindowPlots)
#include "test_window_plots.moc"
