#pragma once
// WebGL 1 (GLSL ES 1.00) text rewritten as GLSL 3.30 core, for drivers that refuse
// "#version 100" in a core context (macOS's 4.1 core profile, some others) or when the user
// asks for it (--translate-webgl1; $LIGHTBENCH_TRANSLATE_WEBGL1=1). Line for line: every
// change stays on its line, and the header's lines are counted so that diagnostics land on
// the user's lines.
//   attribute -> in; varying -> out (vertex) or in (fragment); gl_FragColor and gl_FragData
//   -> declared outputs; texture2D, textureCube and their Proj/Lod/EXT forms -> texture,
//   textureProj, textureLod; gl_FragDepthEXT -> gl_FragDepth; #extension lines blanked (what
//   they enabled is core in 3.30); names that are words of GLSL 3.30 but not of ES 1.00
//   (texture, flat, smooth, layout, uint...) get an "lb_" prefix. Precision statements and
//   qualifiers stay: GLSL 3.30 accepts them.

#include "diagnostics.h"

#include <QString>

namespace lb {

struct TranslatedSource
{
    QString text;
    int linesAdded = 0; // the header's lines before the user's line 1
};

// `source` without #version, or with "#version 100" (which is blanked).
TranslatedSource translateWebGl1(const QString &source, ShaderStage stage);
// The same for desktop GLSL 1.10 to 1.30 (#version blanked), and its fixed-function built-ins
// as legacy_builtins.h names them, declared in the header's second line.
TranslatedSource translateLegacyGlsl(const QString &source, ShaderStage stage);

// Whether WebGL 1 sources are translated rather than handed over under "#version 100":
// forced by the switch, or because this process's driver refused "#version 100" (the
// renderer asks it once per context, noteDriverRefusesVersion100()).
bool translatesWebGl1();
void setWebGl1TranslationForced(bool forced); // overrides $LIGHTBENCH_TRANSLATE_WEBGL1
bool webGl1TranslationForced();
void noteDriverRefusesVersion100(bool refuses);

} // namespace lb
