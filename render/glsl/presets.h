#pragma once
// The programs of the editor's Presets menu, kept as .vert/.frag pairs in shaders/ and
// compiled into the resources.

#include <QString>

#include <optional>
#include <vector>

namespace lb {

struct Preset
{
    // The preset's key, in English: scene files and settings name the program by it (data,
    // never translated). The menu shows title().
    QString name;
    QString resource; // ":/shaders/NAME" without the .vert/.frag suffix
    // The course model the program computes, where its text fixes it: Gouraud (true) or
    // Phong shading, and the specular model by its word ("blinn", lighting_models.h); none
    // where it follows a uniform or is a model of its own (toon). The probe's reference and
    // the panels follow these.
    std::optional<bool> gouraud{};
    const char *specular = nullptr;
    // The text computes V = (0,0,1), the parallel view vector, whatever the projection.
    bool parallelView = false;
    QString vertexSource() const;
    QString fragmentSource() const;
    // The name as the window shows it, translated in the context lb::Presets.
    QString title() const;
};

const std::vector<Preset> &presets();
// The built-in program of a shading mode: "phong" or "gouraud".
const Preset &builtInPreset(bool gouraud);
// The preset of that menu name; nullptr for none.
const Preset *presetNamed(const QString &name);
// Whether the pair is one of the presets as shipped (ours, known to draw in good time: no
// trial needed before it draws).
bool isPresetProgram(const QString &vertexSource, const QString &fragmentSource);

} // namespace lb
