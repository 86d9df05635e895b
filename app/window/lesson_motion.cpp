#include "lesson_motion.h"

#include "scene_document.h"

#include <QVariantAnimation>

#include <glm/common.hpp>

#include <cmath>

namespace lb {

LessonMotion::LessonMotion(SceneDocument *document, QObject *parent)
    : QObject(parent), m_document(document), m_animation(new QVariantAnimation(this))
{
    m_animation->setStartValue(0.0);
    m_animation->setEndValue(1.0);
    m_animation->setEasingCurve(QEasingCurve::InOutCubic);
    connect(m_animation, &QVariantAnimation::valueChanged, this,
            [this](const QVariant &t) { moveTo(t.toDouble()); });
    // The last frame exactly where the step says, whatever the easing's rounding.
    connect(m_animation, &QVariantAnimation::finished, this, [this] { moveTo(1.0); });
}

void LessonMotion::start(const Scene &from, int milliseconds)
{
    m_animation->stop(); // a glide under way was ended by whoever applied this step
    const Scene &to = m_document->scene();
    m_fromCamera = from.camera;
    m_toCamera = to.camera;
    // The shorter way round: from 350 degrees to 10 turns 20, not 340.
    const float turn = std::remainder(to.camera.yawDegrees - from.camera.yawDegrees, 360.0f);
    m_fromCamera.yawDegrees = to.camera.yawDegrees - turn;
    m_toLights = to.lights;
    m_fromLights = to.lights;
    for (std::size_t i = 0; i < m_fromLights.size(); ++i) {
        const Light &before = from.lights[i];
        if (before.frame == to.lights[i].frame && before.object == to.lights[i].object &&
            before.position.w == to.lights[i].position.w)
            m_fromLights[i].position = before.position;
    }
    bool moves = !(m_fromCamera.target == m_toCamera.target) ||
                 m_fromCamera.distance != m_toCamera.distance ||
                 m_fromCamera.pitchDegrees != m_toCamera.pitchDegrees || turn != 0.0f;
    for (std::size_t i = 0; i < m_fromLights.size(); ++i)
        moves = moves || m_fromLights[i].position != m_toLights[i].position;
    if (!moves || milliseconds <= 0)
        return;
    m_animation->setDuration(milliseconds);
    moveTo(0.0);
    m_animation->start();
}

void LessonMotion::stop(bool finish)
{
    if (!isRunning())
        return;
    m_animation->stop();
    if (finish)
        moveTo(1.0);
}

bool LessonMotion::isRunning() const
{
    return m_animation->state() == QAbstractAnimation::Running;
}

void LessonMotion::moveTo(double t)
{
    const float f = float(t);
    m_document->edit([&](Scene &s) {
        OrbitCamera &c = s.camera;
        c.target = glm::mix(m_fromCamera.target, m_toCamera.target, f);
        c.distance = glm::mix(m_fromCamera.distance, m_toCamera.distance, f);
        c.pitchDegrees = glm::mix(m_fromCamera.pitchDegrees, m_toCamera.pitchDegrees, f);
        c.yawDegrees = glm::mix(m_fromCamera.yawDegrees, m_toCamera.yawDegrees, f);
        if (t >= 1.0)
            c = m_toCamera; // exactly, yaw as the step writes it (not 370 for 10)
        for (std::size_t i = 0; i < s.lights.size(); ++i)
            s.lights[i].position =
                t >= 1.0 ? m_toLights[i].position
                         : glm::mix(m_fromLights[i].position, m_toLights[i].position, f);
    });
}

} // namespace lb
