#pragma once
// The Bindings view: every active input of the program on screen and what feeds it. Vertex
// inputs show the mesh array at their location; each uniform a list of what the scene gives
// that fits its type (the panel value and its frame: "Light position (world coordinates)"),
// chosen automatically from its name and changeable: the choice goes into the scene
// (Scene::bindings), which saves it with scene, lesson and exercise files and builds the
// program again with it.

#include "program_build.h"
#include "scene_document.h"

#include <QWidget>

#include <optional>
#include <tuple>
#include <utility>
#include <vector>

class QComboBox;
class QFormLayout;
class QLabel;

namespace lb {

class BindingPanel : public QWidget
{
    Q_OBJECT
public:
    explicit BindingPanel(SceneDocument *document, QWidget *parent = nullptr);

    // The inputs of a program that linked; `choosable` false for the built-in program as
    // shipped, whose inputs are the panels' (shown, not changeable).
    void setProgram(const ProgramBuild &build, bool choosable = true);
    // The list for a uniform, by name (nullptr for none); for tests.
    QComboBox *choiceFor(const QString &uniform) const;
    // How many of the uniforms shown nothing feeds.
    int unfedCount() const { return m_unfed; }

private:
    // What the rows show: a build whose inputs are the same ones, fed the same way, keeps them
    // (a typed edit builds the program again with the same inputs, many times a minute).
    struct Shown
    {
        std::vector<std::tuple<QString, int, int, int, std::optional<Semantic>,
                               std::optional<Semantic>, bool>>
            uniforms;
        std::vector<std::pair<QString, int>> attributes;
        bool choosable = true;
        bool operator==(const Shown &o) const
        {
            return uniforms == o.uniforms && attributes == o.attributes && choosable == o.choosable;
        }
    };
    static Shown shownOf(const ProgramBuild &build, bool choosable);
    void addUniform(const ActiveUniform &u, bool choosable);
    void choose(const QString &uniform, int index, QComboBox *list);

    SceneDocument *m_document;
    QFormLayout *m_form;
    QLabel *m_note;
    std::vector<QWidget *> m_rows;
    std::vector<std::pair<QString, QComboBox *>> m_lists;
    int m_unfed = 0;
    std::optional<Shown> m_shown;
};

} // namespace lb
