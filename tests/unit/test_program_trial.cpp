// The program's trial on scripted frame times: what it accepts, what it refuses, and that a
// stall or a big mesh's fixed cost does not refuse a light program.
#include "program_trial.h"

#include <QTest>

#include <cmath>
#include <functional>
#include <vector>

using namespace lb;

namespace {
const QString kVertex = "attribute vec4 vPosition;\nvoid main() { gl_Position = vPosition; }\n";
// A loop on line 4, so the program is timed (and a refusal points there).
const QString kFragment = "precision mediump float;\nuniform float n;\nvoid main() {\n"
                          "  float x = 0.0; for (int i = 0; i < 8; ++i) { x += n; }\n"
                          "  gl_FragColor = vec4(x);\n}\n";
const QSize kTarget(800, 600);

double pixelsOf(QSize s)
{
    return double(s.width()) * double(s.height());
}
} // namespace

using Script = std::function<double(QSize, int)>; // a frame's size, the call's number -> ms
Q_DECLARE_METATYPE(Script)

class TestProgramTrial : public QObject
{
    Q_OBJECT
private slots:
    void scriptedFrames_data()
    {
        QTest::addColumn<Script>("script");
        QTest::addColumn<bool>("refused");
        // The built-in programs: about a millisecond whatever the size.
        QTest::newRow("light") << Script([](QSize s, int) { return 0.5 + 1e-6 * pixelsOf(s); })
                               << false;
        // A 1M-triangle mesh: 140 ms a frame whatever the size, +3 ms of jitter on the larger
        // tiny frames; the two-point estimate says seconds, the confirming frame says no.
        QTest::newRow("big mesh, jitter") << Script([](QSize s, int) {
            return 140.0 + (pixelsOf(s) > 1000.0 ? 3.0 : 0.0) + 1e-5 * pixelsOf(s);
        }) << false;
        // A stall on one sample: the quicker of two is taken.
        QTest::newRow("stall") << Script([](QSize s, int call) {
            return (call == 3 ? 60.0 : 0.5) + 1e-6 * pixelsOf(s);
        }) << false;
        // The freezing loop below, with a stall (another process on the cores) in its small
        // frame that makes it slower than the larger one: no per-pixel cost shows, and an
        // estimate from the difference would let it draw.
        QTest::newRow("stall hides the per-pixel cost") << Script([](QSize s, int) {
            return pixelsOf(s) > 200.0 && pixelsOf(s) < 400.0 ? 200.0 : 0.1 * pixelsOf(s);
        }) << true;
        // The freezing loop: ~0.1 ms a pixel; 48 s at 800x600.
        QTest::newRow("slow per pixel")
            << Script([](QSize s, int) { return 0.1 * pixelsOf(s); }) << true;
    }
    void scriptedFrames()
    {
        QFETCH(Script, script);
        QFETCH(bool, refused);
        int calls = 0;
        double spent = 0.0;
        const TrialResult r =
            tryProgram(kVertex, kFragment, kTarget, 1000.0, kWindowTrial, [&](QSize s) {
                const double ms = script(s, calls++);
                spent += ms;
                return ms;
            });
        QCOMPARE(r.refusal.has_value(), refused);
        if (refused) {
            QCOMPARE(r.refusal->line, 4);
            QVERIFY(r.refusal->message.contains("at 800x600 would take more than"));
            QVERIFY(r.estimatedMs > 10000.0);
        }
        // What the trial drew stays small: a quarter of a second of frames at most here.
        QVERIFY2(spent < 400.0 + 5 * 143.0, qPrintable(QString::number(spent)));
    }

