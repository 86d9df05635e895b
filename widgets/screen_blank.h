#pragma once
// The clicker's "blank screen" (B or . in presentation mode, PowerPoint's keys): a black cover
// over the whole window, so the class looks at the teacher instead of the picture. Any key or
// click brings the picture back, and that key does nothing else: a clicker's next-slide press
// must not also step or toggle something the class cannot see.

#include <QWidget>

namespace lb {

class ScreenBlank : public QWidget
{
    Q_OBJECT
public:
    // Covers `window` (and follows its size) while blanked; hidden until blank().
    explicit ScreenBlank(QWidget *window);

    void blank();
    void unblank();
    bool isBlank() const { return isVisible(); }

signals:
    void blankChanged(bool blank);

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;
    void paintEvent(QPaintEvent *event) override;
};

} // namespace lb
