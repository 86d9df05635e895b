#pragma once
// A lesson's step glides: the camera (yaw, pitch, distance, target) and the lights' positions
// move from where they were to where the step puts them over ~400 ms, so the class sees the
// change instead of a cut. Everything else in the step is in place from the start.

#include "scene.h"

#include <QObject>

class QVariantAnimation;

namespace lb {

class SceneDocument;

class LessonMotion : public QObject
{
    Q_OBJECT
public:
    static constexpr int kMilliseconds = 400;
    LessonMotion(SceneDocument *document, QObject *parent = nullptr);

    // The document holds the step's scene: its camera and lights are put back to `from`'s
    // and moved to the step's. A light that changes kind (point / directional) or frame
    // jumps: halfway between two frames is no place at all.
    void start(const Scene &from, int milliseconds = kMilliseconds);
    // Ends a glide now: at the step's places (`finish`), or where it is (something else
    // took the scene over, a scene opened).
    void stop(bool finish);
    bool isRunning() const;
    QVariantAnimation *animation() const { return m_animation; }

private:
    void moveTo(double t);

    SceneDocument *m_document;
    QVariantAnimation *m_animation;
    OrbitCamera m_fromCamera, m_toCamera;
    Lights m_fromLights, m_toLights;
};

} // namespace lb
