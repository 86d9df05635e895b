// --plot KIND and --plot-data FILE.csv, read apart from the scene options of command_line.cpp:
// which options go with a plot, and where it goes.
#include "command_line_plot.h"

#include "message_text.h"
#include "safe_write.h"

namespace lb {

QString parsePlotOptions(const QCommandLineParser &parser, CommandLine &cl)
{
    const auto given = [&](const char *name) { return parser.isSet(QString::fromLatin1(name)); };
    const auto value = [&](const char *name) { return parser.value(QString::fromLatin1(name)); };
    const auto bad = [](const char *option, const QString &what) {
        return QString("--%1: %2").arg(QLatin1String(option), what);
    };
    if (given("plot-data") && !given("plot"))
        return bad("plot-data", "goes with --plot KIND");
    const bool svg = cl.renderPath.endsWith(QLatin1String(".svg"), Qt::CaseInsensitive);
    if (!given("plot"))
        return svg ? bad("render", "a frame is written as PNG; an SVG goes with --plot KIND")
                   : QString();
    const QString word = value("plot");
    cl.plot = plotKindFromName(word);
    if (!cl.plot)
        return bad("plot", QString("unknown value '%1' (expected %2)")
                               .arg(echoedValue(word, 80), plotKindNames().join('|')));
    // A plot is drawn instead of a frame: the frame's own modes have nothing to do.
    for (const char *option : {"bench-frames", "bench-edits", "check", "screenshot"})
        if (given(option))
            return bad(option, "does not go with --plot (a plot draws no frame)");
    if (given("plot-data")) {
        cl.plotDataPath = value("plot-data");
        if (cl.plotDataPath.isEmpty())
            return bad("plot-data", "needs a file name");
        if (const QString why = unwritableTarget(cl.plotDataPath); !why.isEmpty())
            return bad("plot-data", why);
    }
    if (cl.renderPath.isEmpty() && cl.plotDataPath.isEmpty())
        return bad("plot", "needs --render FILE.png|FILE.svg or --plot-data FILE.csv");
    return {};
}

} // namespace lb
