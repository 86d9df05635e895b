#include "unfed_inputs.h"

#include "dialect.h"

#include <QCoreApplication>
#include <QRegularExpression>
#include <QStringList>

namespace lb {

namespace {

// The translation context of these messages.
struct UnfedMessages
{
    Q_DECLARE_TR_FUNCTIONS(lb::UnfedInputs)
};

// The 1-based line of `name`'s uniform declaration in `source`, or 0.
int declarationLine(const QString &source, const QString &name)
{
    const QRegularExpression declaration("\\buniform\\b[^;{}]*\\b" +
                                         QRegularExpression::escape(name) + "\\b");
    const QString text = withoutComments(source);
    const QRegularExpressionMatch m = declaration.match(text);
    if (!m.hasMatch())
        return 0;
    return int(text.left(m.capturedEnd()).count('\n')) + 1;
}

// The matrices the scene feeds, as a reader would look for one: the course's, then those of
// the conventions.
QString fedMatrixNames()
{
    QStringList names;
    for (Semantic s : {Semantic::Model, Semantic::View, Semantic::Projection, Semantic::ModelView,
                       Semantic::Normals, Semantic::ModelViewProjection})
        for (const QString &name : allUniformNames(s))
            if (!names.contains(name))
                names << name;
    return names.join(", ");
}

} // namespace

std::vector<Diagnostic> unfedInputWarnings(const std::vector<ActiveUniform> &uniforms,
                                           const QString &vertexSource,
                                           const QString &fragmentSource)
{
    std::vector<Diagnostic> warnings;
    for (const ActiveUniform &u : uniforms) {
        if (u.semantic || u.kind != UniformKind::Matrix)
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
        //: %1 the uniform's name; %2 the names of the matrices the workbench feeds
        d.message = UnfedMessages::tr("the scene feeds nothing to the matrix %1: it stays all "
                                      "zeros, and whatever it multiplies collapses to nothing on "
                                      "screen; the matrices fed have these names: %2")
                        .arg(u.name, fedMatrixNames());
        warnings.push_back(d);
    }
    return warnings;
}

} // namespace lb
