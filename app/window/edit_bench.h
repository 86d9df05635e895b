#pragma once
// --bench-edits N: how long an edit takes to reach the screen in the real window, beside the
// bare compile and link of the same sources (bench/edit.sh runs it and explains the figures).

#include <QString>

namespace lb {

class MainWindow;

// Prints one JSON line per shader pair; returns the exit code.
int runEditBench(MainWindow &window, int edits, const QString &longVertex,
                 const QString &longFragment);

} // namespace lb
