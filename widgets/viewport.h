#pragma once
// The viewport: a QOpenGLWidget around the renderer. It draws the document's scene, moves the
// camera with the mouse (orbit: left drag; pan: right or middle drag; zoom: wheel) and runs
// the auto-rotation. GL objects are released when the context goes away (a dock or window
// change can give the widget a new context; initializeGL runs again then).

#include "renderer.h"
#include "scene_document.h"

#include <QElapsedTimer>
#include <QOpenGLWidget>
#include <QPoint>
#include <QTimer>

namespace lb {

class Viewport : public QOpenGLWidget
{
    Q_OBJECT
public:
    explicit Viewport(SceneDocument *document, QWidget *parent = nullptr);
    ~Viewport() override;

    void resetCamera();
    QString renderError() const { return m_error; }

signals:
    void glInfo(const QString &info); // the driver, once the context exists

protected:
    void initializeGL() override;
    void paintGL() override;
    void mousePressEvent(QMouseEvent *event) override;
    void mouseMoveEvent(QMouseEvent *event) override;
    void wheelEvent(QWheelEvent *event) override;

private:
    void releaseGl(); // with the context made current: the renderer's GL objects go
    void syncAnimation();
    void advanceAnimation();

    SceneDocument *m_document;
    Renderer m_renderer;
    QString m_error;
    QPoint m_lastMouse;
    QTimer m_animation;
    QElapsedTimer m_clock;
};

} // namespace lb
