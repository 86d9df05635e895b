// MainWindow and exercises: the Exercise panel, Check my work (the cases in a grading child,
// a click showing one in the difference view) and what side B of the compare views draws.
#include "main_window.h"

#include "choice_labels.h"

#include "exercise_panel.h"
#include "probe_panel.h"
#include "scene_actions.h"
#include "scene_phrases.h"
#include "shading_panel.h"
#include "status_line.h"
#include "submission.h"
#include "viewport.h"
#include "work_check.h"

#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QMessageBox>
#include <QTimer>

namespace lb {

namespace {

// Not modal: the window (and a test driving it) goes on; the box stays until closed.
void warnAboutSideB(QWidget *window, const QString &message)
{
    auto *box = new QMessageBox(QMessageBox::Warning, MainWindow::tr("Side B"), message,
                                QMessageBox::Ok, window);
    box->setObjectName("sideBMessage");
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->open();
}

// The status line's word on a check that graded nothing. The statuses are the grading
// report's data (grading_report.h), never shown as they are: a whole sentence for each.
const std::pair<const char *, const char *> kNotChecked[] = {
    {"does not compile", QT_TRANSLATE_NOOP("lb::MainWindow", "Not checked: does not compile")},
    {"does not link", QT_TRANSLATE_NOOP("lb::MainWindow", "Not checked: does not link")},
    {"refused", QT_TRANSLATE_NOOP("lb::MainWindow", "Not checked: refused")},
    {"timed out", QT_TRANSLATE_NOOP("lb::MainWindow", "Not checked: timed out")},
    {"could not start", QT_TRANSLATE_NOOP("lb::MainWindow", "Not checked: could not start")},
    {"crashed", QT_TRANSLATE_NOOP("lb::MainWindow", "Not checked: crashed")},
    {"unreadable", QT_TRANSLATE_NOOP("lb::MainWindow", "Not checked: unreadable")},
    // The exercise's fault: one of its known mistakes cannot be drawn (exercise_panel.cpp).
    {"mistake does not build",
     QT_TRANSLATE_NOOP("lb::MainWindow", "Not checked: the exercise has a broken mistake")},
    {"mistake refused",
     QT_TRANSLATE_NOOP("lb::MainWindow", "Not checked: the exercise has a broken mistake")}};

QString notChecked(const QString &status)
{
    for (const auto &[key, sentence] : kNotChecked)
        if (status == QLatin1String(key))
            return MainWindow::tr(sentence);
    //: a check that graded nothing, for a reason this version does not know (%1, in English)
    return MainWindow::tr("Not checked: %1").arg(status);
}

} // namespace

void MainWindow::setUpExercise()
{
    m_workCheck = new WorkCheck(this);
    connect(m_sceneActions, &SceneActions::exerciseChanged, this, &MainWindow::exerciseChanged);
    connect(m_exercisePanel, &ExercisePanel::checkRequested, this, &MainWindow::checkWork);
    connect(m_exercisePanel, &ExercisePanel::cancelRequested, this, [this] {
        m_workCheck->cancel();
        m_exercisePanel->setChecking(false);
        m_exercisePanel->showProblem(tr("Check cancelled."));
    });
    connect(m_exercisePanel, &ExercisePanel::caseChosen, this, &MainWindow::showCase);
    connect(m_exercisePanel, &ExercisePanel::backRequested, this, &MainWindow::showOwnScene);
    connect(m_workCheck, &WorkCheck::finished, this, [this](const GradingReport &report) {
        m_exercisePanel->setChecking(false);
        m_exercisePanel->showReport(report);
        m_viewport->setCaseNote({}); // a case shown is of the list before
        markCheckOutOfDate();        // edited while the check ran
        m_status->showMessage(report.graded() ? tr("Checked: %1 of %2 cases pass")
                                                    .arg(report.passedCount())
                                                    .arg(report.cases.size())
                                              : notChecked(report.status),
                              10000);
    });
    connect(m_shading, &ShadingPanel::sideBFilesRequested, this, &MainWindow::chooseSideBFiles);
    connect(m_shading, &ShadingPanel::sideBClearRequested, this, [this] { setSideBFiles({}); });
    connect(&m_document, &SceneDocument::changed, this, [this](SceneParts parts) {
        if (parts & ScenePart::Compare)
            holdSideBToReference(); // a reset of the Shading panel included
    });
    // An outcome of Check my work says when the program in the editor is no longer the one
    // it was checked with.
    connect(&m_shaders, &ShaderDocument::changed, this, &MainWindow::markCheckOutOfDate);
    // While a case is shown, saves (the file, the session) write the student's own scene.
    m_sceneActions->setSceneToSave([this] { return ownScene(); });
    // The session's scene file may be an exercise.
    m_exercisePanel->setExercise(m_sceneActions->exercise());
    applySideB();
}

void MainWindow::exerciseChanged()
{
    m_workCheck->cancel();
    m_ownScene.reset();
    m_viewport->setCaseNote({});
    const std::optional<Exercise> &exercise = m_sceneActions->exercise();
    if (exercise) // its reference is side B now, not files chosen before
        m_sideBPath.clear();
    m_exercisePanel->setExercise(exercise);
    m_exercisePanel->setChecking(false);
    m_checkedProgram.reset();
    // The difference view counts the share within the exercise's tolerance, as a case does.
    m_viewport->setDifferenceTolerance(exercise ? exercise->grading.tolerance : 2);
    if (m_checkAction)
        m_checkAction->setEnabled(exercise && exercise->unread.isUndefined());
    // In presentation mode with the panels behind F6 the Exercise panel waits there too.
    m_exerciseDock->setVisible(exercise.has_value() && !panelsWaitBehindF6());
    if (exercise) // the task is the first thing to read (once its tab exists again)
        QTimer::singleShot(0, m_exerciseDock, [this] { bringForward(m_exerciseDock); });
    if (m_presentation) // a tab more or less: the names' font is measured again
        QTimer::singleShot(0, this, &MainWindow::styleDockTabs);
    applySideB();
}

void MainWindow::applySideB()
{
    // Files the user chose come first; then an exercise's reference; then the built-in
    // program with the Shading panel's side-B choices.
    const std::optional<Exercise> &e = m_sceneActions->exercise();
    const bool exerciseProgram = e && e->unread.isUndefined() && !e->reference.builtIn();
    const bool exerciseBuiltIn = e && e->unread.isUndefined() && e->reference.builtIn();
    const QString afterFiles = exerciseProgram   ? tr("the exercise's reference")
                               : exerciseBuiltIn ? tr("the exercise's reference (built-in)")
                                                 : tr("the built-in program");
    if (!m_sideBPath.isEmpty()) { // the text as read when chosen (it built then)
        const QString &name = m_sideBName;
        m_viewport->setSideBProgram(m_sideBVertex, m_sideBFragment, name);
        m_probe->setSideBReference(tr("side B (%1)").arg(name));
        m_shading->setSideB(name,
                            tr("Side B draws %1: it shades as it is written, so these choices do "
                               "nothing. The x button brings back %2.")
                                .arg(name, afterFiles),
                            true);
        return;
    }
    if (exerciseProgram) {
        m_viewport->setSideBProgram(e->reference.vertex, e->reference.fragment,
                                    tr("the exercise's reference"));
        m_probe->setSideBReference(tr("the exercise's reference"));
        m_shading->setSideB(tr("the exercise's reference"),
                            tr("Side B draws the exercise's reference program: it shades as it "
                               "is written, so these choices do nothing."),
                            false);
        return;
    }
    m_viewport->setSideBProgram({}, {});
    m_probe->setSideBReference(
        exerciseBuiltIn
            //: %1: gouraud, phong or flat; %2: phong or blinn
            ? tr("the exercise's reference (built-in, %1 shading, %2 specular)")
                  .arg(shadingLabel(e->reference.shading), specularLabel(e->reference.specular))
            : QString());
    if (exerciseBuiltIn) {
        holdSideBToReference();
        //: %1: gouraud, phong or flat; %2: phong or blinn
        m_shading->setSideB(
            tr("the built-in program, %1 shading and %2 specular (the "
               "exercise's reference)")
                .arg(shadingLabel(e->reference.shading), specularLabel(e->reference.specular)),
            tr("The exercise's reference fixes side B's choices."), false);
        return;
    }
    m_shading->setSideB(tr("the built-in program"), {}, false);
}

void MainWindow::holdSideBToReference()
{
    // The reference is the built-in program with the exercise's choices: side B is that,
    // whatever a reset or an old scene says.
    const std::optional<Exercise> &e = m_sceneActions->exercise();
    if (!m_sideBPath.isEmpty() || !e || !e->unread.isUndefined() || !e->reference.builtIn())
        return;
    const CompareSettings &c = m_document.scene().compare;
    if (c.shading != e->reference.shading || c.specular != e->reference.specular)
        m_document.edit([&](Scene &s) {
            s.compare.shading = e->reference.shading;
            s.compare.specular = e->reference.specular;
        });
}

QString MainWindow::setSideBFiles(const QString &path)
{
    if (path.isEmpty()) {
        m_sideBPath.clear();
        applySideB();
        return {};
    }
    const Submission pair = readSubmission(path);
    if (!pair.error.isEmpty()) {
        const QString message = tr("Side B is unchanged: %1").arg(pair.error);
        warnAboutSideB(this, message);
        return message;
    }
    // A pair that does not build is said now; side B keeps what it drew.
    const ProgramBuild build = m_viewport->setSideBProgram(pair.vertex, pair.fragment);
    if (!build.ok()) {
        applySideB(); // what side B drew before
        const QString message =
            tr("Side B is unchanged: %1 does not build:\n%2").arg(path, build.log());
        warnAboutSideB(this, message);
        return message;
    }
    // Kept as read: side B draws this text until other files are chosen (an edit of the
    // files afterwards is not followed; choosing them again reads them again).
    m_sideBPath = path;
    m_sideBVertex = pair.vertex;
    m_sideBFragment = pair.fragment;
    m_sideBName = pair.vertexPath == pair.fragmentPath
                      ? QFileInfo(pair.vertexPath).fileName()
                      : QString("%1 + %2").arg(QFileInfo(pair.vertexPath).fileName(),
                                               QFileInfo(pair.fragmentPath).fileName());
    applySideB();
    if (m_document.scene().compare.mode == CompareMode::Off)
        m_document.edit([](Scene &s) { s.compare.mode = CompareMode::SideBySide; });
    return {};
}

void MainWindow::chooseSideBFiles()
{
    const QString path = QFileDialog::getOpenFileName(
        this, tr("Side B: a shader pair (NAME.vert or NAME.frag) or a scene file's program"), {},
        tr("Shader pairs and scene files (*.vert *.frag *.json *.lbscene);;All files (*)"));
    if (!path.isEmpty())
        setSideBFiles(path);
}

void MainWindow::checkWork()
{
    const std::optional<Exercise> &e = m_sceneActions->exercise();
    if (!e || !e->unread.isUndefined())
        return;
    if (m_workCheck->isRunning()) {
        m_workCheck->cancel();
        m_exercisePanel->setChecking(false);
    }
    bringForward(m_exerciseDock); // the results come there
    // What the editor holds, as it would be handed in (not the last program that drew).
    m_checkedProgram.emplace(m_shaders.source(ShaderStage::Vertex),
                             m_shaders.source(ShaderStage::Fragment));
    const QString error = m_workCheck->start(m_sceneActions->exerciseScene(), *e,
                                             m_checkedProgram->first, m_checkedProgram->second);
    if (!error.isEmpty()) {
        m_exercisePanel->showProblem(tr("The check could not start: %1").arg(error));
        return;
    }
    m_exercisePanel->setChecking(true);
}

void MainWindow::markCheckOutOfDate()
{
    m_exercisePanel->setOutOfDate(
        m_checkedProgram &&
        std::pair(m_shaders.source(ShaderStage::Vertex), m_shaders.source(ShaderStage::Fragment)) !=
            *m_checkedProgram);
}

void MainWindow::showCase(int index)
{
    const std::vector<Scene> &cases = m_workCheck->cases();
    const std::optional<Exercise> &e = m_sceneActions->exercise();
    if (index < 0 || index >= int(cases.size()) || !e)
        return;
    if (!m_ownScene)
        m_ownScene = m_document.scene();
    Scene shown = cases[std::size_t(index)];
    shown.compare.mode = CompareMode::Difference;
    if (e->reference.builtIn()) {
        shown.compare.shading = e->reference.shading;
        shown.compare.specular = e->reference.specular;
    }
    m_probe->clear(); // its arrows and names belonged to the view left behind
    m_document.set(shown);
    m_exercisePanel->markShownCase(index);
    // The list's figures are the check's, at the exercise's size; the view's are its own.
    m_viewport->setCaseNote(m_exercisePanel->caseMeasured(index));
    //: "Back to my scene" is the Exercise panel's button: its name as translated there
    m_status->showMessage(tr("Case %1 in the difference view (key C: the other compare views; "
                             "\"Back to my scene\" in the Exercise panel)")
                              .arg(index),
                          10000);
}

Scene MainWindow::ownScene() const
{
    return m_ownScene ? *m_ownScene : m_document.scene();
}

void MainWindow::showOwnScene()
{
    if (m_ownScene) {
        m_probe->clear(); // a point probed on the case is no point of this view
        m_document.set(*m_ownScene);
    }
    m_ownScene.reset();
    m_exercisePanel->markShownCase(-1);
    m_viewport->setCaseNote({});
}

} // namespace lb
