#include "unfed_inputs.h"

#include "bindings.h"
#include "dialect.h"

#include <QCoreApplication>
#include <QRegularExpression>
#include <QStringList>

#include <algorithm>

namespace lb {

namespace {

// The translation context of these messages.
struct UnfedMessages
{
    Q_DECLARE_TR_FUNCTIONS(lb::UnfedInputs)
};

// The 1-based line of `name`'s declaration as a `qualifier` (uniform; in or attribute) in
// `source`, or 0.
int declarationLine(const QString &source, const QString &name,
                    const QString &qualifier = "uniform")
{
    const QRegularExpression declaration("\\b(" + qualifier + ")\\b[^;{}]*\\b" +
                                         QRegularExpression::escape(name) + "\\b");
    const QString text = withoutComments(source);
    const QRegularExpressionMatch m = declaration.match(text);
    if (!m.hasMatch())
        return 0;
    return int(text.left(m.capturedEnd()).count('\n')) + 1;
}

// The keys a uniform of `u`'s shape could be bound to, those its name suggests first, then
// (for a matrix, where the rest are few) the others; at most `most`, with "..." for more.
QString candidateKeys(const ActiveUniform &u, int most)
{
    std::vector<Semantic> order = suggestedSemantics(u.name, shapeOf(u.kind));
    if (u.kind == UniformKind::Matrix || order.empty())
        for (const QString &key : semanticKeys()) {
            const Semantic s = *semanticFromKey(key);
            if (fits(s, u) && std::find(order.begin(), order.end(), s) == order.end())
                order.push_back(s);
        }
    QStringList keys;
    for (std::size_t i = 0; i < order.size() && int(i) < most; ++i)
        keys << semanticKey(order[i]);
    if (int(order.size()) > most)
        keys << "...";
    return keys.join(", ");
}

bool allZero(const std::vector<float> &values)
{
    return std::all_of(values.begin(), values.end(), [](float v) { return v == 0.0f; });
}

} // namespace

std::vector<Diagnostic> misplacedInputWarnings(const std::vector<PlacedInput> &inputs,
                                               const QString &vertexSource)
{
    // The arrays as the messages name them, by slot.
    const QString arrays[] = {UnfedMessages::tr("the positions"), UnfedMessages::tr("the normals"),
                              UnfedMessages::tr("the texture coordinates"),
                              UnfedMessages::tr("the vertex colours")};
    std::vector<Diagnostic> warnings;
    for (const PlacedInput &in : inputs) {
        if (in.slotOfName < 0 || in.slotOfName > 3 || in.location < 0 ||
            in.location == in.slotOfName)
            continue;
        Diagnostic d;
        d.severity = Diagnostic::Severity::Warning;
        d.stage = ShaderStage::Vertex;
        d.line = declarationLine(vertexSource, in.name, "in|attribute");
        const QString there =
            in.location <= 3 ? arrays[in.location] : UnfedMessages::tr("no array of the mesh");
        //: %1 the input's name; %2 its location; %3 what the mesh gives there; %4 what its
        //: name says; %5 the location that has it
        d.message = UnfedMessages::tr("%1 is at location %2, where the mesh gives %3, though its "
                                      "name says %4 (at location %5 here): write "
                                      "layout(location = %5) to read them")
                        .arg(in.name)
                        .arg(in.location)
                        .arg(there, arrays[in.slotOfName])
                        .arg(in.slotOfName);
        warnings.push_back(d);
    }
    return warnings;
}

bool isUnfed(const ActiveUniform &u)
{
    if (u.semantic || u.bound)
        return false;
    if (u.kind == UniformKind::Matrix)
        return true;
    // A number of the program's own (bands, time) is no concern; one whose name says light,
    // colour, camera or material and that starts at 0 is.
    return u.kind == UniformKind::Float && allZero(u.initial) &&
           !suggestedSemantics(u.name, UniformShape::Number).empty();
}

std::vector<Diagnostic> unfedInputWarnings(const std::vector<ActiveUniform> &uniforms,
                                           const QString &vertexSource,
                                           const QString &fragmentSource)
{
    std::vector<Diagnostic> warnings;
    for (const ActiveUniform &u : uniforms) {
        if (!isUnfed(u))
            continue;
        // A member of a struct is declared by its struct's name (light.model: light).
        const QString declared = u.name.section('.', 0, 0).section('[', 0, 0);
        Diagnostic d;
        d.severity = Diagnostic::Severity::Warning;
        d.stage = ShaderStage::Vertex;
        d.line = declarationLine(vertexSource, declared);
        if (d.line == 0) {
            const int line = declarationLine(fragmentSource, declared);
            if (line > 0) {
                d.stage = ShaderStage::Fragment;
                d.line = line;
            }
        }
        if (u.kind == UniformKind::Matrix)
            //: %1 the uniform's name; %2 the keys it could be bound to (model-view, projection)
            d.message = UnfedMessages::tr(
                            "the scene feeds nothing to the matrix %1: it stays all zeros, and "
                            "whatever it multiplies collapses to nothing on screen; bind it to "
                            "one of %2 (the Bindings tab, or --bind %1=KEY)")
                            .arg(u.name, candidateKeys(u, 10));
        else
            //: %1 the uniform's name; %2 the keys it could be bound to (light-position-world)
            d.message = UnfedMessages::tr(
                            "the scene feeds nothing to %1: it stays 0 unless you set it in the "
                            "Uniforms panel; bind it to one of %2 (the Bindings tab, or --bind "
                            "%1=KEY)")
                            .arg(u.name, candidateKeys(u, 4));
        warnings.push_back(d);
    }
    return warnings;
}

} // namespace lb
