#pragma once
// The Plots panel: the model's curves beside the surface (plots.h), live with the panels.
// Specular (Phong's n against Blinn-Phong's n and 4n), diffuse, each point light's
// attenuation, each spotlight's falloff and the lobe of the three terms at the probed point;
// a probed point's own values are dots on the curves. Export writes the plot as PNG or SVG
// and its samples as CSV, as --plot does.

#include "plots.h"
#include "scene_document.h"

#include <QWidget>

class QChartView;
class QComboBox;
class QLabel;
class QPushButton;
class QSettings;

namespace lb {

class ProbePanel;

class PlotsPanel : public QWidget
{
    Q_OBJECT
public:
    PlotsPanel(SceneDocument *document, ProbePanel *probe, QWidget *parent = nullptr);

    PlotKind kind() const; // the one chosen (drawn once the event loop has run)
    void setKind(PlotKind kind);
    // What is drawn now (or was last, while the panel is hidden).
    const Plot &plot() const { return m_plot; }
    QChartView *chartView() const { return m_view; }
    QComboBox *kindBox() const { return m_kind; }
    QLabel *noteLabel() const { return m_note; }
    // Writes the plot to `path`: PNG, SVG or (ending in .csv) the samples. Empty or the error.
    QString exportTo(const QString &path) const;
    // Export... after its dialog: writes the plot to `path` and says so on the window's
    // status line, or shows why it could not (a box); returns exportTo()'s answer.
    QString exportAndSay(const QString &path);
    // The plot chosen, kept across sessions.
    void saveState(QSettings &settings) const;
    void restoreState(const QSettings &settings);

protected:
    void showEvent(QShowEvent *event) override;
    void changeEvent(QEvent *event) override;
    bool eventFilter(QObject *watched, QEvent *event) override; // the chart view resized

private:
    void schedule(); // rebuilds once the current event is done, if shown
    void rebuild();
    void fitViewToFont(); // the chart's minimum size, in lines of the panel's font
    void exportPlot();

    SceneDocument *m_document;
    ProbePanel *m_probe;
    QComboBox *m_kind;
    QChartView *m_view;
    QLabel *m_note;
    QPushButton *m_export;
    Plot m_plot;
    QString m_exportDir; // where the last export went (kept by saveState)
    bool m_scheduled = false, m_stale = true;
};

} // namespace lb
