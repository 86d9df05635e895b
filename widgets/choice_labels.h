#pragma once
// The scene's choices as the window writes them inside its sentences ("gouraud shading", "the
// camera frame"), translated. toName() (scene.h) gives the same words for files, JSON and the
// command line, which stay English: a choice shown to the user goes through these instead.

#include "scene.h"

#include <QString>

namespace lb {

QString frameLabel(LightFrame frame);
QString shadingLabel(Shading shading);
QString specularLabel(SpecularModel specular);
QString showLabel(ShowChoice show); // what the surface shows instead of the lit colour

} // namespace lb
