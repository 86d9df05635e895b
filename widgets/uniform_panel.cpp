#include "uniform_panel.h"

#include "color_edit.h"
#include "number_box.h"

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QSpinBox>

namespace lb {

namespace {

bool namesAColour(const QString &name)
{
    return name.contains("colo", Qt::CaseInsensitive); // color, colour, Color...
}

} // namespace

UniformPanel::UniformPanel(SceneDocument *document, QWidget *parent)
    : QWidget(parent), m_document(document)
{
    m_form = new QFormLayout(this);
    m_form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    m_note = new QLabel(this);
    m_note->setWordWrap(true);
    m_form->addRow(m_note);
    connect(document, &SceneDocument::changed, this, [this](SceneParts parts) {
        if (parts & ScenePart::Program)
            refresh();
    });
    setUniforms({});
}

std::vector<float> UniformPanel::valueOf(const ActiveUniform &u) const
{
    const auto &values = m_document->scene().shaderValues;
    const auto it = values.find(u.name);
    if (it != values.end() && int(it->second.size()) == u.components())
        return it->second;
    return u.initial;
}

void UniformPanel::store(const QString &name, const std::vector<float> &value)
{
    m_document->edit([&](Scene &s) { s.shaderValues[name] = value; });
}

void UniformPanel::setUniforms(const std::vector<ActiveUniform> &uniforms)
{
    for (QWidget *row : m_rows)
        m_form->removeRow(row);
    m_rows.clear();
    m_refreshers.clear();
    QStringList fixed;
    for (const ActiveUniform &u : uniforms) {
        if (u.semantic)
            continue;
        if (u.components() > 0)
            addControl(u);
        else if (u.name != "uSampler")
            fixed << u.name;
    }
    QString note = m_refreshers.empty()
                       ? tr("The program has no uniforms of its own. A uniform that no panel "
                            "feeds gets a control here.")
                       : tr("The program's own uniforms; values stay when you recompile.");
    if (!fixed.isEmpty())
        //: %1 the names of uniforms that get no control, comma-separated
        note +=
            ' ' + tr("No control for: %1 (matrices, samplers and arrays).").arg(fixed.join(", "));
    m_note->setText(note);
}

void UniformPanel::addControl(const ActiveUniform &u)
{
    const int n = u.components();
    const QString name = u.name;
    auto *field = new QWidget(this);
    auto *row = new QHBoxLayout(field);
    row->setContentsMargins(0, 0, 0, 0);
    // Its declaration in GLSL, which stays as the shader has it (not words to translate).
    field->setToolTip(QString("uniform %1 %2").arg(u.glslType(), name));

    if (!u.isInteger() && n >= 3 && namesAColour(name)) {
        auto *colour = new ColorEdit(name, field);
        row->addWidget(colour);
        QDoubleSpinBox *alpha = nullptr;
        if (n == 4) {
            alpha = new NumberBox(field);
            alpha->setRange(0, 1);
            alpha->setSingleStep(0.05);
            alpha->setToolTip(QString("%1.a").arg(name)); // GLSL: the vector's alpha
            row->addWidget(alpha);
        }
        auto save = [this, name, colour, alpha] {
            const glm::vec3 c = colour->color();
            std::vector<float> v{c.r, c.g, c.b};
            if (alpha)
                v.push_back(float(alpha->value()));
            store(name, v);
        };
        connect(colour, &ColorEdit::colorChanged, this, save);
        if (alpha)
            connect(alpha, &QDoubleSpinBox::valueChanged, this, save);
        m_refreshers.push_back([this, u, colour, alpha] {
            const std::vector<float> v = valueOf(u);
            colour->setColor(glm::vec3(v[0], v[1], v[2]));
            if (alpha) {
                const QSignalBlocker block(alpha);
                alpha->setValue(double(v[3]));
            }
        });
    } else if (u.isBool() && n == 1) {
        auto *check = new QCheckBox(field);
        row->addWidget(check);
        connect(check, &QCheckBox::toggled, this,
                [this, name](bool on) { store(name, {on ? 1.0f : 0.0f}); });
        m_refreshers.push_back([this, u, check] {
            const QSignalBlocker block(check);
            check->setChecked(valueOf(u)[0] != 0.0f);
        });
    } else {
        std::vector<QAbstractSpinBox *> boxes;
        for (int i = 0; i < n; ++i) {
            QAbstractSpinBox *box;
            if (u.isInteger()) {
                auto *spin = new IntegerBox(field);
                spin->setRange(-1000000, 1000000);
                box = spin;
            } else {
                auto *spin = new NumberBox(field);
                spin->setRange(-1e6, 1e6);
                spin->setDecimals(3);
                spin->setSingleStep(0.1);
                box = spin;
            }
            row->addWidget(box);
            boxes.push_back(box);
        }
        auto read = [boxes, integer = u.isInteger()] {
            std::vector<float> v;
            for (QAbstractSpinBox *b : boxes)
                v.push_back(integer ? float(static_cast<QSpinBox *>(b)->value())
                                    : float(static_cast<QDoubleSpinBox *>(b)->value()));
            return v;
        };
        for (QAbstractSpinBox *b : boxes) {
            if (u.isInteger())
                connect(static_cast<QSpinBox *>(b), &QSpinBox::valueChanged, this,
                        [this, name, read] { store(name, read()); });
            else
                connect(static_cast<QDoubleSpinBox *>(b), &QDoubleSpinBox::valueChanged, this,
                        [this, name, read] { store(name, read()); });
        }
        m_refreshers.push_back([this, u, boxes] {
            const std::vector<float> v = valueOf(u);
            for (std::size_t i = 0; i < boxes.size(); ++i) {
                const QSignalBlocker block(boxes[i]);
                if (u.isInteger())
                    static_cast<QSpinBox *>(boxes[i])->setValue(int(v[i]));
                else
                    static_cast<QDoubleSpinBox *>(boxes[i])->setValue(double(v[i]));
            }
        });
    }
    m_form->addRow(QString("%1 (%2)").arg(name, u.glslType()), field);
    m_rows.push_back(field);
    m_refreshers.back()();
}

void UniformPanel::refresh()
{
    for (const auto &r : m_refreshers)
        r();
}

} // namespace lb
