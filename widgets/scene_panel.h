#pragma once
// Base of the dock panels: each edits the SceneDocument and shows its values again whenever
// the document changes (from the panel itself, another panel, the camera or a reset).

#include "number_box.h"
#include "scene_document.h"
#include "semantics.h"

#include <QWidget>

#include <functional>
#include <set>
#include <vector>

class QComboBox;
class QFormLayout;

namespace lb {

class ScenePanel : public QWidget
{
    Q_OBJECT
public:
    // The panel shows the scene's `shown` parts: it refreshes when one of them changes.
    ScenePanel(SceneDocument *document, SceneParts shown, QWidget *parent = nullptr);

    // Greys out the controls whose uniforms the program on screen does not read, and says
    // why in their tooltip (a student who hard-coded a const sees why a slider does nothing).
    void showUsage(const std::set<Semantic> &read);

protected:
    // `control` feeds the program through any of `semantics` (semantics.h names them).
    void feeds(QWidget *control, std::vector<Semantic> semantics);
    // Whether `control` applies to the scene as it is (a spot's axis does not without a spot):
    // it is enabled when it applies and, if it feeds the program, the program reads it.
    void setApplies(QWidget *control, bool applies);
    // The uniform names of `semantics` in words: "lightDif or uLightColor".
    static QString namesOf(const std::vector<Semantic> &semantics);

    // Shows the scene's values in the controls; must not emit edits (block signals).
    virtual void refresh(const Scene &scene) = 0;
    // Runs refresh() once the derived constructor has built its controls.
    void refreshNow() { refresh(m_document->scene()); }
    template <typename F> void edit(F &&change) { m_document->edit(std::forward<F>(change)); }

    NumberBox *makeSpin(double lo, double hi, int decimals, double step, const QString &toolTip);
    // A box for one number of a row of the lighting model's table: its range, decimals, step.
    NumberBox *makeSpin(const LightingParameter &p, const QString &toolTip);
    QComboBox *makeCombo(const QStringList &labels, const QString &toolTip);
    // A "Reset ..." button at the bottom of the panel that applies `reset` to the scene.
    void addResetButton(QFormLayout *form, const QString &text, const QString &toolTip,
                        std::function<void(Scene &)> reset);

    SceneDocument *m_document;
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    struct Use
    {
        QWidget *control;
        std::vector<Semantic> semantics;
        QString toolTip; // as written by the panel
        bool used = true;
    };
    std::vector<Use> m_uses;
    std::set<QWidget *> m_notApplying;
};

} // namespace lb
