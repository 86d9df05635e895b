// lightbench-trial: the helper process that tries the user's programs before the window
// draws them (render/trial/trial_server.h). The window starts it once and keeps it; a driver
// that hangs or crashes on a program does it here, and the window starts another.

#include "catalogue.h"
#include "process_bounds.h"
#include "stream_output.h"
#include "trial_server.h"

#include <QGuiApplication>

#include <cstdio>

int main(int argc, char **argv)
{
    // Goes with the window: a helper must not outlive it, stuck in a draw.
    lb::platform::dieWithParent();
    lb::platform::useBinaryStandardStreams(); // the messages are bytes (trial_wire.h)
    QGuiApplication app(argc, argv);
    lb::installCatalogueFromWindow(app); // a refusal's reason in the window's language
    return lb::runTrialServer(stdin, stdout);
}
