#pragma once
// Building a GLSL program with raw GL calls. QOpenGLShader rewrites the source it is given
// (design.md), so user and built-in shaders alike go to glShaderSource as prepareSource()
// leaves them (dialect.h), and the driver's messages come back on the user's lines.

#include "bindings.h"
#include "gl_object.h"
#include "program_build.h"
#include "scene.h"

#include <QOpenGLExtraFunctions>
#include <QString>

#include <optional>
#include <tuple>
#include <vector>

namespace lb {

// Fixed attribute slots, bound by name before linking so every program reads the renderer's
// buffers the same way.
// The order is the one tutorials give with layout(location = N): LearnOpenGL and the GLSL
// Cookbook put the position at 0, the normal at 1 and the texture coordinates at 2.
enum AttributeSlot : GLuint {
    kPositionSlot = 0,
    kNormalSlot = 1,
    kTexCoordSlot = 2,
    kColorSlot = 3
};

// A build that linked holds the one owner of its program; one that did not holds none.
// What it said (program_build.h) is what the renderer passes on to the window.
struct BuiltProgram
{
    ProgramBuild build;
    GlProgram program;
    // Set when the sources are a built-in pair as shipped (true: Gouraud): the renderer then
    // draws that program compiled for the scene's lights instead (buildSpecialisedBuiltIn),
    // the same pixels in fewer passes.
    std::optional<bool> shippedBuiltIn;
};

// The names bound to each slot: the slides', the exercise's, the tutorials' and books'
// (semantics.h's conventions) and common generic ones.
struct AttributeBinding
{
    const char *name;
    AttributeSlot slot;
};
const std::vector<AttributeBinding> &attributeBindings();
// The slot for an attribute of a name in no table, from what the name says ("inPos",
// "vertex_normal", "myUV"); nullopt when it says nothing the mesh has.
std::optional<AttributeSlot> slotByNameParts(const QString &name);

// The bare cost of building: glShaderSource, glCompileShader (both stages), glLinkProgram,
// nothing else; for the editor's benchmark (bench/edit.sh). Milliseconds.
// With `draw`, also one draw call with the new program and a glFinish: drivers such as
// llvmpipe generate the machine code at the first draw, not at link time.
double rawBuildMilliseconds(QOpenGLExtraFunctions &gl, const QString &vertexSource,
                            const QString &fragmentSource, bool draw = false);

// A built-in pair from the resources (:/shaders/NAME.vert and FRAGMENT.frag, FRAGMENT
// defaulting to NAME). A failure is added to `error`: the build is broken, not the user.
// Whether this context's driver compiles a "#version 100" (GLSL ES 1.00) shader; when it
// does not, WebGL 1 sources are translated from then on (webgl1_translation.h).
bool acceptsVersion100(QOpenGLExtraFunctions &gl);

BuiltProgram buildBuiltIn(QOpenGLExtraFunctions &gl, const QString &name, QString &error,
                          const QString &fragment = {});

// The built-in program of a shading mode compiled for `lights` lights (1 to kMaxLights): its
// MAX_LIGHTS is the count, so a scene with only light 1 on runs one pass of the light loop, as
// the single-light program did, instead of four (llvmpipe pays for every pass, on or off).
// Elements past the count are never read: the scene's later lights are all off.
// Likewise LIGHT_FACTORS: 0 compiles attenuation and spotlights out while no light that is
// on has either (they cost llvmpipe a fifth of the default scene's frame rate at their
// defaults, since it evaluates every branch), and SHOW_CHOICES 0 the Show choice while the
// colour is shown.
struct BuiltInVariant
{
    bool gouraud = false;
    int lights = 1;            // MAX_LIGHTS
    bool lightFactors = false; // LIGHT_FACTORS
    bool showChoices = false;  // SHOW_CHOICES: something other than the colour is shown
    bool flat = false;         // FLAT_SHADING: the Gouraud program, one colour per triangle
    bool operator<(const BuiltInVariant &o) const
    {
        return std::tie(gouraud, lights, lightFactors, showChoices, flat) <
               std::tie(o.gouraud, o.lights, o.lightFactors, o.showChoices, o.flat);
    }
};
// The variant `scene` needs of the built-in program of a shading mode (gouraud: the per-vertex
// text, drawn flat when the scene's shading is flat).
BuiltInVariant builtInVariant(const Scene &scene, bool gouraud);
BuiltProgram buildSpecialisedBuiltIn(QOpenGLExtraFunctions &gl, const BuiltInVariant &variant,
                                     QString &error);
// The lights a scene's built-in program must loop over: up to the last one that is on
// (at least 1).
int builtInLightCount(const Scene &scene);
// Whether a light the program loops over and that is on is attenuated or a spotlight.
bool builtInNeedsLightFactors(const Scene &scene);
// Whether the pair is the built-in program of a shading mode as shipped (true: Gouraud).
std::optional<bool> shippedBuiltIn(const QString &vertexSource, const QString &fragmentSource);
// The source with its "#define NAME N" line set to `value`; empty if it has no such line.
QString withDefine(const QString &source, const QString &name, int value);

// Compiles both stages and links them; `bindings` (the user's, by uniform name) override what
// the uniforms' names give.
BuiltProgram buildProgram(QOpenGLExtraFunctions &gl, const QString &vertexSource,
                          const QString &fragmentSource, const UniformBindings &bindings = {});

} // namespace lb
