// The window's program pipeline on a scripted host (no window, no OpenGL, no helper: the
// trials run in the host, as when there is no helper): what draws, what is refused and why,
// what comes back, and what the window is told, for a program asked for before the context,
// one that does not build, one too slow, a view that grows, a lost context, an object that
// arrives after the trial. And the loop reading they share: read once, in the language of the
// moment.
#include "loops.h"
#include "program_pipeline.h"
#include "scene.h"

#include <QTest>
#include <QTranslator>

using namespace lb;

namespace {
const QString kVertex = "attribute vec4 vPosition;\nvoid main() { gl_Position = vPosition; }\n";
// A loop, so the program is timed; `n` makes each one a different program.
QString fragment(int n)
{
    return QString("precision mediump float;\nvoid main() {\n  float x = 0.0;\n"
                   "  for (int i = 0; i < %1; ++i) { x += 0.1; }\n  gl_FragColor = vec4(x);\n}\n")
        .arg(n);
}

// Builds what it is given unless the fragment says "oops"; a frame costs `perPixelMs` per
// pixel with the user program drawing, next to nothing with the built-in one.
class ScriptedHost : public WindowProgramHost
{
public:
    bool context = false;
    bool object = true;
    QSize view{400, 300};
    double perPixelMs = 1e-6;
    ProgramSources drawing; // empty: the built-in program
    int renewed = 0, builds = 0;
    Scene sceneValue;

    ProgramBuild use(const ProgramSources &sources,
                     const std::function<std::optional<Diagnostic>()> &trial) override
    {
        ++builds;
        ProgramBuild build;
        if (sources.fragment.contains("oops")) {
            Diagnostic d;
            d.message = "syntax error";
            d.line = 3;
            build.diagnostics.push_back(d);
            return build;
        }
        build.linked = true;
        const ProgramSources before = drawing;
        drawing = sources;
        if (trial)
            if (const std::optional<Diagnostic> refusal = trial()) {
                drawing = before;
                build.linked = false;
                build.diagnostics.push_back(*refusal);
            }
        return build;
    }
    double timeFrame(QSize pixels) override
    {
        return drawing.isEmpty() ? 0.1 : 0.2 + perPixelMs * pixels.width() * pixels.height();
    }
    double timeBuiltInFrame(QSize) override { return 0.1; }
    bool hasContext() const override { return context; }
    bool hasObject() const override { return object; }
    QSize viewPixels() const override { return view; }
    const Scene &scene() const override { return sceneValue; }
    std::shared_ptr<const Mesh> objectMesh() const override { return nullptr; }
    bool drawsUserProgram() const override { return !drawing.isEmpty(); }
    void useBuiltIn() override { drawing = {}; }
    ProgramBuild buildCandidate(const ProgramSources &) override { return {}; }
    bool hasCandidate() const override { return false; }
    void prepareCandidate() override {}
    void adoptCandidate() override {}
    void dropCandidate() override {}
    void renewContext() override { ++renewed; }
};

// Every message in brackets: a catalogue that says something else than English.
class BracketTranslator : public QTranslator
{
public:
    bool isEmpty() const override { return false; }
    QString translate(const char *, const char *source, const char *, int) const override
    {
        return QString("[%1]").arg(QString::fromUtf8(source));
    }
};

struct Told
{
    bool failed = false;
    QString why;
    bool builtInDrawing = false;
    std::vector<ProgramBuild> builds;
};

void listen(ProgramPipeline &pipeline, Told &told)
{
    QObject::connect(&pipeline, &ProgramPipeline::stateChanged,
                     [&told](bool failed, const QString &why, bool builtIn) {
                         told.failed = failed;
                         told.why = why;
                         told.builtInDrawing = builtIn;
                     });
    QObject::connect(&pipeline, &ProgramPipeline::built,
                     [&told](const ProgramBuild &build) { told.builds.push_back(build); });
}
} // namespace

class TestProgramPipeline : public QObject
{
    Q_OBJECT
private slots:
    void askedBeforeTheContextIsBuiltInIt()
    {
        ScriptedHost host;
        ProgramPipeline pipeline(&host);
        pipeline.setTrialMode(ProgramPipeline::TrialMode::Window);
        Told told;
        listen(pipeline, told);
        pipeline.submit({kVertex, fragment(1)});
        QCOMPARE(host.builds, 0);
        QVERIFY(told.builds.empty());
        host.context = true;
        pipeline.contextReady();
        QCOMPARE(host.drawing, (ProgramSources{kVertex, fragment(1)}));
        QCOMPARE(told.builds.size(), std::size_t(1));
        QVERIFY(told.builds.back().ok());
        QVERIFY(!told.failed);
        QVERIFY(pipeline.drawingTrial().has_value()); // it has a loop: timed
        // A new context builds the good program again, untried.
        host.drawing = {};
        pipeline.contextReady();
        QCOMPARE(host.drawing, (ProgramSources{kVertex, fragment(1)}));
        QCOMPARE(told.builds.size(), std::size_t(1));
    }

    void aBuildErrorKeepsTheLastGoodProgram()
    {
        ScriptedHost host;
        host.context = true;
        ProgramPipeline pipeline(&host);
        pipeline.setTrialMode(ProgramPipeline::TrialMode::Window);
        Told told;
        listen(pipeline, told);
        pipeline.submit({kVertex, fragment(1)});
        pipeline.submit({kVertex, fragment(2) + "oops"});
        QCOMPARE(host.drawing, (ProgramSources{kVertex, fragment(1)}));
        QVERIFY(told.failed);
        QVERIFY(told.why.isEmpty()); // not refused: it did not build
        QVERIFY(!told.builtInDrawing);
        QCOMPARE(told.builds.back().diagnostics.front().line, 3);
    }

