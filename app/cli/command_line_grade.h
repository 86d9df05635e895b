#pragma once
// --grade's options (grade.h), read into `cl`: "--option: what is wrong" when one is bad.

#include "command_line.h"

#include <QCommandLineParser>

namespace lb {

QString parseGradeOptions(const QCommandLineParser &parser, CommandLine &cl);

} // namespace lb
