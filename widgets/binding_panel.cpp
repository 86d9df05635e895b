#include "binding_panel.h"

#include "bindings.h"
#include "unfed_inputs.h"

#include <QComboBox>
#include <QFormLayout>
#include <QLabel>
#include <QMetaObject>

#include <algorithm>

namespace lb {

namespace {

// A list entry's data: what choosing it stores.
enum class Choice { Automatic, Unbound, Semantic };

QString inputLabel(int location)
{
    switch (location) {
    case 0:
        return BindingPanel::tr("Vertex positions (location 0)");
    case 1:
        return BindingPanel::tr("Vertex normals (location 1)");
    case 2:
        return BindingPanel::tr("Texture coordinates (location 2)");
    case 3:
        return BindingPanel::tr("Vertex colours (location 3)");
    default:
        //: %1 the location number a vertex input was linked at
        return BindingPanel::tr("Nothing: the mesh has no array at location %1").arg(location);
    }
}

// The declaration as GLSL writes it (not words to translate).
QString declaration(const ActiveUniform &u)
{
    return u.size > 1 ? QString("%1 %2[%3]").arg(u.glslType(), u.name).arg(u.size)
                      : QString("%1 %2").arg(u.glslType(), u.name);
}

} // namespace

BindingPanel::BindingPanel(SceneDocument *document, QWidget *parent)
    : QWidget(parent), m_document(document)
{
    m_form = new QFormLayout(this);
    m_form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    m_note = new QLabel(this);
    m_note->setWordWrap(true);
    m_form->addRow(m_note);
    setProgram({});
}

QComboBox *BindingPanel::choiceFor(const QString &uniform) const
{
    for (const auto &[name, list] : m_lists)
        if (name == uniform)
            return list;
    return nullptr;
}

BindingPanel::Shown BindingPanel::shownOf(const ProgramBuild &build, bool choosable)
{
    Shown shown;
    for (const ActiveUniform &u : build.uniforms)
        shown.uniforms.emplace_back(u.name, int(u.kind), u.width, u.size, u.semantic, u.byName,
                                    u.bound);
    for (const ActiveInput &a : build.attributes)
        shown.attributes.emplace_back(a.name, a.location);
    shown.choosable = choosable;
    return shown;
}

void BindingPanel::setProgram(const ProgramBuild &build, bool choosable)
{
    Shown shown = shownOf(build, choosable);
    if (m_shown && *m_shown == shown)
        return;
    m_shown = std::move(shown);
    // Each list under its declaration, the dock's whole width: the declarations are long and so
    // are the entries (the value, its frame and its key).
    m_form->setRowWrapPolicy(QFormLayout::WrapAllRows);
    for (QWidget *row : m_rows)
        m_form->removeRow(row);
    m_rows.clear();
    m_lists.clear();
    m_unfed = 0;
    for (const ActiveInput &a : build.attributes) {
        auto *label = new QLabel(inputLabel(a.location), this);
        label->setToolTip(tr("A vertex input is fed by its location: layout(location = N), or "
                             "the slot its name gives (aPos, a_normal, inTexCoord...)."));
        label->setWordWrap(true); // a column of 38% at 200% is narrower than the words
        m_form->addRow(QString("in %1").arg(a.name), label);
        m_rows.push_back(label);
    }
    for (const ActiveUniform &u : build.uniforms)
        addUniform(u, choosable);
    if (!choosable || (build.uniforms.empty() && build.attributes.empty()))
        m_note->setText(tr("The built-in program draws: its inputs are the panels'. A program of "
                           "your own shows each input here with what feeds it, and you can "
                           "choose what does."));
    else if (m_unfed > 0)
        //: %n how many uniforms nothing feeds
        m_note->setText(tr("%n uniform(s) fed nothing: choose what feeds them; the choice is "
                           "saved with the scene.",
                           "", m_unfed));
    else
        m_note->setText(tr("What feeds each input of the program, chosen by its name; change a "
                           "choice to feed another value. The choice is saved with the scene."));
}

void BindingPanel::addUniform(const ActiveUniform &u, bool choosable)
{
    auto *list = new QComboBox(this);
    list->setEnabled(choosable);
    list->setAccessibleName(u.name);
    list->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    list->setMinimumContentsLength(16);
    const QString byName = u.byName ? semanticLabel(*u.byName) : QString();
    //: the entry that lets the uniform's name decide what feeds it; %1 what that is
    list->addItem(u.byName ? tr("By its name: %1").arg(byName)
                           : tr("By its name: nothing (the name is no convention's)"),
                  int(Choice::Automatic));
    list->addItem(u.components() > 0 ? tr("Not fed: its own value (the Uniforms panel)")
                                     : tr("Not fed"),
                  int(Choice::Unbound));
    // What fits, the name's suggestions first.
    std::vector<Semantic> order = suggestedSemantics(u.name, shapeOf(u.kind));
    for (const QString &key : semanticKeys()) {
        const Semantic s = *semanticFromKey(key);
        if (std::find(order.begin(), order.end(), s) == order.end())
            order.push_back(s);
    }
    for (Semantic s : order)
        if (fits(s, u)) {
            list->addItem(QString("%1 (%2)").arg(semanticLabel(s), semanticKey(s)),
                          int(Choice::Semantic));
            list->setItemData(list->count() - 1, int(s), Qt::UserRole + 1);
        }
    // The current choice.
    int current = 0;
    if (u.bound && !u.semantic)
        current = 1;
    else if (u.bound)
        for (int i = 2; i < list->count(); ++i)
            if (list->itemData(i, Qt::UserRole + 1).toInt() == int(*u.semantic))
                current = i;
    list->setCurrentIndex(current);
    const bool unfed = isUnfed(u);
    m_unfed += unfed ? 1 : 0;
    list->setToolTip(u.semantic ? tr("Fed with: %1").arg(semanticLabel(*u.semantic))
                     : unfed    ? tr("Fed nothing: it stays 0 and decides the picture. Choose "
                                        "what the scene gives.")
                                : tr("Fed nothing by the scene: its own value (the Uniforms "
                                        "panel's control, or its initialiser)."));
    if (unfed)
        list->setStyleSheet("QComboBox { color: #8a5a00; }");
    const QString name = u.name;
    connect(list, &QComboBox::activated, this,
            [this, name, list](int index) { choose(name, index, list); });
    m_form->addRow(QString("uniform %1").arg(declaration(u)), list);
    if (auto *label = qobject_cast<QLabel *>(m_form->labelForField(list)))
        label->setWordWrap(true); // between type and name where the column is narrow
    m_rows.push_back(list);
    m_lists.push_back({name, list});
}

void BindingPanel::choose(const QString &uniform, int index, QComboBox *list)
{
    const Choice choice = Choice(list->itemData(index).toInt());
    const Semantic semantic = Semantic(list->itemData(index, Qt::UserRole + 1).toInt());
    // Built again with the new choice (Viewport, on ScenePart::Bindings): setProgram() comes
    // back with what the build says.
    // Queued: a build said at once would replace this list while it is still signalling.
    QMetaObject::invokeMethod(
        this,
        [this, uniform, choice, semantic] {
            m_document->edit([&](Scene &s) {
                if (choice == Choice::Automatic)
                    s.bindings.erase(uniform);
                else if (choice == Choice::Unbound)
                    s.bindings[uniform] = std::nullopt;
                else if (int(s.bindings.size()) < limits::kMaxBindings || s.bindings.count(uniform))
                    s.bindings[uniform] = semantic;
            });
        },
        Qt::QueuedConnection);
}

} // namespace lb
