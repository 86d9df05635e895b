#pragma once
// --plot's options (plot_output.h), read into `cl`: "--option: what is wrong" when one is bad.

#include "command_line.h"

#include <QCommandLineParser>

namespace lb {

QString parsePlotOptions(const QCommandLineParser &parser, CommandLine &cl);

} // namespace lb
