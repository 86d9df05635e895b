#pragma once
// Controls for the program's own uniforms: every active uniform no panel feeds gets a widget
// made from its type (float, int, bool, vec2/3/4; a colour picker for a vec3/vec4 whose name
// says colour). Values live in the scene (Scene::shaderValues), so they survive recompiles.

#include "program_build.h"
#include "scene_document.h"

#include <QWidget>

#include <functional>
#include <vector>

class QFormLayout;
class QLabel;

namespace lb {

class UniformPanel : public QWidget
{
    Q_OBJECT
public:
    explicit UniformPanel(SceneDocument *document, QWidget *parent = nullptr);

    // The uniforms of a program that linked.
    void setUniforms(const std::vector<ActiveUniform> &uniforms);
    int controlCount() const { return int(m_refreshers.size()); }

private:
    void addControl(const ActiveUniform &u);
    std::vector<float> valueOf(const ActiveUniform &u) const;
    void store(const QString &name, const std::vector<float> &value);
    void refresh();

    SceneDocument *m_document;
    QFormLayout *m_form;
    QLabel *m_note;
    std::vector<std::function<void()>> m_refreshers; // show the scene's values again
    std::vector<QWidget *> m_rows;
};

} // namespace lb
