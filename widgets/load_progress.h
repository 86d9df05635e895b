#pragma once
// The status bar's progress for a mesh load: a bar and a Cancel button, shown only when the
// load takes longer than half a second, so quick loads don't flicker. The text has a fixed
// width (elided, whole in its tooltip), so the Cancel button stays put while it changes.

#include <QTimer>
#include <QWidget>

class QProgressBar;
class QPushButton;

namespace lb {

class ElidedLabel;

class LoadProgress : public QWidget
{
    Q_OBJECT
public:
    static constexpr int kShowAfterMs = 500;
    explicit LoadProgress(QWidget *parent = nullptr);

    void start(const QString &name);
    void setProgress(double fraction, const QString &stage);
    void stop();
    QPushButton *cancelButton() const { return m_cancel; }
    ElidedLabel *label() const { return m_label; }

signals:
    void cancelRequested();

protected:
    void changeEvent(QEvent *event) override; // the UI scale's font: widths follow

private:
    void sizeToFont();
    ElidedLabel *m_label;
    QProgressBar *m_bar;
    QPushButton *m_cancel;
    QTimer m_showTimer;
    QString m_name;
};

} // namespace lb
