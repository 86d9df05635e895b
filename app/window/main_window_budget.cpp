// The scene budget in the window (scene_budget.h): what a scene asks for is checked before
// the object loader builds anything, wherever the scene comes from (a file, the restored
// session, an example, a panel's edit), and the Object panel's tessellation box stops where
// the budget does.

#include "main_window.h"

#include "object_loader.h"
#include "object_panel.h"
#include "status_line.h"

namespace lb {

namespace {
constexpr int kLimitMessageMs = 20000; // long enough to read a two-line message
} // namespace

void MainWindow::limitScenes()
{
    m_document.setLimit([this](Scene &scene) {
        return fitToBudget(scene, loadedFileSizes(), meshBudget()).message;
    });
}

MeshFileSizes MainWindow::loadedFileSizes() const
{
    // The files drawn now: one being read is counted once it is in (the loader edits the
    // scene then, and that edit passes the limit like any other).
    MeshFileSizes sizes;
    for (int i = 0; m_loader && i < m_loader->objectCount(); ++i)
        if (const MeshFile *file = m_loader->file(i); file && file->mesh)
            sizes[file->path] = {file->mesh->vertexCount(), file->mesh->triangleCount(),
                                 file->hasNormals()};
    return sizes;
}

void MainWindow::setUpSceneBudget()
{
    connect(&m_document, &SceneDocument::limited, this,
            [this](const QString &message) { m_status->showMessage(message, kLimitMessageMs); });
    m_object->setTessellationLimit([this](const Scene &scene, int index) {
        const MeshBudget budget = meshBudget();
        return std::pair(highestTessellation(scene, index, loadedFileSizes(), budget),
                         tr("More would take more memory than the scene's meshes may take on "
                            "this machine: %1 for all objects together.")
                             .arg(byteSizeText(budget.bytes)));
    });
    if (!m_restoreLimited.isEmpty())
        m_status->showMessage(m_restoreLimited, kLimitMessageMs);
}

} // namespace lb
