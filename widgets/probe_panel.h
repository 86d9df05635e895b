#pragma once
// The probe in the window: Ctrl+click (or Shift+click) a surface and this panel shows, for that
// point, P, N, V and each light's L, H, R in eye coordinates (and P, L in the light's own
// frame), N.L, N.H or R.V, the terms and their sum from the reference (render/probe), the
// pixel the GPU drew and the difference. The point stays on the surface: the numbers and the
// arrows drawn on it follow the lights, the material and the camera live.

#include "probe.h"
#include "scene_document.h"

#include <QWidget>

#include <optional>

class QLabel;
class QPushButton;

namespace lb {

class Viewport;

class ProbePanel : public QWidget
{
    Q_OBJECT
public:
    ProbePanel(SceneDocument *document, Viewport *viewport, QWidget *parent = nullptr);

    // Probes the frame pixel (device pixels, top-left origin) and follows that point.
    void probeAt(QPoint framePixel);
    void clear();
    bool isActive() const { return m_point.has_value(); }
    // The point lies on side B of a compare view: its numbers are side B's scene's.
    bool onSideB() const { return m_point && m_point->sideB; }
    const ProbeResult &result() const { return m_result; }
    QLabel *textLabel() const { return m_text; }
    QPushButton *copyEquationButton() const { return m_copyEquation; }
    // The lighting equation with the probed point's numbers (probe_equation.h), its words
    // translated (probe_equation_words.h), as shown and copied; empty if none.
    const QString &equation() const { return m_equation; }
    // What the reference does not know about the program on screen ("it computes V =
    // (0,0,1)..."), shown under the numbers; empty for none.
    void setReferenceNote(const QString &note);
    // The GPU's pixel at the point, once the viewport has drawn it: the surface's, never a
    // marker's, a normal line's or an arrow's.
    std::optional<glm::ivec3> gpuColour() const { return m_gpu; }
    // Where side B is side A's reference (an exercise's reference, or a program from files),
    // its name; empty: the built-in model with the probed side's choices is. A point on side A
    // is then compared with what that reference draws there (side B's program's pixel, or the
    // model with side B's choices); a point drawn by side B's program is compared with nothing
    // (it is the reference).
    void setSideBReference(const QString &name);
    // What the GPU's pixel was compared with (0-255) and its name; none when nothing was.
    std::optional<glm::ivec3> referenceColour() const { return m_reference; }
    const QString &referenceName() const { return m_referenceName; }

signals:
    // The probed point's numbers changed, or it was cleared (the Plots panel marks them).
    void resultChanged();

protected:
    void resizeEvent(QResizeEvent *event) override;

private:
    struct Point
    {
        int object; // index into Scene::objects
        std::size_t triangle;
        glm::vec3 barycentric;
        bool sideB;
    };
    void update();           // the model again at the point; arrows to the viewport
    void followResize();     // the point moved to its new pixel's centre, then update()
    void showText();         // after the frame is drawn, with the GPU's pixel
    bool stacksRows() const; // whether the panel is too narrow for names beside values

    SceneDocument *m_document;
    Viewport *m_viewport;
    QLabel *m_text;
    QPushButton *m_copyEquation;
    QString m_equation;
    std::optional<Point> m_point;
    ProbeResult m_result;
    std::optional<glm::ivec3> m_gpu, m_reference;
    QString m_referenceNote, m_sideBReference, m_referenceName;
    bool m_stacked = false; // the rows' values under their names (stacksRows)
};

} // namespace lb
