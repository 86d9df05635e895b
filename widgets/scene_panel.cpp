#include "scene_panel.h"

#include "narrow_forms.h"

#include <QAbstractScrollArea>
#include <QComboBox>
#include <QCoreApplication>
#include <QEvent>
#include <QFormLayout>
#include <QPushButton>

namespace lb {

ScenePanel::ScenePanel(SceneDocument *document, SceneParts shown, QWidget *parent)
    : QWidget(parent), m_document(document)
{
    connect(document, &SceneDocument::changed, this, [this, shown](SceneParts parts) {
        if (parts & shown)
            refresh(m_document->scene());
    });
}

NumberBox *ScenePanel::makeSpin(double lo, double hi, int decimals, double step,
                                const QString &toolTip)
{
    auto *spin = new NumberBox(this); // 2.5 and 2,5 alike; edits once, not per key typed
    spin->setRange(lo, hi);
    spin->setDecimals(decimals);
    spin->setSingleStep(step);
    spin->setToolTip(toolTip);
    spin->setAccessibleName(toolTip.section(':', 0, 0));
    // The wheel scrolls the panel over a spin box it passes; it edits one clicked first.
    spin->setFocusPolicy(Qt::StrongFocus);
    spin->installEventFilter(this);
    return spin;
}

bool ScenePanel::eventFilter(QObject *watched, QEvent *event)
{
    if (event->type() == QEvent::Wheel)
        if (auto *widget = qobject_cast<QWidget *>(watched); widget && !widget->hasFocus()) {
            // On to the scroll area around the panel (a wheel event sent to a parent is not
            // passed further up, so it goes straight to the area's viewport).
            for (QWidget *w = widget->parentWidget(); w; w = w->parentWidget())
                if (auto *area = qobject_cast<QAbstractScrollArea *>(w)) {
                    QCoreApplication::sendEvent(area->viewport(), event);
                    break;
                }
            return true;
        }
    return QWidget::eventFilter(watched, event);
}

NumberBox *ScenePanel::makeSpin(const LightingParameter &p, const QString &toolTip)
{
    return makeSpin(double(p.lo), double(p.hi), p.decimals, p.step, toolTip);
}

QComboBox *ScenePanel::makeCombo(const QStringList &labels, const QString &toolTip)
{
    auto *combo = new ElidingComboBox(this); // a narrow column ends its words with "…"
    combo->addItems(labels);
    combo->setToolTip(toolTip);
    return combo;
}

void ScenePanel::feeds(QWidget *control, std::vector<Semantic> semantics)
{
    m_uses.push_back({control, std::move(semantics), control->toolTip()});
}

QString ScenePanel::namesOf(const std::vector<Semantic> &semantics)
{
    QStringList names;
    for (Semantic s : semantics)
        names << uniformNames(s);
    if (names.size() < 2)
        return names.value(0);
    // One pattern for the whole list, not " or " glued between names: the translator places
    // the names and the word.
    const QString last = names.takeLast();
    //: uniform names, one of which a shader may declare: %1 the first ones, comma-separated; %2 the
    //: last
    return tr("%1 or %2").arg(names.join(", "), last);
}

void ScenePanel::setApplies(QWidget *control, bool applies)
{
    if (applies)
        m_notApplying.erase(control);
    else
        m_notApplying.insert(control);
    bool used = true;
    for (const Use &use : m_uses)
        if (use.control == control)
            used = use.used;
    control->setEnabled(applies && used);
}

void ScenePanel::showUsage(const std::set<Semantic> &read)
{
    for (Use &use : m_uses) {
        bool used = false;
        for (Semantic s : use.semantics)
            used = used || read.count(s) > 0;
        use.used = used;
        use.control->setEnabled(used && m_notApplying.count(use.control) == 0);
        use.control->setToolTip(
            used ? use.toolTip
                 : tr("Unused: the program on screen has no uniform %1 (a constant in the "
                      "shader, perhaps), so this control changes nothing.\n\n%2")
                       .arg(namesOf(use.semantics), use.toolTip));
    }
}

void ScenePanel::addResetButton(QFormLayout *form, const QString &text, const QString &toolTip,
                                std::function<void(Scene &)> reset)
{
    auto *button = new QPushButton(text, this);
    button->setToolTip(toolTip);
    connect(button, &QPushButton::clicked, this, [this, reset] { m_document->edit(reset); });
    form->addRow(button);
}

} // namespace lb
