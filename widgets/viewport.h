#pragma once
// The viewport: a QOpenGLWidget around the renderer. It draws the document's scene, moves the
// camera with the mouse (orbit: left drag; pan: right or middle drag; zoom: wheel) and runs
// the auto-rotation. GL objects are released when the context goes away (a dock or window
// change can give the widget a new context; initializeGL runs again then). A user's program
// is the program pipeline's to build, try, adopt or refuse (program_pipeline.h): the viewport
// is its host (a context to build in, trial frames drawn: viewport_program_host.cpp) and
// shows what it says (the banner, programBuilt()).

#include "context_loss.h"
#include "probe_labels.h"
#include "program_pipeline.h"
#include "renderer.h"
#include "scene_document.h"

#include <QElapsedTimer>
#include <QOpenGLWidget>
#include <QPoint>
#include <QTimer>

#include <vector>

class QLabel;

namespace lb {

class DifferenceScaleLabels;

class Viewport : public QOpenGLWidget, private WindowProgramHost
{
    Q_OBJECT
public:
    explicit Viewport(SceneDocument *document, QWidget *parent = nullptr);
    ~Viewport() override;

    void resetCamera();
    // The probe's arrows and their names (probe_labels.h), and the pixel whose colour the
    // next frame reads back (renderer().probedColour()); `againstSideB`: also the colour side
    // B's program draws there (renderer().probedSideBColour()).
    void setProbe(std::vector<Renderer::Arrow> arrows, QPoint pixel, std::vector<ProbeLabel> labels,
                  bool againstSideB = false);
    ProbeLabels *probeLabels() const { return m_labels; }
    // The scene as the viewport draws it, rendered offscreen at any size (Export Image), the
    // probe's names included; a null image when there is no OpenGL.
    QImage renderImage(QSize pixels);
    // Why the program on screen may not draw a frame of `pixels` (its trial's estimate is over
    // the budget there); empty when it may. renderImage() draws nothing then.
    QString tooSlowAt(QSize pixels) const { return m_pipeline->tooSlowAt(pixels); }
    // What the trial of the program on screen measured (none: not tried, or no loop).
    const std::optional<TrialResult> &drawingTrial() const { return m_pipeline->drawingTrial(); }
    // The mesh to draw for object `index` from now on (ObjectLoader builds it) and its
    // texture (nullptr: the checker).
    void setObject(int index, std::shared_ptr<const Mesh> mesh,
                   std::shared_ptr<const Texture> texture);
    // The scene has `count` objects: the meshes of those beyond go.
    void setObjectCount(int count);
    const Renderer &renderer() const { return m_renderer; }
    QString renderError() const { return m_error; }
    QString banner() const; // the message over the picture; empty when there is none
    // What the compare view shows, in words (sides, or the largest difference); empty when
    // compare is off.
    QString compareText() const;
    // The texts over the picture at this UI scale (1 to 2.5; the application's font is
    // already scaled): banner, compare caption, the colour scale (its bar too) and its
    // numbers, the probe's names (viewport_captions.cpp).
    void setUiScale(double scale);
    QLabel *compareLabel() const { return m_compareLabel; }
    DifferenceScaleLabels *differenceLabels() const { return m_differenceLabels; }
    // The probe's arrows thin and see-through (View > Faded Probe Arrows).
    void setProbeArrowsFaded(bool faded);
    // The name of the program on screen, for side A's words ("Toon (edited)").
    void setProgramName(const QString &name);
    // What Check My Work measured for the case on screen, said after the difference view's
    // own figures (its frame is the exercise's size, the view's another); empty: none.
    void setCaseNote(const QString &note);
    // Side B of the compare views draws this program (an exercise's reference; `name` for
    // the words) instead of the built-in one; empty sources: the built-in one again. Kept
    // across a new context. Returns what the build said (linked when there is no context yet).
    ProgramBuild setSideBProgram(const QString &vertexSource, const QString &fragmentSource,
                                 const QString &name = {});
    bool hasSideBProgram() const { return !m_sideBVertex.isEmpty(); }
    const QString &sideBName() const { return m_sideBName; }
    // The tolerance the difference view's share within is counted with (compare.h).
    void setDifferenceTolerance(int tolerance)
    {
        m_renderer.setDifferenceTolerance(tolerance);
        update();
    }

