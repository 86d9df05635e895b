#pragma once
// The main window's keys in QSettings and the numbers its files share (main_window.cpp,
// main_window_layout.cpp, main_window_menus.cpp).

namespace lb::window_settings {

// 2: the editor dock, 3: the probe dock, 4: the layouts fitted to the screen, 5: the Bindings
// dock
inline constexpr int kStateVersion = 5;
inline constexpr const char *kSceneKey = "scene";
inline constexpr const char *kGeometryKey = "window/geometry";
inline constexpr const char *kStateKey = "window/state";
inline constexpr const char *kScreenKey = "window/screen"; // the available size of the state
inline constexpr const char *kLayoutKey = "window/layout";
inline constexpr const char *kScaleKey = "ui/scale";
inline constexpr const char *kPresentationScaleKey = "ui/presentationScale";
// Edit > Preferences: a lesson's steps glide (true) or jump.
inline constexpr const char *kAnimateLessonsKey = "lessons/animateSteps";
inline constexpr int kScalePercents[] = {100, 125, 150, 175, 200, 250};

} // namespace lb::window_settings
