#include "presets.h"

#include <QFile>

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

const std::vector<Preset> &presets()
{
    static const std::vector<Preset> list{
        {"Built-in: Phong shading (per fragment)", ":/shaders/phong"},
        {"Built-in: Gouraud shading (per vertex)", ":/shaders/gouraud"},
        {"Slides: Gouraud, WebGL 1 as printed", ":/shaders/presets/slides_gouraud"},
        {"Slides: Phong shading, WebGL 1 as printed", ":/shaders/presets/slides_phong"},
        {"Toon (the exercise's \"like Zelda\"), GLSL 3.30", ":/shaders/presets/toon"},
    };
    return list;
}

const Preset &builtInPreset(bool gouraud)
{
    return presets()[gouraud ? 1 : 0];
}

} // namespace lb
