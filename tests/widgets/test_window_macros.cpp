// Issue 29 in the window: the 40-doubling macro bomb typed into the editor is refused on the
// line of its use, with the macro's name, before the driver sees it (the window would grow
// to 24 GB in Mesa's preprocessor); the last good program keeps drawing and a fix brings the
// new one. A for (;;) behind a macro is named on the line of the macro's use.
#include "window_fixture.h"

using namespace lb;
using namespace lb::test;

namespace {

QStringList listed(EditorPanel *e)
{
    QStringList items;
    for (int i = 0; i < e->diagnosticsList()->count(); ++i)
        items << e->diagnosticsList()->item(i)->text();
    return items;
}

} // namespace

class TestWindowMacros : public WindowTest
{
    Q_OBJECT
private slots:
    void macroBombIsRefusedOnItsLine()
    {
        EditorPanel *e = m_window->editorPanel();
        QVERIFY(buildAfter([&] { e->loadPreset(presets()[3]); }));
        const QImage good = frame();
        ShaderEditor *fragment = e->editor(ShaderStage::Fragment);
        const QString original = fragment->text();
        QString bomb = "precision mediump float;\n#define M0 1.0\n";
        for (int i = 1; i < 40; ++i)
            bomb += QString("#define M%1 (M%2+M%2)\n").arg(i).arg(i - 1);
        bomb += "void main() { gl_FragColor = vec4(M39); }\n"; // line 42
        const std::optional<ProgramBuild> b = buildAfter([&] { fragment->setText(bomb); });
        QVERIFY(b && !b->ok());
        const QString items = listed(e).join('\n');
        QVERIFY2(items.contains("fragment 42:35  error: macro M39 expands to more than 1 MB of "
                                "text (a macro that doubles itself?): refused before the driver "
                                "sees it"),
                 qPrintable(items));
        QVERIFY(fragment->annotation(41).contains("macro M39")); // 0-based
        const QRect belowBanner(0, 40, good.width(), good.height() - 40);
        QVERIFY2(imageDifference(frame().copy(belowBanner), good.copy(belowBanner)) == 0,
                 "the last good program must keep drawing");
        QVERIFY(buildAfter([&] { fragment->setText(original); })->ok());
    }

    void loopBehindAMacroIsNamedWhereItIsUsed()
    {
        EditorPanel *e = m_window->editorPanel();
        ShaderEditor *fragment = e->editor(ShaderStage::Fragment);
        const QString looping = "#version 330 core\nout vec4 c;\n#define FOREVER for (;;)\n"
                                "void main() {\n  float x = 1.0;\n  FOREVER { x *= 0.5; }\n"
                                "  c = vec4(x);\n}\n";
        const std::optional<ProgramBuild> b = buildAfter([&] { fragment->setText(looping); });
        QVERIFY(b && !b->ok());
        const QString items = listed(e).join('\n');
        QVERIFY2(items.contains("fragment 6:3  warning: this loop never ends"), qPrintable(items));
        QVERIFY2(items.contains("fragment 6:3  error: this program never finishes a frame"),
                 qPrintable(items));
        QVERIFY2(items.contains("(the loop comes from macro FOREVER, used on this line)"),
                 qPrintable(items));
    }
};

LB_WINDOW_TEST_MAIN(TestWindowMacros)
#include "test_window_macros.moc"
