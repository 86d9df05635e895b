#pragma once
// The probe's equation as the Probe panel shows it: the lines lightingEquationLines()
// (probe_equation.h) gives, their patterns and phrases translated (context lb::ProbeEquation)
// and a Show choice named as the Shading panel names it; symbols (I, Σ, att·spot, Ia·Ka, N·L,
// ...) and numbers are never translated. The command line and Copy the Equation keep English.

#include "probe_equation.h"

#include <QString>

namespace lb {

QString equationForDisplay(const std::vector<EquationLine> &lines);

} // namespace lb
