#include "plots_panel.h"

#include "compare.h"
#include "narrow_forms.h"
#include "plot_chart.h"
#include "probe_panel.h"
#include "safe_write.h"
#include "status_line.h"

#include <QComboBox>
#include <QDir>
#include <QEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QMainWindow>
#include <QMessageBox>
#include <QPushButton>
#include <QSettings>
#include <QTimer>
#include <QVBoxLayout>
#include <QtCharts/QChart>
#include <QtCharts/QChartView>

namespace lb {

namespace {

const char *const kKindKey = "plots/kind";
const char *const kDirKey = "plots/exportDir";

// The size an export has: a slide's 4:3 at 1200 pixels across, whatever the panel's size.
const QSize kExportSize(1200, 900);

} // namespace

PlotsPanel::PlotsPanel(SceneDocument *document, ProbePanel *probe, QWidget *parent)
    : QWidget(parent), m_document(document), m_probe(probe)
{
    m_kind = new ElidingComboBox; // beside Export in a narrow column
    m_kind->addItem(tr("Specular: Phong and Blinn-Phong"), int(PlotKind::Specular));
    m_kind->addItem(tr("Diffuse: max(N·L, 0)"), int(PlotKind::Diffuse));
    m_kind->addItem(tr("Attenuation with distance"), int(PlotKind::Attenuation));
    m_kind->addItem(tr("Spotlight falloff"), int(PlotKind::Spot));
    m_kind->addItem(tr("Lobe at the probed point"), int(PlotKind::Lobe));
    m_kind->setToolTip(tr("Which of the model's curves to draw"));
    // Its longest name need not widen the panels' column (1024 pixels share it with the view).
    m_kind->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    m_kind->setMinimumContentsLength(10);
    m_export = new QPushButton(tr("Export…"));
    m_export->setToolTip(tr("Write this plot as a PNG or SVG picture, or its samples as CSV"));
    auto *row = new QHBoxLayout;
    row->addWidget(m_kind, 1);
    row->addWidget(m_export);

    m_view = new QChartView;
    m_view->setRenderHint(QPainter::Antialiasing);
    m_view->installEventFilter(this); // resized: the title's lines again
    fitViewToFont();
    m_view->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
    m_note = new QLabel;
    m_note->setWordWrap(true);
    m_note->setTextFormat(Qt::PlainText);

    auto *layout = new QVBoxLayout(this);
    layout->addLayout(row);
    layout->addWidget(m_view, 1);
    layout->addWidget(m_note);

    connect(m_kind, &QComboBox::currentIndexChanged, this, [this] {
        m_stale = true;
        schedule();
    });
    connect(m_export, &QPushButton::clicked, this, &PlotsPanel::exportPlot);
    connect(document, &SceneDocument::changed, this, [this] {
        m_stale = true;
        schedule();
    });
    connect(probe, &ProbePanel::resultChanged, this, [this] {
        m_stale = true;
        schedule();
    });
}

PlotKind PlotsPanel::kind() const
{
    return PlotKind(m_kind->currentData().toInt());
}

void PlotsPanel::setKind(PlotKind kind)
{
    m_kind->setCurrentIndex(m_kind->findData(int(kind)));
}

void PlotsPanel::schedule()
{
    if (m_scheduled || !isVisible())
        return; // a hidden panel catches up when shown
    m_scheduled = true;
    QTimer::singleShot(0, this, [this] {
        m_scheduled = false;
        if (isVisible())
            rebuild();
    });
}

void PlotsPanel::showEvent(QShowEvent *event)
{
    QWidget::showEvent(event);
    if (m_stale)
        schedule();
}

bool PlotsPanel::eventFilter(QObject *watched, QEvent *event)
{
    if (watched == m_view && event->type() == QEvent::Resize && m_view->chart())
        fitPlotTitle(m_view->chart(), m_view->width());
    return QWidget::eventFilter(watched, event);
}

void PlotsPanel::changeEvent(QEvent *event)
{
    QWidget::changeEvent(event);
    if (event->type() == QEvent::FontChange) { // the UI scale: texts and lines follow
        fitViewToFont();
        m_stale = true;
        schedule();
    }
}

void PlotsPanel::fitViewToFont()
{
    // Room for the axes' labels and a legible curve at any UI scale; no wider than the column
    // a 1024-pixel projector leaves the panels at 200% (10 lines: 280 px there).
    m_view->setMinimumSize(fontMetrics().height() * 10, fontMetrics().height() * 16);
}

void PlotsPanel::rebuild()
{
    m_stale = false;
    const ProbeResult *probed = m_probe->isActive() ? &m_probe->result() : nullptr;
    // A point on side B of a compare view was probed in side B's scene (its shading and
    // specular choices): the curves are that scene's too.
    m_plot = computePlot(kind(), sceneOfSide(m_document->scene(), m_probe->onSideB()), probed);
    QChart *old = m_view->chart();
    m_view->setChart(makePlotChart(m_plot, font()));
    fitPlotTitle(m_view->chart(), m_view->width());
    delete old; // setChart() hands the old one back instead of deleting it
    QString note = plotGapText(m_plot.gap);
    if (note.isEmpty() && m_plot.kind == PlotKind::Lobe && !m_plot.probed)
        note = tr("No point probed: light %1's lobe where N faces the camera at the selected "
                  "object's centre. Ctrl+click the surface to plot it at a point.")
                   .arg(m_plot.lobeLight + 1);
    else if (note.isEmpty() && !m_plot.probed)
        note = tr("Ctrl+click the surface: the probed point's own values appear as dots.");
    else if (note.isEmpty() && m_plot.kind == PlotKind::Lobe)
        note = tr("Light %1's terms at the probed point. The dots are where V's part in the "
                  "plane of incidence points; the Probe tab has the values at V itself.")
                   .arg(m_plot.lobeLight + 1);
    else if (note.isEmpty() && m_plot.markers.empty() && m_plot.kind != PlotKind::Attenuation)
        note = tr("No dot: at the probed point every light is behind the surface (N·L < 0) "
                  "or outside the plot.");
    else if (note.isEmpty() && m_plot.kind == PlotKind::Specular)
        note = tr("Dots: each light's angle at the probed point (for Blinn-Phong, 2·acos(N·H)).");
    m_note->setText(note);
}

QString PlotsPanel::exportTo(const QString &path) const
{
    if (path.endsWith(QLatin1String(".csv"), Qt::CaseInsensitive))
        return writeFileSafely(path, plotCsv(m_plot));
    return writePlotImage(m_plot, kExportSize, path, font());
}

void PlotsPanel::exportPlot()
{
    if (m_stale)
        rebuild();
    const QString png = tr("PNG images (*.png)"), svg = tr("SVG pictures (*.svg)"),
                  csv = tr("CSV samples (*.csv)");
    QString filter = png;
    const QString start =
        (m_exportDir.isEmpty() ? QDir::homePath() : m_exportDir) + '/' + plotKindName(m_plot.kind);
    QString path = QFileDialog::getSaveFileName(this, tr("Export the plot"), start,
                                                png + ";;" + svg + ";;" + csv, &filter);
    if (path.isEmpty())
        return;
    if (QFileInfo(path).suffix().isEmpty())
        path += filter == svg ? ".svg" : filter == csv ? ".csv" : ".png";
    m_exportDir = QFileInfo(path).absolutePath(); // the window's next save keeps it
    exportAndSay(path);
}

QString PlotsPanel::exportAndSay(const QString &path)
{
    const QString error = exportTo(path);
    if (!error.isEmpty())
        QMessageBox::warning(
            this, tr("Export the plot"),
            tr("The plot could not be written; nothing was changed.\n%1").arg(error));
    else if (auto *window = qobject_cast<QMainWindow *>(this->window()))
        showStatusMessage(window, tr("Exported the plot to %1").arg(path), 5000);
    return error;
}

void PlotsPanel::saveState(QSettings &settings) const
{
    settings.setValue(kKindKey, plotKindName(kind()));
    settings.setValue(kDirKey, m_exportDir);
}

void PlotsPanel::restoreState(const QSettings &settings)
{
    if (const auto kind = plotKindFromName(settings.value(kKindKey).toString()))
        setKind(*kind);
    m_exportDir = settings.value(kDirKey).toString();
}

} // namespace lb
