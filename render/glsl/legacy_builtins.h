#pragma once
// GLSL 1.10 to 1.30's fixed-function built-ins (gl_Vertex, gl_ModelViewMatrix, ftransform(),
// gl_LightSource[i].position, gl_FrontMaterial.diffuse...) as names of GLSL 3.30 core that
// the workbench feeds: attributes at the mesh's slots, uniforms in the semantic table (the
// lb_ names), what the model has no value for as constants. The legacy translation
// (webgl1_translation.h) writes them and puts the declarations it used in its header, so a
// shader from a GLSL 1.20 tutorial runs on a core context on every driver (Mesa compiles the
// built-ins in core and leaves them unfed; macOS refuses them).

#include "diagnostics.h"

#include <QString>

#include <optional>

namespace lb {

// The lights the per-light arrays hold (gl_MaxLights here): the scene's kMaxLights.
constexpr int kLegacyLights = 4;

struct LegacyName
{
    QString replacement; // the 3.30 name, or expression (ftransform())
    QString declaration; // what the header declares for it, one line of GLSL
};

// A plain built-in word in `stage` (gl_Vertex, gl_NormalMatrix, gl_Color...); nullopt for a
// word that is none.
std::optional<LegacyName> legacyWord(const QString &word, ShaderStage stage);

// A built-in block: gl_LightSource, gl_FrontLightProduct (indexed by light), gl_FrontMaterial,
// gl_LightModel...; its member then becomes a name of its own (an array for an indexed block:
// gl_LightSource[i].position -> lb_LightSource_position[i]).
bool isLegacyBlock(const QString &word, bool &indexed);
std::optional<LegacyName> legacyMember(const QString &block, const QString &member);

// Whether a source uses any built-in of the fixed-function pipeline (comments aside).
bool usesLegacyBuiltins(const QString &source);

// A driver's message about a translated program, with the user's names (lb_Vertex ->
// gl_Vertex, lb_LightSource_position -> gl_LightSource[].position).
QString withLegacyNames(const QString &message);

} // namespace lb