    // What an accepted program's trial says about bigger frames (the view grown, an export):
    // a per-pixel cost grows with them; a light one, or one as cheap as the built-in program
    // on a big mesh, is never refused for its size.
    void biggerFramesFromTheTrial()
    {
        const auto perPixel = [](QSize s) { return 0.5 + 1e-3 * pixelsOf(s); }; // 480 ms here
        TrialResult r = tryProgram(kVertex, kFragment, kTarget, 1000.0, kWindowTrial, perPixel);
        QVERIFY(!r.refusal && !r.light && !r.nearReference);
        QVERIFY(qAbs(r.estimateAt(pixelsOf(kTarget)) - r.estimatedMs) < 1e-6);
        QVERIFY(!r.overBudgetAt(pixelsOf(kTarget), 1000.0));
        QVERIFY(r.overBudgetAt(pixelsOf(QSize(1920, 1080)), 1000.0)); // ~2 s
        QVERIFY(qAbs(r.estimateAt(pixelsOf(QSize(1920, 1080))) - 2074.1) < 5.0);

        // Under a millisecond at 32x32: the difference is noise, whatever it estimates.
        r = tryProgram(kVertex, kFragment, QSize(2000, 1500), 1000.0, kWindowTrial,
                       [](QSize s) { return pixelsOf(s) > 1000.0 ? 0.95 : 0.05; });
        QVERIFY(!r.refusal && r.light);
        QVERIFY(!r.overBudgetAt(pixelsOf(QSize(8000, 8000)), 1000.0));

        // A big mesh: 140 ms whatever the size, the built-in program the same.
        const auto mesh = [](QSize s) { return 140.0 + 1e-6 * pixelsOf(s); };
        r = tryProgram(kVertex, kFragment, kTarget, 100.0, kWindowTrial, mesh, mesh);
        QVERIFY(!r.refusal && r.nearReference);
        QVERIFY(!r.overBudgetAt(pixelsOf(QSize(4000, 3000)), 100.0));
    }

    void programsWithoutLoopsAreTimedToo()
    {
        // 25,000 lines of sin() and no loop took 4 minutes a frame: a program needs no loop
        // to be slow. Scripted: 2 ms per 1000 pixels, over the 100 ms budget at 640x480.
        int calls = 0;
        const auto slow = [&](QSize s) {
            ++calls;
            return 2e-3 * pixelsOf(s);
        };
        const QString fragment = "void main() {\n  gl_FragColor = vec4(sin(sin(1.0)));\n}\n";
        TrialResult r = tryProgram(kVertex, fragment, kTarget, 100.0, kWindowTrial, slow);
        QVERIFY(calls > 0);
        QVERIFY(r.refusal);
        QVERIFY2(r.refusal->message.startsWith(
                     "drawing one frame with this program at 800x600 would take more than"),
                 qPrintable(r.refusal->message));
        QCOMPARE(r.refusal->line, 0); // no loop to point at: the fragment shader as a whole
        QCOMPARE(r.refusal->stage, ShaderStage::Fragment);
        // A light one is drawn.
        r = tryProgram(kVertex, fragment, kTarget, 100.0, kWindowTrial,
                       [](QSize s) { return 1e-6 * pixelsOf(s); });
        QVERIFY(!r.refusal);
    }

    void aLoopWithNoWayOutIsRefusedWithoutDrawing()
    {
        int calls = 0;
        const TrialResult r =
            tryProgram(kVertex, "void main() {\n  float x;\n  for (;;) { x += 1.0; }\n}\n", kTarget,
                       1000.0, kWindowTrial, [&](QSize) {
                           ++calls;
                           return 0.0;
                       });
        QVERIFY(r.refusal);
        QCOMPARE(r.refusal->line, 3);
        QVERIFY(r.refusal->message.contains("never finishes a frame"));
        QCOMPARE(calls, 0);
    }
    // A loop the reader cannot bound, run until the driver cuts it short (llvmpipe: 65,535
    // steps), is far over the budget on the small frames: the larger one drawn a second time
    // refuses it, with no bigger frame (issue 47: 3.9 s a runaway's child before).
    void farOverTheBudgetIsRefusedOnTheSmallFrames()
    {
        std::vector<QSize> drawn;
        const TrialResult r =
            tryProgram(kVertex, kFragment, kTarget, 1000.0, kWindowTrial, [&](QSize s) {
                drawn.push_back(s);
                return 0.2 * pixelsOf(s); // 96 s at 800x600
            });
        QVERIFY(r.refusal);
        QCOMPARE(r.refusal->line, 4);
        QCOMPARE(int(drawn.size()), 4); // the code's first frame, the small, the large twice
        QCOMPARE(drawn[2], drawn[3]);
        for (QSize s : drawn)
            QVERIFY(pixelsOf(s) <= 1100.0);
    }

