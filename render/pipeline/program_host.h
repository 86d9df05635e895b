#pragma once
// What the program pipeline needs of the place a program is built and drawn: an OpenGL
// context (the window's, an offscreen one), seen through this GL-free interface. The host
// makes its context current for each call; the pipeline decides, the host does.

#include "bindings.h"
#include "program_build.h"

#include <QSize>
#include <QString>

#include <functional>
#include <optional>
#include <utility>

namespace lb {

// A program's two stages as the user gave them (WebGL 1 or GLSL 3.30; translated by the host)
// and what the user chose to feed its uniforms (a new choice is a new program to build).
struct ProgramSources
{
    ProgramSources() = default;
    ProgramSources(QString vertexSource, QString fragmentSource, UniformBindings given = {})
        : vertex(std::move(vertexSource)), fragment(std::move(fragmentSource)),
          bindings(std::move(given))
    {
    }
    QString vertex, fragment;
    UniformBindings bindings;
    bool isEmpty() const { return vertex.isEmpty(); } // empty: the built-in programs
    bool operator==(const ProgramSources &o) const
    {
        return vertex == o.vertex && fragment == o.fragment && bindings == o.bindings;
    }
    bool operator!=(const ProgramSources &o) const { return !(*this == o); }
};

class ProgramHost
{
public:
    virtual ~ProgramHost() = default;
    // Builds `sources` and draws with them from now on when they link; when they do not,
    // what drew before keeps drawing. `trial`, when given, runs once the program links and
    // draws in its place: a diagnostic it returns refuses the program, the one before comes
    // back and the build reports the diagnostic, not linked (Renderer::setUserProgram).
    virtual ProgramBuild use(const ProgramSources &sources,
                             const std::function<std::optional<Diagnostic>()> &trial = {}) = 0;
    // One frame at `pixels` with the program in use, waited for: its cost in ms (processor
    // time where the driver draws on the processor, Renderer::renderTimed); the same with the
    // built-in program in its place (what the scene costs anyway).
    virtual double timeFrame(QSize pixels) = 0;
    virtual double timeBuiltInFrame(QSize pixels) = 0;
};

} // namespace lb