    // Builds the user's program (now, or once the context exists) with the scene's bindings
    // and reports it through programBuilt(). When it fails, the last good program keeps
    // drawing under a banner. A change of the bindings builds it again.
    void compileProgram(const QString &vertexSource, const QString &fragmentSource);
    // A program that would draw one frame at the view's size slower than this is refused
    // (tried on tiny frames first); Edit > Preferences sets it.
    void setFrameBudget(double milliseconds) { m_pipeline->setFrameBudget(milliseconds); }
    double frameBudget() const { return m_pipeline->frameBudget(); }
    using TrialMode = ProgramPipeline::TrialMode; // $LIGHTBENCH_PROGRAM_TRIAL
    void setTrialMode(TrialMode mode) { m_pipeline->setTrialMode(mode); }
    TrialProcess *trialProcess() const { return m_pipeline->trialProcess(); }
    // A program is being tried in the helper: the one before it draws meanwhile.
    bool isTrying() const { return m_pipeline->isTrying(); }
    // For the benchmark: the bare compile and link of these sources in this context (ms).
    double rawBuildMilliseconds(const QString &vertexSource, const QString &fragmentSource,
                                bool draw = false);

signals:
    void glInfo(const QString &info); // the driver, once the context exists
    void programBuilt(const lb::ProgramBuild &build);
    void probeRequested(QPoint framePixel); // Ctrl+click or Shift+click, in device pixels
    void clicked(QPoint framePixel);        // a plain click, not a drag: selects an object
    void objectChanged();                   // a new mesh: probed points are gone
    void textureChanged(); // an object's texture (an image decoded): probed points stay
    void resized();        // a new frame size

protected:
    void paintEvent(QPaintEvent *event) override;
    void initializeGL() override;
    void paintGL() override;
    void resizeGL(int w, int h) override;
    void mousePressEvent(QMouseEvent *event) override;
    void mouseMoveEvent(QMouseEvent *event) override;
    void mouseReleaseEvent(QMouseEvent *event) override;
    void wheelEvent(QWheelEvent *event) override;

private:
    QPoint m_pressedAt{-1, -1}; // where a plain left press began (a click, if it ends there)
    void releaseGl();           // with the context made current: the renderer's GL objects go
    // The driver lost the context (context_loss.h): the pipeline refuses the program that
    // drew, and the widget gets a new context.
    void recoverLostContext() { m_pipeline->contextLost(); }
    // The pipeline's word on the program asked for: the banner (viewport_captions.cpp).
    void showProgramState(bool failed, const QString &why, bool builtInDrawing);

    // WindowProgramHost (viewport_program_host.cpp): each call makes the context current
    // unless it already is (Current).
    class Current;
    ProgramBuild use(const ProgramSources &sources,
                     const std::function<std::optional<Diagnostic>()> &trial) override;
    double timeFrame(QSize pixels) override; // in a framebuffer of its own, waited for (ms)
    double timeBuiltInFrame(QSize pixels) override;
    bool hasContext() const override { return m_renderer.isInitialized(); }
    bool hasObject() const override { return m_renderer.objectMesh() != nullptr; }
    QSize viewPixels() const override { return size() * devicePixelRatio(); }
    const Scene &scene() const override { return m_document->scene(); }
    std::shared_ptr<const Mesh> objectMesh() const override
    {
        return m_renderer.sharedObjectMesh();
    }
    bool drawsUserProgram() const override { return m_renderer.hasUserProgram(); }
    void useBuiltIn() override;
    ProgramBuild buildCandidate(const ProgramSources &sources) override;
    bool hasCandidate() const override { return m_renderer.hasCandidate(); }
    void prepareCandidate() override;
    void adoptCandidate() override;
    void dropCandidate() override;
    void renewContext() override;

    void setBanner(const QString &text);
    void showFrameLook(FrameLook look);
    // The banner over a program that was refused (`why`) or did not build (`why` empty), with
    // what draws instead; the driver line (`version` 4.5, the driver's `renderer`). Whole
    // sentences, translatable as such (viewport_captions.cpp).
    static QString bannerText(const QString &why, bool builtInDrawing);
    static QString driverText(const QString &version, const QString &renderer, bool webGl1);
    void updateCompareLabel();
    bool nearWipe(QPoint position) const;
    void syncAnimation();
    void advanceAnimation();

    SceneDocument *m_document;
    Renderer m_renderer;
    QString m_error;
    QString m_programName;
    QString m_caseNote;
    ProgramPipeline *m_pipeline;
    QLabel *m_banner;
    QLabel *m_compareLabel;
    bool m_draggingWipe = false;
    bool m_probing = false; // a probe click held down: the probe follows the mouse
    ProbeLabels *m_labels;
    DifferenceScaleLabels *m_differenceLabels;
    ProgramSources m_submitted; // the last sources compileProgram() was given
    ProgramBuild m_lastBuild;   // what the pipeline last said, with the frame's look added
    int m_builds = 0;           // how many builds the pipeline has said
    QString m_sideBVertex, m_sideBFragment, m_sideBName; // empty: the built-in program
    ResetStatus m_resetStatus;                           // the driver's word on this context
    QPoint m_lastMouse;
    QTimer m_animation;
    QElapsedTimer m_clock;
};

} // namespace lb
