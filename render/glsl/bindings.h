#pragma once
// What feeds a program's uniforms beyond the names of the semantic table (semantics.h): the
// user's own choice, by uniform name, saved with the scene (Scene::bindings) and given on the
// command line (--bind NAME=KEY). Each semantic has a key for files and the command line
// ("model-view", "light-position-world") and a label for the Bindings view.

#include "diagnostics.h"
#include "program_build.h"
#include "semantics.h"

#include <QString>

#include <map>
#include <optional>
#include <vector>

namespace lb {

// A uniform's name to what the user chose for it: a semantic, or nothing (nullopt: "none",
// the uniform keeps its own value and gets a generated control, even where a convention's
// name would feed it).
using UniformBindings = std::map<QString, std::optional<Semantic>>;

// The word for "fed with nothing" in files and on the command line.
inline const char *kUnboundKey = "none";

QString semanticKey(Semantic semantic);
// nullopt for no semantic; `unbound` is set for "none".
std::optional<Semantic> semanticFromKey(const QString &key, bool *unbound = nullptr);
// Every key, in the table's order (the course's first), "none" not among them.
QStringList semanticKeys();
// What the scene gives under `semantic`, translated: "Light position (world)".
QString semanticLabel(Semantic semantic);
// The shape of what the scene gives: Matrix, Number or Sampler (never Any).
UniformShape shapeOf(Semantic semantic);
// Whether `semantic`'s value can go into `uniform` (a matrix into a matrix, numbers into
// numbers, the texture into a sampler).
bool fits(Semantic semantic, const ActiveUniform &uniform);

// Sets each uniform's semantic from `bindings` where they name it (keeping the semantic its
// name gave in byName); a binding that does not fit the uniform's type is not applied, and
// a warning says so.
std::vector<Diagnostic> applyBindings(std::vector<ActiveUniform> &uniforms,
                                      const UniformBindings &bindings);

// The semantics of `shape` whose keys share a word with `name` (uLightPos: light-position,
// light-position-camera, light-position-world), the closest first; empty when none does.
std::vector<Semantic> suggestedSemantics(const QString &name, UniformShape shape);

} // namespace lb
