#pragma once
// What is drawn over the object, unlit: the lights' markers (a sphere for a point light, with
// rays along its cone's edge for a spotlight; an arrow along a directional light's rays),
// the normals as short lines, and the probe's arrows. Their programs take their matrices through
// the semantic table (mModelView, mNormals, mProjection), like every other program.

#include "frames.h"
#include "gpu_mesh.h"
#include "program.h"
#include "scene.h"

#include <QOpenGLExtraFunctions>
#include <QString>

#include <vector>

#include <glm/vec3.hpp>

namespace lb {

// One of the probe's arrows, in eye coordinates; its length is the direction's.
struct ProbeArrow
{
    glm::vec3 origin, direction, colour;
};

class Overlays
{
public:
    // With the context current: builds the programs and marker meshes. Returns an empty
    // string, or what failed.
    QString initialize(QOpenGLExtraFunctions &gl);
    void release(); // with the context current

    // The marker of light `index`, in its diffuse colour at full brightness.
    void drawLightMarker(QOpenGLExtraFunctions &gl, const Light &light, int index,
                         const Frames &frames);
    // The mesh's normals as lines, transformed by mNormals as the shaders do.
    void drawNormals(QOpenGLExtraFunctions &gl, const GpuMesh &mesh, const Scene &scene,
                     const Frames &frames);
    // Arrows drawn with the bound viewport's projection; the caller turns depth off. `faded`:
    // half as thick and blended 40% over the picture, so a highlight under them stays seen.
    void drawArrows(QOpenGLExtraFunctions &gl, const std::vector<ProbeArrow> &arrows,
                    const Frames &frames, bool faded = false);

private:
    void useUnlit(QOpenGLExtraFunctions &gl, const glm::mat4 &modelView,
                  const glm::mat4 &projection, const glm::vec3 &colour);

    BuiltProgram m_unlit, m_normals;
    GpuMesh m_sphere, m_arrow;
};

} // namespace lb
