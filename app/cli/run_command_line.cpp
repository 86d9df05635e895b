#include "run_command_line.h"

#include "catalogue.h"
#include "grade.h"
#include "headless.h"
#include "language.h"
#include "object_mesh.h"
#include "plot_output.h"
#include "safe_write.h"
#include "scene_file.h"

#include <QApplication>
#include <QGuiApplication>

#include <cstdio>
#include <memory>
#include <new>

namespace lb {

int runCommandLine(int &argc, char **argv, const CommandLine &cl)
{
    // A plot without a probed point draws no frame (main() chose the offscreen platform).
    const bool plotOnly = cl.plot && !cl.probe;
    // A plot's chart is a graphics-view widget: it needs QApplication; a frame does not.
    std::unique_ptr<QGuiApplication> application =
        cl.plot ? std::make_unique<QApplication>(argc, argv)
                : std::make_unique<QGuiApplication>(argc, argv);
    QGuiApplication &app = *application;
    if (cl.grade)
        return runGrade(cl);
    if (!cl.gradePrepare.isEmpty())
        return runGradePrepare(cl);
    if (!cl.gradeOne.isEmpty()) {
        installCatalogueFromWindow(app); // Check My Work's reasons in its language
        return runGradeOne(cl);
    }
    // Headless frames start from the scene file or the defaults, not the saved session.
    const Scene scene = cl.headlessScene();
    if (!cl.saveScenePath.isEmpty()) {
        const QString error = writeSceneFile(
            cl.saveScenePath,
            SceneFile{scene, cl.program(), cl.sceneFile ? cl.sceneFile->exercise : std::nullopt});
        if (!error.isEmpty()) {
            std::fprintf(stderr, "lightbench: --save-scene: %s\n", qPrintable(error));
            return 1;
        }
        if (cl.renderPath.isEmpty() && !cl.probe && !cl.plot && cl.benchFrames == 0 && !cl.check)
            return 0;
    }
    if (cl.plot && cl.language) // a slide's words in the language asked for
        installCatalogue(app, resolvedLanguage(*cl.language));
    if (plotOnly) // the curves alone: no mesh, no OpenGL
        return writePlotOutputs(cl, scene, nullptr);
    try {
        return runHeadless(cl, scene);
    } catch (const std::bad_alloc &e) { // within the scene budget, this is rare
        const bool mesh = dynamic_cast<const ObjectMeshOutOfMemory *>(&e);
        std::fprintf(stderr, "lightbench: %s\n",
                     mesh ? e.what() : "out of memory"); // "... building the torus at ..."
        return 1;
    }
}

} // namespace lb
