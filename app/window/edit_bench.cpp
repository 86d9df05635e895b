#include "edit_bench.h"

#include "editor_panel.h"
#include "main_window.h"
#include "presets.h"
#include "shader_editor.h"
#include "viewport.h"

#include <QCheckBox>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTimer>

#include <algorithm>
#include <cstdio>
#include <vector>

namespace lb {

namespace {

double median(std::vector<double> v)
{
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : v[v.size() / 2];
}

// Times `edits` edits of the fragment shader. Each edit adds a different comment, so no
// compiler cache can answer (bench/edit.sh also turns Mesa's off).
QJsonObject measure(MainWindow &window, const QString &name, const QString &vertex,
                    const QString &fragment, int edits)
{
    EditorPanel *editor = window.editorPanel();
    Viewport *viewport = window.viewport();
    editor->liveCheck()->setChecked(false); // the bench ends the pause itself
    editor->document()->setSources(vertex, fragment);
    std::vector<double> toPixels, raw, rawDraw, build, frameOnly;
    for (int i = 0; i < edits; ++i) {
        editor->editor(ShaderStage::Fragment)->setText(fragment + QString("\n// edit %1\n").arg(i));
        // The first frame once the program is built and adopted (a program with loops is
        // adopted when the trial helper answers).
        QEventLoop frameShown;
        bool built = false;
        const auto c0 =
            QObject::connect(viewport, &Viewport::programBuilt, &frameShown, [&] { built = true; });
        const auto c = QObject::connect(viewport, &QOpenGLWidget::frameSwapped, &frameShown, [&] {
            if (built)
                frameShown.quit();
        });
        QTimer::singleShot(10000, &frameShown, &QEventLoop::quit);
        QElapsedTimer timer;
        timer.start(); // the end of the pause
        editor->compileNow();
        build.push_back(double(timer.nsecsElapsed()) * 1e-6);
        frameShown.exec();
        toPixels.push_back(double(timer.nsecsElapsed()) * 1e-6);
        QObject::disconnect(c);
        QObject::disconnect(c0);
        // A frame with nothing rebuilt, for scale.
        QEventLoop plain;
        const auto c2 =
            QObject::connect(viewport, &QOpenGLWidget::frameSwapped, &plain, &QEventLoop::quit);
        timer.restart();
        viewport->update();
        plain.exec();
        frameOnly.push_back(double(timer.nsecsElapsed()) * 1e-6);
        QObject::disconnect(c2);
        raw.push_back(viewport->rawBuildMilliseconds(vertex + QString("\n// raw %1\n").arg(i),
                                                     fragment + QString("\n// raw %1\n").arg(i)));
        rawDraw.push_back(
            viewport->rawBuildMilliseconds(vertex + QString("\n// draw %1\n").arg(i),
                                           fragment + QString("\n// draw %1\n").arg(i), true));
    }
    QJsonObject o;
    o["shaders"] = name;
    const QString trial = qEnvironmentVariable("LIGHTBENCH_PROGRAM_TRIAL");
    o["trial"] = trial.isEmpty() ? QString("helper") : trial;
    o["fragmentLines"] = int(fragment.count('\n'));
    o["edits"] = edits;
    o["editToPixelsMs"] = median(toPixels);
    o["rawCompileLinkMs"] = median(raw);
    o["rawCompileLinkFirstDrawMs"] = median(rawDraw);
    o["buildAndShowMs"] = median(build);
    o["frameOnlyMs"] = median(frameOnly);
    o["ratioToCompileLink"] = median(toPixels) / std::max(median(raw), 1e-9);
    o["ratioToCompileLinkFirstDraw"] = median(toPixels) / std::max(median(rawDraw), 1e-9);
    return o;
}

} // namespace

int runEditBench(MainWindow &window, int edits, const QString &longVertex,
                 const QString &longFragment)
{
    const Preset &phong = builtInPreset(false), &gouraud = builtInPreset(true);
    std::vector<QJsonObject> rows{
        measure(window, "built-in Phong", phong.vertexSource(), phong.fragmentSource(), edits),
        measure(window, "built-in Gouraud", gouraud.vertexSource(), gouraud.fragmentSource(),
                edits)};
    if (!longVertex.isEmpty())
        rows.push_back(measure(window, "300-line shader", longVertex, longFragment, edits));
    for (const QJsonObject &row : rows)
        std::printf("%s\n", QJsonDocument(row).toJson(QJsonDocument::Compact).constData());
    std::fflush(stdout);
    return 0;
}

} // namespace lb
