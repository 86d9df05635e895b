#pragma once
// A brief coloured frame around a control, so a class sees what the teacher points at (a
// lesson's "highlight"): drawn over the window, clicks pass through, gone after a moment.

#include <QPointer>
#include <QWidget>

#include <vector>

namespace lb {

class ControlHighlight : public QWidget
{
    Q_OBJECT
public:
    // Frames the area the `controls` cover (in their window) for `milliseconds`; replaces the
    // frame shown before. Controls not shown are left out; none shown: no frame.
    static ControlHighlight *frame(const std::vector<QWidget *> &controls, int milliseconds = 2000);
    static ControlHighlight *current(); // the frame on screen, if any

protected:
    void paintEvent(QPaintEvent *event) override;

private:
    explicit ControlHighlight(QWidget *window);
    static QPointer<ControlHighlight> s_current;
};

} // namespace lb