    // Tiny frames shade more pixels than they cover (blocks shaded whole along the object's
    // edge: a cost of the edge's length, the square root of the pixels): bigger frames, each
    // 4 times the one before, correct the estimate until it is under the budget. Scripted:
    // 521 ms at 800x600, against the 700 ms budget; the two tiny frames alone said 1.07 s.
    void biggerFramesCorrectTheTinyOnes()
    {
        std::vector<QSize> drawn;
        const auto edgy = [&](QSize s) {
            drawn.push_back(s);
            return 1e-3 * (pixelsOf(s) + 60.0 * std::sqrt(pixelsOf(s)));
        };
        TrialResult r = tryProgram(kVertex, kFragment, kTarget, 700.0, kWindowTrial, edgy);
        QVERIFY2(!r.refusal, qPrintable(r.refusal ? r.refusal->message : QString()));
        QVERIFY2(r.estimatedMs > 521.0 && r.estimatedMs < 700.0,
                 qPrintable(QString::number(r.estimatedMs)));
        QVERIFY(pixelsOf(drawn.back()) < 0.1 * pixelsOf(kTarget)); // never near the target
        // Under a budget of 400 ms it is refused, after as many frames.
        drawn.clear();
        r = tryProgram(kVertex, kFragment, kTarget, 400.0, kWindowTrial, edgy);
        QVERIFY(r.refusal);
        QVERIFY(r.refusal->message.contains("more than its budget of 400 ms"));
    }

    // Every timed frame has the target's shape: a square frame of a wide target holds more
    // of the object than the target does, so each of its pixels costs more.
    void framesHaveTheTargetsShape()
    {
        const QSize wide(1920, 1080);
        std::vector<QSize> drawn;
        tryProgram(kVertex, kFragment, wide, 100.0, kWindowTrial, [&](QSize s) {
            drawn.push_back(s);
            return 1e-3 * pixelsOf(s);
        });
        QVERIFY(drawn.size() > 4);
        for (std::size_t i = 1; i < drawn.size(); ++i) // (the first one compiles the code)
            QVERIFY2(qAbs(double(drawn[i].width()) / drawn[i].height() - 16.0 / 9.0) < 0.15,
                     qPrintable(QString("%1x%2").arg(drawn[i].width()).arg(drawn[i].height())));
    }

    // The refusal names the budget, never the figure measured: two runs of one program, 20%
    // apart (a busy machine), and programs 1.5 to 300 times over the budget, say the same words.
    void theMessageSaysNoFigure()
    {
        QStringList messages;
        for (double msPerPixel : {3e-3, 6e-2, 6e-1})
            for (double load : {1.0, 1.2}) {
                const TrialResult r =
                    tryProgram(kVertex, kFragment, kTarget, 1000.0, kWindowTrial,
                               [&](QSize s) { return load * msPerPixel * pixelsOf(s); });
                QVERIFY(r.refusal);
                messages << r.refusal->message;
            }
        messages.removeDuplicates();
        QCOMPARE(messages, QStringList{"drawing one frame with this program at 800x600 would take "
                                       "more than its budget of 1.0 s: an endless or very long "
                                       "loop?"});
    }
};

QTEST_APPLESS_MAIN(TestProgramTrial)
#include "test_program_trial.moc"