    void aProgramTooSlowIsRefusedOnItsLoop()
    {
        ScriptedHost host;
        host.context = true;
        host.perPixelMs = 0.01; // 1.2 s at 400x300
        ProgramPipeline pipeline(&host);
        pipeline.setTrialMode(ProgramPipeline::TrialMode::Window);
        pipeline.setFrameBudget(100.0);
        Told told;
        listen(pipeline, told);
        pipeline.submit({kVertex, fragment(1)});
        QVERIFY(host.drawing.isEmpty()); // the built-in program goes on
        QVERIFY(told.failed);
        QVERIFY2(told.why.contains("budget"), qPrintable(told.why));
        QVERIFY(told.builtInDrawing);
        const Diagnostic &refusal = told.builds.back().diagnostics.back();
        QCOMPARE(refusal.line, 4); // the loop's line
        QVERIFY(!pipeline.drawingTrial().has_value());
    }

    void aViewThatGrowsPastTheBudgetBringsTheOneBeforeBack()
    {
        ScriptedHost host;
        host.context = true;
        host.perPixelMs = 1e-3; // 120 ms at 400x300, 2 s at 1920x1080
        ProgramPipeline pipeline(&host);
        pipeline.setTrialMode(ProgramPipeline::TrialMode::Window);
        pipeline.setFrameBudget(200.0);
        Told told;
        listen(pipeline, told);
        pipeline.submit({kVertex, fragment(1)});
        pipeline.submit({kVertex, fragment(2)});
        QCOMPARE(host.drawing, (ProgramSources{kVertex, fragment(2)}));
        QVERIFY(pipeline.tooSlowAt(host.view).isEmpty());
        QVERIFY(!pipeline.tooSlowAt(QSize(1920, 1080)).isEmpty());
        host.view = QSize(1920, 1080);
        pipeline.viewResized();
        QCOMPARE(host.drawing, (ProgramSources{kVertex, fragment(1)})); // the one before
        QVERIFY(told.failed);
        QVERIFY(told.why.contains("1920x1080"));
        QVERIFY(!told.builtInDrawing);
        QCOMPARE(told.builds.back().diagnostics.back().line, 4);
        QCOMPARE(host.renewed, 0); // the same context
    }

    void aLostContextRefusesTheProgramThatDrew()
    {
        ScriptedHost host;
        host.context = true;
        ProgramPipeline pipeline(&host);
        pipeline.setTrialMode(ProgramPipeline::TrialMode::Window);
        Told told;
        listen(pipeline, told);
        pipeline.submit({kVertex, fragment(1)});
        pipeline.contextLost();
        QCOMPARE(host.renewed, 1);
        QVERIFY(told.failed);
        QVERIFY(told.why.contains("context was lost"));
        QVERIFY(told.builtInDrawing); // nothing good before it
        QCOMPARE(told.builds.size(), std::size_t(2));
        // The new context draws the built-in program: nothing to build.
        host.drawing = {};
        const int builds = host.builds;
        pipeline.contextReady();
        QCOMPARE(host.builds, builds);
    }

    void aProgramTriedOnAnEmptyViewIsTriedAgainOnTheObject()
    {
        ScriptedHost host;
        host.context = true;
        host.object = false; // a mesh file still loading
        ProgramPipeline pipeline(&host);
        pipeline.setTrialMode(ProgramPipeline::TrialMode::Window);
        pipeline.submit({kVertex, fragment(1)});
        const int builds = host.builds;
        pipeline.objectArrived(); // still no object: nothing
        QCOMPARE(host.builds, builds);
        host.object = true;
        pipeline.objectArrived();
        QCOMPARE(host.builds, builds + 1);
        pipeline.objectArrived(); // tried on it now: not again
        QCOMPARE(host.builds, builds + 1);
    }

    // A reading is kept (the build, the trial and the window ask of the same text), but
    // its messages are the catalogue's of the moment: a new catalogue reads again.
    void theSharedLoopReadingFollowsTheCatalogue()
    {
        const QString endless = "void main() { for (;;) { } }\n";
        const auto english = endlessLoopWarnings(endless, ShaderStage::Fragment);
        QCOMPARE(english.size(), std::size_t(1));
        QVERIFY(!english.front().message.startsWith('['));
        QCOMPARE(endlessLoopWarnings(endless, ShaderStage::Fragment).front().message,
                 english.front().message);
        BracketTranslator brackets;
        QCoreApplication::installTranslator(&brackets);
        const auto translated = endlessLoopWarnings(endless, ShaderStage::Fragment);
        QCoreApplication::removeTranslator(&brackets);
        QVERIFY2(translated.front().message.startsWith('['),
                 qPrintable(translated.front().message));
        QCOMPARE(endlessLoopWarnings(endless, ShaderStage::Fragment).front().message,
                 english.front().message);
        // The stage is part of what is kept: the vertex stage's reading is its own.
        QCOMPARE(endlessLoopWarnings(endless, ShaderStage::Vertex).front().stage,
                 ShaderStage::Vertex);
    }

    void withTrialsOffAProgramIsDrawnUntried()
    {
        ScriptedHost host;
        host.context = true;
        host.perPixelMs = 1.0; // anything tried would be refused
        ProgramPipeline pipeline(&host);
        pipeline.setTrialMode(ProgramPipeline::TrialMode::Off);
        Told told;
        listen(pipeline, told);
        pipeline.submit({kVertex, fragment(1)});
        QVERIFY(told.builds.back().ok()); // Off: drawn untried
        QVERIFY(!pipeline.drawingTrial().has_value());
    }
};

QTEST_GUILESS_MAIN(TestProgramPipeline)
#include "test_program_pipeline.moc"
