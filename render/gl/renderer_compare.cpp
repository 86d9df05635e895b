// The renderer's passes beyond the object itself: the compare views (side by side, wipe,
// difference and its measure) and the probe (its arrows, the pixels read where it points).
#include "renderer.h"

#include "frames.h"
#include "uniform_upload.h"
#include "webgl1_translation.h"

#include <algorithm>

namespace lb {

void Renderer::drawSides(const Scene &scene, QSize pixels)
{
    // Side A left of the divider, B right of it: in halves, or across the wipe.
    const Scene sceneB = sceneOfSide(scene, true);
    const int divider = dividerColumn(scene, pixels);
    const bool wipe = scene.compare.mode == CompareMode::Wipe;
    for (bool sideB : {false, true}) {
        const QRect view = viewRect(scene, pixels, sideB);
        const QRect clip = !wipe   ? view
                           : sideB ? QRect(divider, 0, pixels.width() - divider, pixels.height())
                                   : QRect(0, 0, divider, pixels.height());
        drawView(sideB ? sceneB : scene, sideB ? sideBProgram(sceneB) : objectProgram(scene), view,
                 clip, pixels.height());
    }
    drawDivider(divider, pixels);
}

glm::ivec3 Renderer::readPixel(QPoint framePixel, int frameHeight)
{
    std::uint8_t rgba[4] = {0, 0, 0, 0};
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(framePixel.x(), frameHeight - 1 - framePixel.y(), 1, 1, GL_RGBA, GL_UNSIGNED_BYTE,
                 rgba);
    return glm::ivec3(rgba[0], rgba[1], rgba[2]);
}

void Renderer::readSideBAtProbe(const Scene &scene, QSize pixels)
{
    const QRect view = viewRect(scene, pixels, false);
    if (!m_sideB.program || !view.contains(m_probePixel))
        return;
    // Side B's program over side A's view, in a framebuffer of the frame's size (gl_FragCoord
    // as on screen), drawn only at the probe's pixel: the pixel the reference draws there.
    GLint target = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &target);
    if (!m_probeFbo || m_probeFbo->size() != pixels) {
        QOpenGLFramebufferObjectFormat format;
        format.setAttachment(QOpenGLFramebufferObject::Depth);
        m_probeFbo = std::make_unique<QOpenGLFramebufferObject>(pixels, format);
    }
    m_probeFbo->bind();
    const int height = pixels.height();
    setViewportRect(view, height);
    glScissor(m_probePixel.x(), height - 1 - m_probePixel.y(), 1, 1);
    glClearColor(kBackgroundRgb[0], kBackgroundRgb[1], kBackgroundRgb[2], 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    drawObjects(sceneOfSide(scene, true), m_sideB, float(view.width()) / float(view.height()));
    glDisable(GL_DEPTH_TEST);
    m_probedSideB = readPixel(m_probePixel, height);
    glBindFramebuffer(GL_FRAMEBUFFER, GLuint(target));
    setViewportRect(QRect(QPoint(0, 0), pixels), pixels.height());
}

void Renderer::setProbe(std::vector<Arrow> arrows, QPoint framePixel)
{
    m_probeArrows = std::move(arrows);
    m_probePixel = framePixel;
}

void Renderer::drawProbe(const Scene &scene, QSize pixels)
{
    if (m_probeArrows.empty())
        return;
    const bool split = scene.compare.mode == CompareMode::SideBySide;
    for (bool sideB : {false, true}) {
        if (sideB && !split)
            break;
        const QRect view = viewRect(scene, pixels, sideB);
        setViewportRect(view, pixels.height());
        const Frames frames = computeFrames(scene, float(view.width()) / float(view.height()));
        m_overlays.drawArrows(*this, m_probeArrows, frames, m_probeArrowsFaded);
    }
}

void Renderer::drawDivider(int column, QSize frame)
{
    // A 2-pixel light line between the sides.
    glScissor(std::clamp(column - 1, 0, frame.width()), 0, 2, frame.height());
    glClearColor(0.85f, 0.85f, 0.85f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
}

void Renderer::drawDifference(const Scene &scene, QSize pixels)
{
    GLint target = 0; // the caller's framebuffer (QOpenGLWidget's is not 0)
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &target);
    const QRect whole(QPoint(0, 0), pixels);
    for (int side = 0; side < 2; ++side) {
        auto &fbo = m_sideFbo[side];
        if (!fbo || fbo->size() != pixels) {
            QOpenGLFramebufferObjectFormat format;
            format.setAttachment(QOpenGLFramebufferObject::Depth);
            fbo = std::make_unique<QOpenGLFramebufferObject>(pixels, format);
        }
        fbo->bind();
        const Scene sideScene = sceneOfSide(scene, side == 1);
        drawView(sideScene, side == 1 ? sideBProgram(sideScene) : objectProgram(scene), whole,
                 whole, pixels.height());
    }
    measureDifference(pixels);

    glBindFramebuffer(GL_FRAMEBUFFER, GLuint(target));
    glViewport(0, 0, pixels.width(), pixels.height());
    glScissor(0, 0, pixels.width(), pixels.height());
    glUseProgram(m_differenceProgram.program.id());
    const std::vector<ActiveUniform> &uniforms = m_differenceProgram.build.uniforms;
    for (int side = 0; side < 2; ++side) {
        glActiveTexture(GL_TEXTURE0 + GLenum(side));
        glBindTexture(GL_TEXTURE_2D, m_sideFbo[side]->texture());
        uploadNamed(*this, uniforms, side ? "uB" : "uA", UniformValue::ofNumber(float(side)));
    }
    uploadNamed(*this, uniforms, "uScale", UniformValue::ofNumber(kDifferenceScale));
    uploadNamed(*this, uniforms, "uPixels",
                UniformValue::ofVector(glm::vec4(pixels.width(), pixels.height(), 0, 0)));
    uploadNamed(*this, uniforms, "uBar",
                UniformValue::ofVector(differenceScaleBarEdges(pixels, m_uiScale)));
    m_screenTriangle.draw(*this);
    glBindTexture(GL_TEXTURE_2D, 0);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, 0);
}

void Renderer::measureDifference(QSize pixels)
{
    // Both sides back to the CPU: the largest difference is a number for the user, and a
    // GPU reduction for one number per frame is not worth its code at these sizes.
    const std::size_t n = std::size_t(pixels.width()) * std::size_t(pixels.height()) * 4;
    std::vector<std::uint8_t> side[2] = {std::vector<std::uint8_t>(n),
                                         std::vector<std::uint8_t>(n)};
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    for (int s = 0; s < 2; ++s) {
        m_sideFbo[s]->bind();
        glReadPixels(0, 0, pixels.width(), pixels.height(), GL_RGBA, GL_UNSIGNED_BYTE,
                     side[s].data());
    }
    m_difference =
        lb::measureDifference(side[0].data(), side[1].data(), pixels, m_differenceTolerance);
}

} // namespace lb
