#pragma once
// How the window meets its screen: its first size (the screen's available area, never more),
// the arrangement of the docks for that width, and the UI scale for the back row.

#include <QRect>

namespace lb {

enum class DockLayout {
    Wide,         // from 1600 pixels of width: Light and Material above the other panels
    Compact,      // below: every panel a tab down the left edge, the editor narrower
    Presentation, // full screen: the view large on the left, the editor over the panels' tabs
                  // (beside them, as tabs of one column, on a screen under 900 lines)
};

DockLayout dockLayoutFor(int availableWidth);

// The first window: `preferred` (clipped to `available`) centred in `available`.
QRect initialGeometry(const QRect &available, QSize preferred = QSize(1600, 1000));

// The widths the panels' docks and the editor's dock get in a window `windowWidth` wide;
// what is left (at least 45% below presentation mode) is the view's.
struct DockWidths
{
    int panels;
    int editor;
};
DockWidths dockWidths(DockLayout layout, int windowWidth);
// The least share of the width the view keeps below presentation mode, whatever a saved
// state's dock sizes say (the README's promise).
constexpr double kMinViewShare = 0.45;

// The UI scale: the application's font (panels, menus, status bar, banner, probe names and,
// through EditorPanel::setUiScale, the editor) grown from the size Qt started with.
constexpr double kMinUiScale = 1.0, kMaxUiScale = 2.5;
double clampUiScale(double scale);
void applyUiScale(double scale);
double currentUiScale();

} // namespace lb
