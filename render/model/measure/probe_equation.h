#pragma once
// The lighting equation as the course writes it, with a probed point's numbers put in, term
// by term and light by light: what the Probe panel shows and copies as text.

#include "probe.h"
#include "scene.h"

#include <QString>

namespace lb {

// Several lines of plain text: the equation in symbols (Phong's (R·V)^n or Blinn-Phong's
// (N·H)^n; only the terms switched on), then each light that is on with its numbers, then the
// sum and the pixel it gives. Empty when `probe` missed the surface.
QString lightingEquation(const Scene &scene, const ProbeResult &probe);

} // namespace lb
