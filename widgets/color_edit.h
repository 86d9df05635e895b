#pragma once
// A colour as the slides use it: three numbers from 0 to 1, with a swatch that opens the
// system colour picker.

#include <QWidget>

#include <glm/vec3.hpp>

#include <array>

class QDoubleSpinBox;
class QToolButton;

namespace lb {

class ColorEdit : public QWidget
{
    Q_OBJECT
public:
    explicit ColorEdit(const QString &symbol, QWidget *parent = nullptr);
    glm::vec3 color() const;
    void setColor(const glm::vec3 &c); // does not emit colorChanged
    QDoubleSpinBox *channel(int i) const { return m_channels[std::size_t(i)]; }
    QToolButton *swatch() const { return m_swatch; }

signals:
    void colorChanged(const glm::vec3 &c);

private:
    void pickColor();
    void updateSwatch();

    QString m_symbol;
    QToolButton *m_swatch;
    std::array<QDoubleSpinBox *, 3> m_channels{};
};

} // namespace lb
