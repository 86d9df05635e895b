#include "plot_output.h"

#include "grading_files.h"
#include "plot_chart.h"
#include "safe_write.h"

#include <QApplication>

#include <algorithm>

namespace lb {

int writePlotOutputs(const CommandLine &cl, const Scene &scene, const ProbeResult *probe)
{
    const Plot plot = computePlot(*cl.plot, scene, probe);
    if (const QString gap = plotGapText(plot.gap, false); !gap.isEmpty()) // stderr: English
        printLine("lightbench: --plot " + plotKindName(plot.kind) + ": " + gap, stderr);
    if (!cl.plotDataPath.isEmpty())
        if (const QString error = writeFileSafely(cl.plotDataPath, plotCsv(plot));
            !error.isEmpty()) {
            printLine("lightbench: --plot-data: cannot write " + error, stderr);
            return 1;
        }
    if (!cl.renderPath.isEmpty()) {
        // Text a fortieth of the picture's height: readable on a slide at any --size.
        QFont font = QApplication::font();
        font.setPixelSize(std::max(11, cl.size.height() / 40));
        if (const QString error = writePlotImage(plot, cl.size, cl.renderPath, font);
            !error.isEmpty()) {
            printLine("lightbench: --render: cannot write " + error, stderr);
            return 1;
        }
    }
    return 0;
}

} // namespace lb
