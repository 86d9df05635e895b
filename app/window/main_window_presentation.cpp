// MainWindow in front of a class, stepped with a presentation clicker. A clicker sends
// PageUp/PageDown, F5 and Esc (Logitech's start button alternates them) and B or . for a
// black screen (PowerPoint's convention): here F5 and F11 toggle presentation mode, Esc leaves
// it, B and . blank the screen. The panels and the editor wait behind F6 so the view keeps
// the screen at a big UI scale on a 1024x768 projector.
#include "main_window.h"

#include "editor_panel.h"
#include "lesson_actions.h"
#include "lesson_bar.h"
#include "main_window_settings.h"
#include "probe_panel.h"
#include "scene_actions.h"
#include "screen_blank.h"
#include "status_line.h"
#include "viewport.h"

#include <QAction>
#include <QApplication>
#include <QDockWidget>
#include <QLayout>
#include <QMenu>
#include <QMenuBar>
#include <QSettings>
#include <QStatusBar>
#include <QStyle>
#include <QTabBar>
#include <QTimer>

#include <algorithm>
#include <cmath>

namespace lb {

namespace {
const char *const kPanelsKey = "ui/presentationPanels";
const char *const kFadedArrowsKey = "ui/fadedProbeArrows";

// A tabbed dock's tab becomes current when raise() changes its place among its siblings
// (QDockWidget acts on the ZOrderChange): the Exercise panel, raised last as its exercise
// opened and left by a click on the Light panel's tab, stayed behind when F9 raised it again.
void makeCurrent(QDockWidget *dock)
{
    dock->show();
    dock->lower();
    dock->raise();
}
} // namespace

void MainWindow::addPresentationActions(QMenu *view)
{
    m_blank = new ScreenBlank(this);
    m_presentationAction =
        view->addAction(tr("&Presentation Mode"), this, [this](bool on) { setPresentation(on); });
    m_presentationAction->setCheckable(true);
    // F5: a clicker's start button; Esc (escapePressed) is its other half. Shift+F5 is
    // PowerPoint's "from the current slide": here every start is from the current step.
    m_presentationAction->setShortcuts(
        {QKeySequence(tr("F11")), QKeySequence(tr("F5")), QKeySequence(tr("Shift+F5"))});
    m_presentationAction->setToolTip(
        tr("Full screen, the presentation UI scale, the view large (F6: the panels)"));

    m_panelsAction = view->addAction(tr("Show the Panels in Presentation &Mode"), this,
                                     [this](bool on) { setPresentationPanels(on); });
    m_panelsAction->setCheckable(true);
    m_panelsAction->setChecked(m_settings.value(kPanelsKey, false).toBool());
    m_panelsAction->setShortcut(QKeySequence(tr("F6")));

    // Both keys a clicker may send for its blank-screen button.
    QAction *blank = view->addAction(tr("&Blank the Screen (Presentation Mode)"), this,
                                     [this] { blankPressed(); });
    blank->setShortcuts({QKeySequence(tr("B", "shortcut")), QKeySequence(Qt::Key_Period)});

    m_fadedArrowsAction = view->addAction(tr("&Faded Probe Arrows"), this, [this](bool on) {
        m_settings.setValue(kFadedArrowsKey, on);
        m_viewport->setProbeArrowsFaded(on);
    });
    m_fadedArrowsAction->setCheckable(true);
    m_fadedArrowsAction->setToolTip(
        tr("The probe's arrows thin and see-through, so the highlight under them stays visible"));
    // Faded by default: the arrows start on the point being discussed.
    m_fadedArrowsAction->setChecked(m_settings.value(kFadedArrowsKey, true).toBool());
    m_viewport->setProbeArrowsFaded(m_fadedArrowsAction->isChecked());
}

void MainWindow::blankPressed()
{
    if (m_presentation) {
        m_blank->blank();
        return;
    }
    // B toggled the specular model before: say where it went instead of doing nothing.
    m_status->showMessage(tr("B or . blanks the screen in presentation mode (F5 or F11); "
                             "Phong / Blinn-Phong is Ctrl+B"));
}

void MainWindow::escapePressed()
{
    // The clicker's Esc always leaves, whatever is set: its button alternates F5 and Esc, and
    // an Esc spent on the probe would put the button out of step. The probe stays; the next
    // Esc, in the window, clears it.
    if (m_presentation)
        setPresentation(false);
    else
        m_probe->clear();
}

bool MainWindow::presentationPanelsShown() const
{
    return m_panelsAction && m_panelsAction->isChecked();
}

void MainWindow::bringForward(QDockWidget *dock)
{
    if (!dock)
        return;
    if (panelsWaitBehindF6()) {
        m_forwardOnF6 = dock;
        return;
    }
    makeCurrent(dock);
}

void MainWindow::setPresentationPanels(bool shown)
{
    if (m_panelsAction->isChecked() != shown)
        m_panelsAction->setChecked(shown);
    m_settings.setValue(kPanelsKey, shown);
    if (!m_presentation) {
        m_status->showMessage(shown ? tr("Presentation mode (F5) will show the panels (F6 hides "
                                         "them)")
                                    : tr("Presentation mode (F5) will hide the panels (F6 shows "
                                         "them)"));
        return;
    }
    for (QDockWidget *dock : m_panelDocks) // the Exercise panel only with an exercise open
        dock->setVisible(shown &&
                         (dock != m_exerciseDock || m_sceneActions->exercise().has_value()));
    const bool editor = presentationEditorFits();
    m_editorDock->setVisible(shown && editor);
    if (!shown)
        return;
    if (!editor) // said, not silently left out
        m_status->showMessage(
            //: View > Shader editor: the menu's and the dock's names as translated there
            tr("The editor needs %1 px at this scale: View > Shader editor shows it")
                .arg(m_editor->minimumSizeHint().width()));
    applyDockWidths();
    QTimer::singleShot(0, this, &MainWindow::styleDockTabs); // the tab bars made for them now
    if (QDockWidget *forward = m_forwardOnF6.data()) {       // once its tab exists again
        m_forwardOnF6.clear();
        QTimer::singleShot(0, forward, [forward] { makeCurrent(forward); });
    }
}

QFont MainWindow::presentationTabFont(double share) const
{
    const QFont font = QApplication::font();
    const double scale = uiScale();
    QFont f = font;
    if (font.pointSizeF() > 0)
        f.setPointSizeF(font.pointSizeF() * share / scale);
    else
        f.setPixelSize(int(std::lround(font.pixelSize() * share / scale)));
    return f;
}

int MainWindow::presentationTabsWidth() const
{
    return QFontMetrics(presentationTabFont(m_tabShare)).height() + 14; // padding and frame
}

void MainWindow::styleDockTabs()
{
    // Names whole, scrolled when short. In presentation mode the column of tabs down the edge
    // is written at 140% of the 100% font (not 200%), less where the names do not fit its
    // height (nine names at 140% are taller than 720 lines, Portuguese ones even at 100%),
    // down to 80%; they are the teacher's to click, the view is the class's to read.
    const QList<QTabBar *> bars = findChildren<QTabBar *>(Qt::FindDirectChildrenOnly);
    const auto apply = [&](const QFont &font) {
        for (QTabBar *bar : bars) {
            bar->setElideMode(Qt::ElideNone);
            bar->setUsesScrollButtons(true);
            bar->setFont(font);
        }
    };
    if (!m_presentation) {
        apply(QApplication::font());
        return;
    }
    const auto overflows = [&] {
        for (QTabBar *bar : bars) {
            if (!bar->isVisible() || bar->count() < 2)
                continue;
            const QTabBar::Shape shape = bar->shape();
            const bool down = shape == QTabBar::RoundedEast || shape == QTabBar::RoundedWest ||
                              shape == QTabBar::TriangularEast || shape == QTabBar::TriangularWest;
            int length = 0;
            for (int i = 0; i < bar->count(); ++i)
                length += down ? bar->tabRect(i).height() : bar->tabRect(i).width();
            if (length > (down ? bar->height() : bar->width()))
                return true;
        }
        return false;
    };
    m_tabShare = std::min(uiScale(), 1.4);
    apply(presentationTabFont(m_tabShare));
    while (m_tabShare > 0.8 && overflows()) {
        m_tabShare = std::max(0.8, m_tabShare - 0.05);
        apply(presentationTabFont(m_tabShare));
    }
    applyDockWidths(); // the tabs' column is now as wide as it will be
}

bool MainWindow::presentationEditorFits() const
{
    // The editor's bar of buttons grows with the font: at 200% it needs about 600 pixels, more
    // than 40% of a 1280-wide projector. The view's 60% comes first.
    const int dockFrame = 2 * m_editorDock->style()->pixelMetric(QStyle::PM_DockWidgetFrameWidth);
    // A hidden editor's layouts keep the sizes of the font they were last shown with.
    for (QWidget *w : m_editor->findChildren<QWidget *>())
        w->ensurePolished();
    for (QLayout *l : m_editor->findChildren<QLayout *>())
        l->invalidate();
    return m_editor->minimumSizeHint().width() + dockFrame + presentationTabsWidth() <=
           int(width() * 0.395);
}

void MainWindow::placeStatusMessage()
{
    // In presentation mode with a lesson the message is said in the lesson bar's first row and
    // the status line goes: its row, mostly empty, took the caption's room at 200%.
    LessonBar *bar = m_lessons->bar();
    const bool inBar = m_presentation && bar->isVisibleTo(this);
    statusBar()->setVisible(!inBar);
    bar->setMessage(inBar ? m_status->message() : QString());
}

void MainWindow::presentationChanged()
{
    // The status line's fixed places are fragments at 200% on a projector: in presentation
    // mode it says only the last message (what a key did, or why it did nothing).
    for (QWidget *place : {static_cast<QWidget *>(m_status->programLabel()),
                           static_cast<QWidget *>(m_status->meshLabel()),
                           static_cast<QWidget *>(m_status->driverLabel())})
        place->setVisible(!m_presentation);
    placeStatusMessage();
    if (m_presentation)
        setPresentationPanels(m_panelsAction->isChecked());
    else
        m_blank->unblank();
}

} // namespace lb
