#include "program_build.h"

namespace lb {

int ActiveUniform::components() const
{
    const bool numbers =
        kind == UniformKind::Float || kind == UniformKind::Int || kind == UniformKind::Bool;
    return numbers && size == 1 && location >= 0 ? width : 0;
}

QString ActiveUniform::glslType() const
{
    switch (kind) {
    case UniformKind::Matrix:
        return QString("mat%1").arg(width);
    case UniformKind::Sampler:
        return "sampler2D";
    case UniformKind::Int:
        return width == 1 ? "int" : QString("ivec%1").arg(width);
    case UniformKind::Bool:
        return width == 1 ? "bool" : QString("bvec%1").arg(width);
    case UniformKind::Float:
        return width == 1 ? "float" : QString("vec%1").arg(width);
    case UniformKind::Other:
        break;
    }
    return "?";
}

bool ProgramBuild::hasErrors() const
{
    return firstError() != nullptr;
}

const Diagnostic *ProgramBuild::firstError() const
{
    for (const Diagnostic &d : diagnostics)
        if (d.severity == Diagnostic::Severity::Error)
            return &d;
    return nullptr;
}

bool ProgramBuild::reads(Semantic semantic) const
{
    for (const ActiveUniform &u : uniforms)
        if (u.semantic == semantic)
            return true;
    return false;
}

QString ProgramBuild::log() const
{
    QString text;
    for (const Diagnostic &d : diagnostics)
        text +=
            QString("%1:%2:%3: %4: %5\n")
                .arg(stageName(d.stage))
                .arg(d.line)
                .arg(d.column)
                .arg(d.severity == Diagnostic::Severity::Error ? "error" : "warning", d.message);
    return text;
}

} // namespace lb
