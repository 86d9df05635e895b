#include "color_edit.h"

#include "number_box.h"

#include <QColorDialog>
#include <QHBoxLayout>
#include <QSignalBlocker>
#include <QToolButton>

#include <glm/common.hpp>

namespace lb {

ColorEdit::ColorEdit(const QString &symbol, QWidget *parent) : QWidget(parent), m_symbol(symbol)
{
    auto *layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(3);
    m_swatch = new QToolButton(this);
    m_swatch->setFixedSize(26, 22);
    m_swatch->setToolTip(tr("Pick %1 with the colour dialog").arg(symbol));
    layout->addWidget(m_swatch);
    const char *names[3] = {"R", "G", "B"};
    for (int i = 0; i < 3; ++i) {
        auto *spin = new NumberBox(this);
        spin->setRange(0.0, 1.0);
        spin->setDecimals(2);
        spin->setSingleStep(0.05);
        spin->setToolTip(tr("%1, %2 channel (0 to 1)").arg(symbol, names[i]));
        spin->setAccessibleName(QString("%1.%2").arg(symbol, names[i]));
        connect(spin, &QDoubleSpinBox::valueChanged, this, [this] {
            updateSwatch();
            emit colorChanged(color());
        });
        m_channels[std::size_t(i)] = spin;
        layout->addWidget(spin, 1);
    }
    connect(m_swatch, &QToolButton::clicked, this, &ColorEdit::pickColor);
    updateSwatch();
}

glm::vec3 ColorEdit::color() const
{
    return glm::vec3(float(m_channels[0]->value()), float(m_channels[1]->value()),
                     float(m_channels[2]->value()));
}

void ColorEdit::setColor(const glm::vec3 &c)
{
    for (int i = 0; i < 3; ++i) {
        const QSignalBlocker block(m_channels[std::size_t(i)]);
        m_channels[std::size_t(i)]->setValue(double(c[i]));
    }
    updateSwatch();
}

void ColorEdit::pickColor()
{
    const glm::vec3 c = color();
    const QColor picked = QColorDialog::getColor(QColor::fromRgbF(c.r, c.g, c.b), this,
                                                 tr("Choose %1").arg(m_symbol));
    if (!picked.isValid())
        return;
    setColor(glm::vec3(float(picked.redF()), float(picked.greenF()), float(picked.blueF())));
    emit colorChanged(color());
}

void ColorEdit::updateSwatch()
{
    const glm::vec3 c = glm::clamp(color(), 0.0f, 1.0f);
    m_swatch->setStyleSheet(QString("QToolButton { background-color: %1; border: 1px solid #888; }")
                                .arg(QColor::fromRgbF(c.r, c.g, c.b).name()));
}

} // namespace lb
