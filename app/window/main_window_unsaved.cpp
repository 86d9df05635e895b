// MainWindow and work not yet in its files: what the title's * stands for, the question
// before quit, close, another scene or Reset Everything set it aside, and its Save.
#include "main_window.h"

#include "lesson_actions.h"
#include "main_window_settings.h"
#include "presets.h"
#include "scene_actions.h"

#include <QFileDialog>
#include <QFileInfo>
#include <QJsonDocument>
#include <QMessageBox>
#include <QSettings>

namespace lb {

using namespace window_settings;

bool MainWindow::untitledProgramInFiles() const
{
    return m_sceneActions->documentName().isEmpty() &&
           !m_shaders.filePath(ShaderStage::Vertex).isEmpty() &&
           !m_shaders.filePath(ShaderStage::Fragment).isEmpty();
}

UnsavedWork MainWindow::unsavedWork() const
{
    UnsavedWork work;
    work.sceneName = m_sceneActions->documentName();
    // A scene file holds its program inline: an edit of it is the scene's. An untitled
    // scene's program from a shader pair is the pair's to save; the scene then counts alone.
    work.scene =
        untitledProgramInFiles() ? m_sceneActions->isSceneModified() : m_sceneActions->isModified();
    if (m_lessons && m_lessons->isOpen()) {
        // The lesson is the document: the class's edits to its steps are a demonstration
        // (Reset Step); what a save would lose is the lesson's own changes.
        work.scene = false;
        work.lesson = m_lessons->isModified();
        work.lessonName = m_lessons->name();
    }
    for (ShaderStage stage : {ShaderStage::Vertex, ShaderStage::Fragment})
        if (const QString path = m_shaders.filePath(stage);
            !path.isEmpty() && m_shaders.isModified(stage))
            work.shaderFiles << QFileInfo(path).fileName();
    return work;
}

bool MainWindow::maySetAside(SetAsideFor occasion, const QString &target)
{
    return askToSetAside(occasion, target) != SetAside::Cancelled;
}

MainWindow::SetAside MainWindow::askToSetAside(SetAsideFor occasion, const QString &target)
{
    UnsavedWork work = unsavedWork();
    // A scene opened or everything reset while a lesson is open sets none of the lesson
    // aside: it stays open with its changes (only opening another one, or closing, does).
    if (occasion == SetAsideFor::OpeningScene || occasion == SetAsideFor::ResettingEverything)
        work.lesson = false;
    if (!work.any())
        return SetAside::NothingUnsaved;
    if (!m_asker)
        return SetAside::NotAsked;
    switch (m_asker(this, unsavedWorkQuestion(work, occasion, target), unsavedWorkDetails(work))) {
    case QMessageBox::Save:
        return saveUnsavedWork(work) ? SetAside::Saved : SetAside::Cancelled;
    case QMessageBox::Discard:
        return SetAside::Discarded;
    default:
        return SetAside::Cancelled;
    }
}

bool MainWindow::saveUnsavedWork(const UnsavedWork &work)
{
    // The scene first: it is what a student hands in. A failed save has said why.
    if (work.scene && !m_sceneActions->saveScene())
        return false;
    if (work.lesson && !m_lessons->save())
        return false;
    return work.shaderFiles.isEmpty() || saveShaders();
}

bool MainWindow::saveShaders()
{
    if (m_shaders.filePath(ShaderStage::Vertex).isEmpty() ||
        m_shaders.filePath(ShaderStage::Fragment).isEmpty())
        return saveShadersAs(); // ShaderDocument::save() writes only a pair
    const QString error = m_shaders.save();
    if (!error.isEmpty())
        QMessageBox::warning(this, tr("Shader files"), error);
    return error.isEmpty();
}

bool MainWindow::saveShadersAs()
{
    const QString path =
        QFileDialog::getSaveFileName(this, tr("Save the shader pair as NAME.vert and NAME.frag"),
                                     {}, tr("Shader pairs (*.vert *.frag);;All files (*)"));
    if (path.isEmpty())
        return false;
    const QString error = m_shaders.saveAs(path);
    if (!error.isEmpty())
        QMessageBox::warning(this, tr("Shader files"), error);
    return error.isEmpty();
}

void MainWindow::writeSavedWork()
{
    // Discard means discard: the next start shows the files as saved, not the edit the user
    // threw away (a crash or a kill still brings unsaved work back: no question was answered).
    // The scene file stays the document; an untitled scene goes back to the defaults.
    const SceneFile saved = m_sceneActions->savedFile();
    m_settings.setValue(kSceneKey, QJsonDocument(saved.scene.toJson()).toJson());
    // The editor's part of the session, as a document of what the files hold would write it.
    ShaderDocument program;
    const QStringList pair = {m_shaders.filePath(ShaderStage::Vertex),
                              m_shaders.filePath(ShaderStage::Fragment)};
    // A pair gone from the disk meanwhile: the built-in program, as for any untitled scene.
    const bool fromFiles = untitledProgramInFiles() && program.openFiles(pair).isEmpty();
    if (!fromFiles)
        program.setProgram(saved.program, perVertex(saved.scene.shading.shading));
    program.saveState(m_settings);
}

} // namespace lb
