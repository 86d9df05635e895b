#include "presets.h"

#include <QCoreApplication>
#include <QFile>

#include <utility>

namespace lb {

namespace {
QString readResource(const QString &path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? QString::fromUtf8(f.readAll()) : QString();
}
} // namespace

QString Preset::vertexSource() const
{
    return readResource(resource + ".vert");
}
QString Preset::fragmentSource() const
{
    return readResource(resource + ".frag");
}
QString Preset::title() const
{
    return QCoreApplication::translate("lb::Presets", name.toUtf8().constData());
}

const std::vector<Preset> &presets()
{
    static const std::vector<Preset> list{
        // The built-in programs read their specular term from uSpecularModel and their V
        // from uProjection; the slides' compute N.H (Blinn-Phong) with V = (0,0,1).
        // Marked for lupdate: title() translates them.
        {QT_TRANSLATE_NOOP("lb::Presets", "Built-in: Phong shading (per fragment)"),
         ":/shaders/phong", false},
        {QT_TRANSLATE_NOOP("lb::Presets", "Built-in: Gouraud shading (per vertex)"),
         ":/shaders/gouraud", true},
        {QT_TRANSLATE_NOOP("lb::Presets", "Slides: Gouraud, WebGL 1 as printed"),
         ":/shaders/presets/slides_gouraud", true, "blinn", true},
        {QT_TRANSLATE_NOOP("lb::Presets", "Slides: Phong shading, WebGL 1 as printed"),
         ":/shaders/presets/slides_phong", false, "blinn", true},
        {QT_TRANSLATE_NOOP("lb::Presets", "Toon (the exercise's \"like Zelda\"), GLSL 3.30"),
         ":/shaders/presets/toon"},
    };
    return list;
}

const Preset &builtInPreset(bool gouraud)
{
    return presets()[gouraud ? 1 : 0];
}

const Preset *presetNamed(const QString &name)
{
    for (const Preset &p : presets())
        if (p.name == name)
            return &p;
    return nullptr;
}

bool isPresetProgram(const QString &vertexSource, const QString &fragmentSource)
{
    static const std::vector<std::pair<QString, QString>> texts = [] {
        std::vector<std::pair<QString, QString>> t;
        for (const Preset &p : presets())
            t.emplace_back(p.vertexSource(), p.fragmentSource());
        return t;
    }();
    for (const auto &[vertex, fragment] : texts)
        if (vertex == vertexSource && fragment == fragmentSource)
            return true;
    return false;
}

} // namespace lb
