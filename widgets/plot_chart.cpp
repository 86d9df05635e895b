#include "plot_chart.h"

#include "model_colours.h"
#include "safe_write.h"

#include <QBuffer>
#include <QCoreApplication>
#include <QFontMetrics>
#include <QGraphicsScene>
#include <QPainter>
#include <QSvgGenerator>
#include <QtCharts/QCategoryAxis>
#include <QtCharts/QChart>
#include <QtCharts/QLegendMarker>
#include <QtCharts/QLineSeries>
#include <QtCharts/QPolarChart>
#include <QtCharts/QScatterSeries>
#include <QtCharts/QValueAxis>

#include <algorithm>
#include <cmath>

namespace lb {

namespace {

const QColor kBackground(30, 32, 38);
const QColor kGrid(80, 84, 96);
const QColor kText(225, 228, 235);
const QColor kSurface(150, 150, 150);

QString number(float v)
{
    return QString::number(double(v), 'g', 4);
}

QColor seriesColour(const PlotSeries &s)
{
    switch (s.role) {
    case PlotRole::Ambient:
        return colours::toQColor(colours::kAmbient);
    case PlotRole::Diffuse:
        return colours::toQColor(colours::kDiffuse);
    case PlotRole::Specular:
        if (const SpecularModelRow *model = specularModelOfCurve(s.key))
            return colours::toQColor(model->curveColour);
        return colours::toQColor(colours::kSpecular);
    case PlotRole::Light:
        return colours::toQColor(colours::lightArrow(s.lightDiffuse));
    case PlotRole::Direction:
        if (s.key == QLatin1String("V"))
            return colours::toQColor(colours::kView);
        if (s.key == QLatin1String("R"))
            return colours::toQColor(colours::kMirror);
        return colours::toQColor(colours::lightArrow(s.lightDiffuse));
    }
    return kText;
}

// The lines' width: a sixth of the text's height, so a projector's larger text gets bolder
// curves.
double lineWidth(const QFont &font)
{
    return std::max(2.0, QFontMetricsF(font).height() / 6.0);
}

QPen seriesPen(const PlotSeries &s, const QFont &font)
{
    QPen pen(seriesColour(s), lineWidth(font));
    // Lights of one colour (white by default) still tell apart: each light its own dashes.
    const Qt::PenStyle byLight[] = {Qt::SolidLine, Qt::DashLine, Qt::DotLine, Qt::DashDotLine};
    if (s.dashed)
        pen.setStyle(Qt::DashLine);
    else if (s.role == PlotRole::Light)
        pen.setStyle(byLight[std::clamp(s.light, 0, 3)]);
    if (s.role == PlotRole::Direction)
        pen.setWidthF(pen.widthF() * 0.75);
    return pen;
}

void styleAxis(QAbstractAxis *axis, const QString &title, const QFont &font)
{
    axis->setTitleText(title);
    QFont titleFont = font;
    titleFont.setBold(false);
    axis->setTitleFont(titleFont);
    axis->setLabelsFont(font);
    axis->setTitleBrush(kText);
    axis->setLabelsColor(kText);
    axis->setGridLineColor(kGrid);
    axis->setLinePenColor(kGrid);
}

// The polar chart's angle for an angle of V from N: N up (0), towards L clockwise to 90,
// away from L anticlockwise to 270 (-90).
qreal polarAngle(float degrees)
{
    return degrees < 0.0f ? 360.0 + double(degrees) : double(degrees);
}

void hideFromLegend(QChart *chart, QAbstractSeries *series)
{
    for (QLegendMarker *m : chart->legend()->markers(series))
        m->setVisible(false);
}

// A dot's colour: its curve's, or where the probed point has several lights' dots, its
// light's (the colour of that light's L arrow over the surface).
QColor markerColour(const Plot &plot, const PlotMarker &m)
{
    for (const PlotMarker &other : plot.markers)
        if (other.light != m.light)
            return colours::toQColor(colours::lightArrow(m.lightDiffuse));
    return seriesColour(plot.series[std::size_t(m.series)]);
}

// A dot of light `light`: each light its own shape, since two lights of one hue (light 1's
// grey and light 4's) get one colour.
QScatterSeries *markerSeries(const QColor &colour, const QFont &font, int light)
{
    auto *dots = new QScatterSeries;
    const QScatterSeries::MarkerShape shapes[] = {
        QScatterSeries::MarkerShapeCircle, QScatterSeries::MarkerShapeRectangle,
        QScatterSeries::MarkerShapeTriangle, QScatterSeries::MarkerShapeRotatedRectangle};
    dots->setMarkerShape(shapes[std::clamp(light, 0, 3)]);
    dots->setMarkerSize(QFontMetricsF(font).height() * 0.6);
    dots->setColor(colour);
    dots->setBorderColor(Qt::white);
    return dots;
}

// `series` into `chart` on axes `a` and `b`, left out of the legend unless `inLegend`.
void attach(QChart *chart, QAbstractSeries *series, QAbstractAxis *a, QAbstractAxis *b,
            bool inLegend)
{
    chart->addSeries(series);
    series->attachAxis(a);
    series->attachAxis(b);
    if (!inLegend)
        hideFromLegend(chart, series);
}

// The probed point's dots, at `x(mark's x)` along axis `a`.
template <typename X>
void addMarks(QChart *chart, const Plot &plot, const QFont &font, QAbstractAxis *a,
              QAbstractAxis *b, X x)
{
    for (const PlotMarker &m : plot.markers) {
        QScatterSeries *dot = markerSeries(markerColour(plot, m), font, m.light);
        dot->append(x(m.at.x), double(m.at.y));
        attach(chart, dot, a, b, false);
    }
}

void addCartesian(QChart *chart, const Plot &plot, const QFont &font)
{
    auto *x = new QValueAxis;
    auto *y = new QValueAxis;
    x->setRange(plot.xMin, plot.xMax);
    const bool angle = plot.kind != PlotKind::Attenuation;
    x->setTickCount(angle ? 7 : 6);
    x->setLabelFormat("%g");
    // Factors run 0 to 1; an attenuation with kc under 1 rises above it (up to 10 shown).
    float top = 1.0f;
    for (const PlotSeries &s : plot.series)
        for (const glm::vec2 &p : s.points)
            top = std::max(top, std::min(p.y, 10.0f));
    y->setRange(0.0, double(top));
    y->setTickCount(6);
    if (top > 1.0f)
        y->applyNiceNumbers();
    y->setLabelFormat("%g");
    chart->addAxis(x, Qt::AlignBottom);
    chart->addAxis(y, Qt::AlignLeft);
    const char *xTitle[] = {QT_TRANSLATE_NOOP("lb::PlotChart", "Angle between R and V (°)"),
                            QT_TRANSLATE_NOOP("lb::PlotChart", "Angle between N and L (°)"),
                            QT_TRANSLATE_NOOP("lb::PlotChart", "Distance d from the light"),
                            QT_TRANSLATE_NOOP("lb::PlotChart", "Angle from the spot's axis (°)")};
    const char *yTitle[] = {QT_TRANSLATE_NOOP("lb::PlotChart", "Specular factor"), "max(N·L, 0)",
                            "1 / (kc + kl·d + kq·d²)",
                            QT_TRANSLATE_NOOP("lb::PlotChart", "Spot factor")};
    const int k = int(plot.kind);
    styleAxis(x, QCoreApplication::translate("lb::PlotChart", xTitle[k]), font);
    styleAxis(y, QCoreApplication::translate("lb::PlotChart", yTitle[k]), font);
    for (const PlotSeries &s : plot.series) {
        auto *line = new QLineSeries;
        line->setName(plotSeriesName(plot, s));
        for (const glm::vec2 &p : s.points)
            line->append(double(p.x), double(p.y));
        attach(chart, line, x, y, true);
        line->setPen(seriesPen(s, font));
    }
    addMarks(chart, plot, font, x, y, [](float v) { return double(v); });
}

void addPolar(QPolarChart *chart, const Plot &plot, const QFont &font)
{
    auto *angle = new QCategoryAxis;
    angle->setRange(0, 360);
    angle->setLabelsPosition(QCategoryAxis::AxisLabelsPositionOnValue);
    for (int a : {0, 30, 60, 90})
        angle->append(QString("%1°").arg(a), a);
    for (int a : {270, 300, 330})
        angle->append(QString("%1°").arg(a - 360), a);
    auto *radius = new QValueAxis;
    float reach = 0.0f;
    for (const PlotSeries &s : plot.series)
        for (const glm::vec2 &p : s.points)
            reach = std::max(reach, p.y);
    radius->setRange(0.0, double(reach > 0.0f ? reach : 1.0f));
    radius->setTickCount(5);
    radius->applyNiceNumbers();
    radius->setLabelFormat("%g");
    chart->addAxis(angle, QPolarChart::PolarOrientationAngular);
    chart->addAxis(radius, QPolarChart::PolarOrientationRadial);
    styleAxis(angle, {}, font);
    styleAxis(radius, {}, font);
    const auto add = [&](QLineSeries *line, const QPen &pen, bool inLegend) {
        attach(chart, line, angle, radius, inLegend);
        line->setPen(pen);
    };
    // The surface: the horizontal line through the point.
    for (qreal a : {90.0, 270.0}) {
        auto *surface = new QLineSeries;
        surface->setName(QCoreApplication::translate("lb::PlotChart", "Surface"));
        surface->append(a, 0.0);
        surface->append(a, radius->max());
        add(surface, QPen(kSurface, lineWidth(font) * 1.5), false); // plain to see
    }
    for (const PlotSeries &s : plot.series) {
        // Each curve in two halves that meet at N: a line across 0/360 would go round.
        auto *towardsL = new QLineSeries;
        auto *awayFromL = new QLineSeries;
        towardsL->setName(plotSeriesName(plot, s));
        for (const glm::vec2 &p : s.points) {
            if (p.x >= 0.0f)
                towardsL->append(double(p.x), double(p.y));
            if (p.x <= 0.0f)
                awayFromL->append(polarAngle(p.x) == 0.0 ? 360.0 : polarAngle(p.x), double(p.y));
        }
        const QPen pen = seriesPen(s, font);
        // The legend names the terms; the rays L, R and V carry their names at their tips,
        // as the arrows over the surface do (a narrow panel's legend has no room for seven).
        const bool ray = s.role == PlotRole::Direction;
        add(towardsL, pen, !ray);
        add(awayFromL, pen, false);
        if (ray) {
            auto *tip = new QScatterSeries;
            tip->append(polarAngle(s.points.back().x), double(s.points.back().y));
            tip->setMarkerSize(1.0);
            tip->setColor(Qt::transparent);
            tip->setBorderColor(Qt::transparent);
            tip->setPointLabelsFormat(plotSeriesName(plot, s));
            QFont bold = font;
            bold.setBold(true);
            tip->setPointLabelsFont(bold);
            tip->setPointLabelsColor(seriesColour(s));
            tip->setPointLabelsClipping(false);
            tip->setPointLabelsVisible(true);
            attach(chart, tip, angle, radius, false);
        }
    }
    addMarks(chart, plot, font, angle, radius, polarAngle);
}

} // namespace

QString plotTitle(PlotKind kind)
{
    // A short first line (a narrow panel elides the rest) and the details under it.
    switch (kind) {
    case PlotKind::Specular:
        return QCoreApplication::translate(
            "lb::PlotChart", "Specular factor<br><small>Phong (R·V)^n, Blinn-Phong (N·H)^n; "
                             "dashed: Blinn-Phong at 4n</small>");
    case PlotKind::Diffuse:
        return QCoreApplication::translate(
            "lb::PlotChart", "Diffuse factor<br><small>against the angle of incidence</small>");
    case PlotKind::Attenuation:
        return QCoreApplication::translate(
            "lb::PlotChart", "Attenuation<br><small>against the distance from the light</small>");
    case PlotKind::Spot:
        return QCoreApplication::translate(
            "lb::PlotChart", "Spotlight factor<br><small>against the angle from its axis</small>");
    case PlotKind::Lobe:
        return QCoreApplication::translate(
            "lb::PlotChart", "The three terms as V sweeps<br><small>the plane of incidence, N "
                             "up; radius: the mean of red, green and blue</small>");
    }
    return {};
}

QString plotGapText(PlotGap gap, bool translated)
{
    static const char *const texts[] = {
        "",
        QT_TRANSLATE_NOOP("lb::PlotChart", "No point light is on: a directional light (w = 0) "
                                           "is not attenuated."),
        QT_TRANSLATE_NOOP("lb::PlotChart", "No spotlight: every light that is on has a cutoff "
                                           "of 180°. Set a cutoff in the Light panel."),
        QT_TRANSLATE_NOOP("lb::PlotChart", "No light is on."),
        QT_TRANSLATE_NOOP("lb::PlotChart", "No lobe: the light is at the surface's point, where "
                                           "L has no direction. Move the light off the surface.")};
    const char *text = texts[int(gap)];
    if (!*text)
        return {};
    return translated ? QCoreApplication::translate("lb::PlotChart", text)
                      : QString::fromUtf8(text);
}

QString plotSeriesName(const Plot &plot, const PlotSeries &s)
{
    // Short: the legend of a narrow panel has a row for them all. The title names the models.
    const QString &k = s.key;
    const SpecularPlotCurve *curve = nullptr;
    if (const SpecularModelRow *model = specularModelOfCurve(k, &curve))
        return QString("(%1)^%2").arg(QString::fromUtf8(model->angle),
                                      number(curve->exponentTimes * plot.shininess));
    if (k == QLatin1String("ambient"))
        return QCoreApplication::translate("lb::PlotChart", "Ambient");
    if (k == QLatin1String("diffuse"))
        return plot.kind == PlotKind::Lobe ? QCoreApplication::translate("lb::PlotChart", "Diffuse")
                                           : QStringLiteral("max(N·L, 0)");
    if (k == QLatin1String("specular"))
        return QCoreApplication::translate("lb::PlotChart", "Specular");
    if (s.role == PlotRole::Light)
        return QCoreApplication::translate("lb::PlotChart", "Light %1").arg(s.light + 1);
    return k; // L, R, V
}

void fitPlotTitle(QChart *chart, int width)
{
    // plotTitle()'s form: a first line, then the details in <small> (measured in the title's
    // own bold font: a little wider than they are drawn, so a line never overflows).
    const QString title = chart->property("lbTitle").toString();
    const int details = int(title.indexOf(QLatin1String("<br><small>")));
    if (details < 0 || !title.endsWith(QLatin1String("</small>"))) {
        chart->setTitle(title);
        return;
    }
    const QFontMetrics metrics(chart->titleFont());
    const int room = std::max(width - 16, metrics.averageCharWidth() * 8);
    const QString words = title.mid(details + 11, title.size() - details - 11 - 8);
    QStringList lines{QString()};
    for (const QString &word : words.split(QLatin1Char(' '), Qt::SkipEmptyParts)) {
        const QString longer = lines.last().isEmpty() ? word : lines.last() + ' ' + word;
        if (!lines.last().isEmpty() && metrics.horizontalAdvance(longer) > room)
            lines << word;
        else
            lines.last() = longer;
    }
    chart->setTitle(title.left(details) + "<br><small>" + lines.join("<br>") + "</small>");
}

QChart *makePlotChart(const Plot &plot, const QFont &font)
{
    QChart *chart = plot.polar ? new QPolarChart : new QChart;
    chart->setAnimationOptions(QChart::NoAnimation);
    chart->setBackgroundBrush(kBackground);
    chart->setPlotAreaBackgroundVisible(false);
    chart->setBackgroundRoundness(0);
    chart->setMargins(QMargins(4, 4, 4, 4));
    QFont title = font;
    title.setBold(true);
    chart->setTitleFont(title);
    chart->setTitleBrush(kText);
    chart->setProperty("lbTitle", plotTitle(plot.kind)); // fitPlotTitle() breaks its lines
    chart->setTitle(plotTitle(plot.kind));
    chart->legend()->setFont(font);
    chart->legend()->setLabelColor(kText);
    chart->legend()->setAlignment(Qt::AlignBottom);
    if (plot.polar)
        addPolar(static_cast<QPolarChart *>(chart), plot, font);
    else
        addCartesian(chart, plot, font);
    return chart;
}

QString writePlotImage(const Plot &plot, QSize size, const QString &path, const QFont &font)
{
    QGraphicsScene scene;
    QChart *chart = makePlotChart(plot, font);
    scene.addItem(chart); // the scene owns it
    chart->resize(size);
    fitPlotTitle(chart, size.width());
    scene.setSceneRect(QRectF(QPointF(0, 0), size));
    const QRectF area(QPointF(0, 0), size);
    if (path.endsWith(QLatin1String(".svg"), Qt::CaseInsensitive)) {
        QBuffer svg;
        svg.open(QIODevice::WriteOnly);
        QSvgGenerator generator;
        generator.setOutputDevice(&svg);
        generator.setSize(size);
        generator.setViewBox(area);
        generator.setTitle(QStringLiteral("lightbench --plot %1").arg(plotKindName(plot.kind)));
        QPainter painter(&generator);
        scene.render(&painter, area, area);
        painter.end();
        return writeFileSafely(path, svg.data());
    }
    QImage image(size, QImage::Format_RGB32);
    image.fill(kBackground);
    QPainter painter(&image);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setRenderHint(QPainter::TextAntialiasing);
    scene.render(&painter, area, area);
    painter.end();
    return writeImageSafely(path, image);
}

} // namespace lb
