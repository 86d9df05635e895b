#pragma once
// The selected object's texture, inside the Object panel: the texture switch, the image it
// shows (an image file, or the mesh file's texture or the checker when none), and how it is
// sampled (wrap, filter, mipmaps).

#include "scene_panel.h"

#include <functional>

class QCheckBox;
class QComboBox;
class QLabel;
class QToolButton;

namespace lb {

class ElidedLabel;

class TextureControls : public ScenePanel
{
    Q_OBJECT
public:
    explicit TextureControls(SceneDocument *document, QWidget *parent = nullptr);

    QCheckBox *textureCheck() const { return m_texture; }
    ElidedLabel *imageLabel() const { return m_image; }
    // Where the panel learns why the selected object's image is not shown (the object
    // loader's textureProblem()); refreshProblem() shows it again.
    void setProblemLookup(std::function<QString()> lookup) { m_problem = std::move(lookup); }
    void refreshProblem() { refreshNow(); }
    QToolButton *openButton() const { return m_open; }
    QToolButton *clearButton() const { return m_clear; }
    QComboBox *wrapCombo() const { return m_wrap; }
    QComboBox *filterCombo() const { return m_filter; }
    QCheckBox *mipmapsCheck() const { return m_mipmaps; }

signals:
    void openImageRequested(); // "Image...": the window shows its file dialog

protected:
    void refresh(const Scene &scene) override;

private:
    QCheckBox *m_texture;
    ElidedLabel *m_image;
    std::function<QString()> m_problem;
    QToolButton *m_open, *m_clear;
    QComboBox *m_wrap, *m_filter;
    QCheckBox *m_mipmaps;
};

} // namespace lb
