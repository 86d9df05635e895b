#pragma once
// The options that change the scene, read into CommandLine::sceneOverrides
// (command_line_scene.cpp).

#include "command_line.h"

#include <QCommandLineParser>

namespace lb {

// Throws options::BadOption (option_values.h) on the first bad one.
void parseSceneOptions(const QCommandLineParser &parser, CommandLine &cl);

} // namespace lb
