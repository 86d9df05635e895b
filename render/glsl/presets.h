#pragma once
// The programs of the editor's Presets menu, kept as .vert/.frag pairs in shaders/ and
// compiled into the resources.

#include <QString>

#include <vector>

namespace lb {

struct Preset
{
    QString name;     // as the menu shows it
    QString resource; // ":/shaders/NAME" without the .vert/.frag suffix
    QString vertexSource() const;
    QString fragmentSource() const;
};

const std::vector<Preset> &presets();
// The built-in program of a shading mode: "phong" or "gouraud".
const Preset &builtInPreset(bool gouraud);

} // namespace lb
