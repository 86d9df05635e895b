#pragma once
// The numbers of the difference view's colour scale: the renderer draws the bar up the right
// edge (differenceScaleBar in compare.h), this transparent child of the viewport writes the
// difference each tick stands for beside it, in the UI's font on a dark backing, so they are
// read from the back row over any picture. (QPainter text inside paintGL is garbled on Mesa.)

#include <QRect>
#include <QString>
#include <QWidget>

#include <vector>

namespace lb {

class DifferenceScaleLabels : public QWidget
{
    Q_OBJECT
public:
    // Covers `viewport` and follows its size; hidden until setShown(true).
    explicit DifferenceScaleLabels(QWidget *viewport);

    // The UI scale the bar is drawn for (the renderer's).
    void setUiScale(double scale);
    void setShown(bool shown);

    struct Tick
    {
        QRect box; // the number's backing, in this widget's coordinates
        QString text;
    };
    // The numbers as they are painted: 0, 16, ... up to the top of the scale.
    std::vector<Tick> ticks() const;
    int pixelSize() const; // the numbers' height in pixels
    // The column left of the numbers (a caption kept there does not cover them).
    int leftOfTicks() const;

protected:
    bool eventFilter(QObject *watched, QEvent *event) override; // the viewport's resizes
    void paintEvent(QPaintEvent *event) override;

private:
    double m_uiScale = 1.0;
};

} // namespace lb
