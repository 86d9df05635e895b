// MainWindow and its screen: the docks arranged for the screen's width, the window kept
// inside it, presentation mode and the UI scale.
#include "main_window.h"

#include "editor_panel.h"
#include "main_window_settings.h"
#include "narrow_forms.h"
#include "probe_panel.h"
#include "scene_actions.h"
#include "viewport.h"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QDockWidget>
#include <QFormLayout>
#include <QMenuBar>
#include <QScreen>
#include <QScrollArea>
#include <QScrollBar>
#include <QSettings>
#include <QStatusBar>
#include <QStyle>
#include <QTabBar>
#include <QTimer>

#include <algorithm>
#include <cmath>

namespace lb {

using namespace window_settings;

QDockWidget *MainWindow::addPanelDock(const QString &title, const QString &objectName,
                                      QWidget *panel)
{
    // Narrow docks put a form's field under its label instead of scrolling sideways.
    for (QFormLayout *form : panel->findChildren<QFormLayout *>())
        form->setRowWrapPolicy(QFormLayout::WrapLongRows);
    auto *scroll = new QScrollArea; // a dock whose panel scrolls when the screen is too short
    scroll->setWidget(panel);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    auto *dock = new QDockWidget(title, this);
    dock->setObjectName(objectName); // saveState() needs it
    dock->setWidget(scroll);
    addDockWidget(Qt::LeftDockWidgetArea, dock);
    m_panelDocks.push_back(dock);
    return dock;
}

void MainWindow::fitToScreen(const QRect &available)
{
    m_available = available;
    const bool wasLarge = isFullScreen() || isMaximized();
    if (wasLarge)
        showNormal();
    setGeometry(initialGeometry(available));
    if (wasLarge) // the window manager answers showNormal() with its own geometry later
        QTimer::singleShot(0, this, [this] { setGeometry(initialGeometry(m_available)); });
    arrangeDocks(dockLayoutFor(available.width()));
}

void MainWindow::keepInsideScreen()
{
    // setGeometry() places the inside of the window; a window manager's frame comes on top.
    // Once the frame is known, the whole window shrinks into the available area.
    if (isFullScreen() || isMaximized() || m_available.isEmpty())
        return;
    const QRect frame = frameGeometry();
    if (m_available.contains(frame))
        return;
    const QSize margins = frame.size() - geometry().size();
    const QSize inside = size().boundedTo(m_available.size() - margins);
    const QSize outside = inside + margins;
    resize(inside);
    move(m_available.x() + (m_available.width() - outside.width()) / 2, // move() places the frame
         m_available.y() + (m_available.height() - outside.height()) / 2);
}

void MainWindow::arrangeDocks(DockLayout layout)
{
    m_layout = layout;
    for (QDockWidget *dock : m_panelDocks) {
        dock->setFloating(false);
        removeDockWidget(dock);
    }
    removeDockWidget(m_editorDock);
    m_editorDock->setFloating(false);
    QDockWidget *light = m_panelDocks[0];
    QDockWidget *shading = m_panelDocks[2];
    addDockWidget(Qt::RightDockWidgetArea, m_editorDock);
    if (layout == DockLayout::Wide) {
        // Light over Material over the rest as tabs: the two most used panels open at once.
        addDockWidget(Qt::LeftDockWidgetArea, light);
        addDockWidget(Qt::LeftDockWidgetArea, m_panelDocks[1], Qt::Vertical);
        addDockWidget(Qt::LeftDockWidgetArea, shading, Qt::Vertical);
        for (std::size_t i = 3; i < m_panelDocks.size(); ++i)
            tabifyDockWidget(shading, m_panelDocks[i]);
    } else if (layout == DockLayout::Compact || !presentationIsShort()) {
        // Compact: one column of tabs down the left edge, whose names stay whole. Presentation:
        // the same tabs under the editor, so the view keeps the whole left and the panels
        // get the editor's width (they need it at a big scale).
        addDockWidget(layout == DockLayout::Compact ? Qt::LeftDockWidgetArea
                                                    : Qt::RightDockWidgetArea,
                      light, Qt::Vertical);
        for (std::size_t i = 1; i < m_panelDocks.size(); ++i)
            tabifyDockWidget(light, m_panelDocks[i]);
    } else {
        // Presentation on a short screen (a 720-line projector): the panels are tabs beside
        // the editor, each with the whole height, rather than a strip of three rows under it.
        tabifyDockWidget(m_editorDock, light);
        for (std::size_t i = 1; i < m_panelDocks.size(); ++i)
            tabifyDockWidget(light, m_panelDocks[i]);
    }
    applyTabPositions();
    // In presentation mode the docks wait behind F6 unless it showed them.
    const bool shown = layout != DockLayout::Presentation || presentationPanelsShown();
    for (QDockWidget *dock : m_panelDocks) // the Exercise panel only with an exercise open
        dock->setVisible(shown &&
                         (dock != m_exerciseDock || m_sceneActions->exercise().has_value()));
    m_editorDock->setVisible(shown &&
                             (layout != DockLayout::Presentation || presentationEditorFits()));
    (layout == DockLayout::Wide                                    ? shading
     : layout == DockLayout::Presentation && presentationIsShort() ? m_editorDock
                                                                   : light)
        ->raise();
    applyDockWidths();
    // The docks' tab bars exist once the layout has run.
    QTimer::singleShot(0, this, &MainWindow::styleDockTabs);
}

bool MainWindow::presentationIsShort() const
{
    return height() < 900; // full screen: the screen's height
}

void MainWindow::applyTabPositions()
{
    setTabPosition(Qt::LeftDockWidgetArea,
                   m_layout == DockLayout::Compact ? QTabWidget::West : QTabWidget::North);
    // Presentation: the tabs down the right edge, one narrow column whose names stay whole at
    // 200%; a row above a column of 38% would scroll them out of sight.
    setTabPosition(Qt::RightDockWidgetArea,
                   m_layout == DockLayout::Presentation ? QTabWidget::East : QTabWidget::North);
}

void MainWindow::applyDockWidths()
{
    // Before the window is shown its layout has no size to share out: the widths wait.
    if (!isVisible()) {
        m_widthsPending = true;
        return;
    }
    m_widthsPending = false;
    const int w = width();
    const DockWidths shares = dockWidths(m_layout, w);
    if (m_layout == DockLayout::Presentation) {
        // The editor over the panels on the right; the view has the rest of the width.
        const int h = std::max(height() - menuBar()->height() - statusBar()->height(), 100);
        // Without the editor (it did not fit), the panels have the column.
        QDockWidget *column = m_editorDock->isVisible() ? m_editorDock : m_panelDocks[0];
        // The column of tabs down the edge is outside the dock's width.
        const int tabs = presentationTabsWidth();
        // The widest panel's form where that fits in 39.5% (with the tabs), so it does not
        // scroll sideways; never more: the view keeps 60%.
        const int frames = 2 * column->style()->pixelMetric(QStyle::PM_DockWidgetFrameWidth);
        const int most = int(w * 0.395) - tabs;
        // Narrower than that (200% on a 1024-pixel projector), the forms' rows of boxes stand
        // one under another and their long switches wrap, rather than scroll sideways.
        stackPanelForms(false);
        const bool stacked = panelsNeed() + frames > most;
        stackPanelForms(stacked); // and the column all it may have
        resizeDocks({column},
                    {stacked
                         ? most
                         : std::min(std::max(shares.editor - tabs, panelsNeed() + frames), most)},
                    Qt::Horizontal);
        if (!presentationIsShort() && m_editorDock->isVisible())
            resizeDocks({m_editorDock, m_panelDocks[0]}, {h * 7 / 10, h * 3 / 10}, Qt::Vertical);
        return;
    }
    // The panels get at least what their widest form needs (at this UI scale), so none
    // scrolls sideways; the editor gives way, down to 22% of the window, before the view's
    // share does.
    // The tab bar down the edge of the compact layout is outside the docks' width.
    const int tabBar = m_layout == DockLayout::Compact ? fontMetrics().height() + 14 : 0;
    const int panels = std::max(shares.panels, panelsNeed() + tabBar);
    const int editor = std::max(std::min(shares.editor, int(w * 0.53) - panels), int(w * 0.22));
    resizeDocks({m_panelDocks[0], m_editorDock}, {panels, editor}, Qt::Horizontal);
}

void MainWindow::stackPanelForms(bool on)
{
    for (QDockWidget *dock : m_panelDocks)
        setFormsMayStack(qobject_cast<QScrollArea *>(dock->widget())->widget(), on);
}

int MainWindow::panelsNeed() const
{
    // The widest panel's form at this UI scale, with a vertical scrollbar where it is taller
    // than its dock.
    int need = 0;
    for (QDockWidget *dock : m_panelDocks) {
        auto *scroll = qobject_cast<QScrollArea *>(dock->widget());
        const QSize panel = scroll->widget()->minimumSizeHint();
        int width = panel.width() + 2 * scroll->frameWidth();
        if (panel.height() > scroll->viewport()->height())
            width += scroll->verticalScrollBar()->sizeHint().width();
        need = std::max(need, width);
    }
    return need;
}

void MainWindow::resizeEvent(QResizeEvent *event)
{
    QMainWindow::resizeEvent(event);
    if (m_presentation) { // full screen arrives after the request
        applyDockWidths();
        // The tab names' font is measured on the bars once they have their new length.
        QTimer::singleShot(0, this, &MainWindow::styleDockTabs);
    }
}

void MainWindow::showEvent(QShowEvent *event)
{
    QMainWindow::showEvent(event);
    QTimer::singleShot(200, this, &MainWindow::keepInsideScreen); // the frame has come by then
    if (m_widthsPending)
        QTimer::singleShot(0, this, &MainWindow::applyDockWidths);
    else // the last session's own dock sizes, unless they leave the view too little
        QTimer::singleShot(0, this, &MainWindow::keepTheViewsShare);
}

// A restored state can leave the view a third of the width: a 1366-pixel window reopened
// with an exercise had its panel column grow to the Exercise panel's wrapped task (33%).
void MainWindow::keepTheViewsShare()
{
    if (!m_presentation && isVisible() && m_viewport->width() < kMinViewShare * width())
        applyDockWidths();
}

void MainWindow::setPresentation(bool on)
{
    if (on == m_presentation)
        return;
    if (on) {
        m_normalGeometry = saveGeometry();
        m_normalState = saveState(kStateVersion);
        m_normalLayout = m_layout;
        m_normalRect = geometry();
        m_normalUnsized = m_widthsPending; // entered before the docks had their widths
    }
    m_presentation = on;
    if (!on)
        stackPanelForms(false);
    applyScale();
    if (on) {
        // The whole screen also where no window manager answers the full-screen request.
        if (const QScreen *s = screen())
            setGeometry(s->geometry());
        showFullScreen();
        arrangeDocks(DockLayout::Presentation);
    } else {
        showNormal();
        m_layout = m_normalLayout;
        applyTabPositions(); // not part of the saved state
        // The rectangle itself (restoreGeometry() from full screen put the window 20 pixels
        // low under Xvfb), then the docks as they were, once the window has its size again:
        // restored into the full-screen window, their widths came out wrong.
        setGeometry(m_normalRect);
        restoreState(m_normalState, kStateVersion);
        QTimer::singleShot(0, this, [this] {
            if (m_presentation)
                return;
            setGeometry(m_normalRect);
            restoreState(m_normalState, kStateVersion);
            m_exerciseDock->setVisible(m_sceneActions->exercise().has_value());
            if (m_normalUnsized || panelsNeed() > m_panelDocks[0]->width())
                applyDockWidths();
        });
    }
    if (m_presentationAction)
        m_presentationAction->setChecked(on);
    presentationChanged(); // the panels behind F6, the status line, the blank screen
}

void MainWindow::setUiScale(double scale)
{
    (m_presentation ? m_presentationScale : m_scale) = clampUiScale(scale);
    m_settings.setValue(kScaleKey, m_scale);
    m_settings.setValue(kPresentationScaleKey, m_presentationScale);
    applyScale();
    // The panels' forms grew or shrank with the font: their widths again, once laid out.
    QTimer::singleShot(0, this, &MainWindow::applyDockWidths);
}

// A dock writes its title in the font QApplication::font("QDockWidgetTitle") had when the
// dock was made, as long as its own font is the QDockWidget class's: at 200% in presentation
// mode the titles stayed at 9 points. Given the panels' font as their own, with the class's
// set apart (it is drawn nowhere: every dock has its own), the docks write their titles in it.
void MainWindow::scaleDockTitles()
{
    QFont apart = QApplication::font();
    apart.setUnderline(!apart.underline()); // (QFont's == ignores its style strategy)
    QApplication::setFont(apart, "QDockWidget");
    QFont own = QApplication::font();
    own.setUnderline(own.underline()); // set, so that the class's is not taken for it
    for (QDockWidget *dock : findChildren<QDockWidget *>())
        dock->setFont(own);
}

double MainWindow::uiScale() const
{
    return m_presentation ? m_presentationScale : m_scale;
}

void MainWindow::applyScale()
{
    const double scale = uiScale();
    applyUiScale(scale);
    scaleDockTitles();
    m_editor->setUiScale(scale);
    m_viewport->setUiScale(scale); // the texts over the view
    QTimer::singleShot(0, this, &MainWindow::styleDockTabs);

    if (m_scaleGroup)
        for (QAction *a : m_scaleGroup->actions())
            a->setChecked(a->data().toInt() == int(std::lround(scale * 100.0)));
}

} // namespace lb
