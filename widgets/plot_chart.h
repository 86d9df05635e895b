#pragma once
// A Plot (plots.h) as a Qt Charts chart: the Plots panel shows it and --plot draws it into a
// PNG or SVG. Names are translated, colours are the probe's (model_colours.h), the probed
// point's values are dots on their curves, and the lobe is a polar chart with the surface
// across its middle and N up.

#include "plots.h"

#include <QFont>
#include <QSize>
#include <QString>

class QChart;

namespace lb {

// "Specular factor against the angle from the mirror direction" and the like; translated.
QString plotTitle(PlotKind kind);
// Why nothing is drawn (PlotGap::None: empty); translated, or English (the command line's).
QString plotGapText(PlotGap gap, bool translated = true);
// A series' name in the legend: "Phong (R·V)^6", "Light 2", "Ambient"...
QString plotSeriesName(const Plot &plot, const PlotSeries &series);

// A new chart for `plot` (the caller owns it), its texts in `font` and its lines as thick as
// that font asks, for a projector as for a panel.
QChart *makePlotChart(const Plot &plot, const QFont &font);
// The chart's title with its details broken into lines of at most `width` pixels: Qt Charts
// elides a title wider than the chart ("Blinn-Phong (N·H)^n; das..." in a narrow panel).
void fitPlotTitle(QChart *chart, int width);

// The chart at `size` into `path`: SVG where the name ends in .svg, else PNG; written through
// the safe writer. Returns an empty string, or what went wrong.
QString writePlotImage(const Plot &plot, QSize size, const QString &path, const QFont &font);

} // namespace lb
