#pragma once
// The scene's choices in the window's words. toName() (scene.h) gives the words files, JSON
// and the command line use, which are data and never translated; the window puts its own,
// translatable words into its sentences. In English they are the same words, so English
// users see what they saw before; translators get each name, and the status line's phrases
// whole (a German "im Kamerasystem" is not "im" + a name for "camera").

#include "scene.h"

#include <QString>

namespace lb {

// The status line's description of what draws: "Program: toon.vert, Phong specular (R·V)  |
// point light in the world frame  |  perspective projection". `builtInProgram`: the editor
// shows a built-in program, which follows the Shading panel (flat, Show, specular choice);
// `readsLight`: the program reads the scene's light (else it has its own, marker hidden).
QString statusDescription(const Scene &scene, const QString &programName, bool builtInProgram,
                          bool readsLight);

} // namespace lb
