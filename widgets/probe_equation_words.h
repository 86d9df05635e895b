#pragma once
// The probe's equation as the Probe panel shows it: lightingEquation() (probe_equation.h)
// writes English, which the command line prints and the probe's JSON keeps; the panel shows
// and copies it with its words translated. Each phrase the equation writes is matched whole and
// replaced by its translation (context lb::ProbeEquation), its numbers and symbols put back as
// arguments; symbols (I, Σ, att·spot, Ia·Ka, N·L, ...) and numbers are never translated. A
// phrase it does not know (the equation reworded) stays English rather than being guessed at.

#include <QString>

namespace lb {

QString equationForDisplay(const QString &equation);

} // namespace lb
