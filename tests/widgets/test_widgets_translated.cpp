// Every text the panels and dialogs of widgets/ show goes through Qt's translation system
// (issue 31): under a translator that marks what it is asked (translation_marks.h), no word a
// user reads is left outside a mark, no free function puts its words in QObject's context,
// and the sentences once built from pieces reach the translator whole. The bad inputs tried:
// a term's word slotted untranslated into a tooltip (the material's "ambient"), a list joined
// with tr(" or "), a count choosing "decimal" or "decimals" in code, " copy" glued to a name,
// a compiler message prefixed with an English "error: ", a stage's name from the command
// line's English, GLSL (a uniform's declaration) and keys (Ctrl+Return) sent to translators.
#include "translation_marks.h"

#include "caption_dialog.h"
#include "editor_panel.h"
#include "exercise_panel.h"
#include "export_size_dialog.h"
#include "lesson_bar.h"
#include "light_panel.h"
#include "load_progress.h"
#include "material_panel.h"
#include "number_box.h"
#include "object_panel.h"
#include "preferences_dialog.h"
#include "presets.h"
#include "recent_files.h"
#include "shader_editor.h"
#include "shading_panel.h"
#include "uniform_panel.h"

#include <QApplication>
#include <QMessageBox>
#include <QPushButton>
#include <QSettings>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>

using namespace lb;
using namespace lb::test;

class TestWidgetsTranslated : public QObject
{
    Q_OBJECT
    RecordingTranslator m_translator;

    // Fails with the list of what is wrong, if anything is.
    static void expectNone(const QStringList &found)
    {
        QVERIFY2(found.isEmpty(), qPrintable(found.join('\n')));
    }

private slots:
    void initTestCase() { QCoreApplication::installTranslator(&m_translator); }
    void cleanupTestCase() { QCoreApplication::removeTranslator(&m_translator); }

    // The scene panels: labels, tooltips, combo entries, the object list; each control's
    // "Unused" tooltip names its uniforms in one translatable pattern.
    void scenePanels()
    {
        SceneDocument document;
        document.edit([](Scene &s) { s.selectedObject().name = plainText("Teapot lid"); });
        LightPanel light(&document);
        MaterialPanel material(&document);
        ObjectPanel object(&document);
        ShadingPanel shading(&document);
        const std::set<QString> data = wordsOf("Teapot lid");
        for (ScenePanel *panel :
             std::initializer_list<ScenePanel *>{&light, &material, &object, &shading}) {
            expectNone(problemsIn(panel, data));
            panel->showUsage({}); // nothing read: every control says which uniforms it lacks
            expectNone(problemsIn(panel, data));
        }
        // The term is part of each sentence, not a word slotted into one for all three.
        for (const char *source : {"%1 (%2): the material's ambient reflection coefficients",
                                   "%1 (%2): the material's diffuse reflection coefficients",
                                   "%1 (%2): the material's specular reflection coefficients"})
            QVERIFY2(m_translator.asked("lb::LightingParameters", source), source);
        for (const char *source :
             {"%1 (%2): the light's ambient intensity", "%1 (%2): the light's diffuse intensity",
              "%1 (%2): the light's specular intensity"})
            QVERIFY2(m_translator.asked("lb::LightingParameters", source), source);
        QVERIFY(m_translator.asked("lb::ScenePanel", "%1 or %2"));
        QVERIFY(!m_translator.asked("lb::ScenePanel", " or "));

        // A duplicate's name is one translatable pattern around the original's.
        object.duplicateButton()->click();
        const QString copy = displayName(document.scene().selectedObject());
        QVERIFY2(oneSentence(copy) && copy.contains("Teapot lid"), qPrintable(copy));
    }

    // The program's own uniforms: the note and the rows are translated; a uniform's GLSL
    // declaration is not (a translator must not turn "uniform float" into words).
    void uniformPanel()
    {
        SceneDocument document;
        UniformPanel panel(&document);
        expectNone(problemsIn(&panel)); // no uniforms yet
        std::vector<ActiveUniform> uniforms(3);
        for (int i = 0; i < 3; ++i)
            uniforms[std::size_t(i)].location = i;
        uniforms[0].name = "uShine";
        uniforms[0].kind = UniformKind::Float;
        uniforms[0].initial = {1.0f};
        uniforms[1].name = "uTintColour";
        uniforms[1].kind = UniformKind::Float;
        uniforms[1].width = 4;
        uniforms[1].initial = {1.0f, 0.5f, 0.25f, 1.0f};
        uniforms[2].name = "uBones";
        uniforms[2].kind = UniformKind::Matrix;
        uniforms[2].width = 4;
        panel.setUniforms(uniforms);
        QCOMPARE(panel.controlCount(), 2);
        expectNone(problemsIn(&panel, {"uShine", "uTintColour", "uBones", "uniform"}));
        bool declared = false;
        for (QWidget *w : panel.findChildren<QWidget *>())
            if (w->toolTip() == "uniform float uShine" ||
                w->toolTip() == "uniform vec4 uTintColour")
                declared = true;
        QVERIFY2(declared, "a uniform's declaration is shown as GLSL has it, unmarked");
        QVERIFY(!m_translator.asked("lb::UniformPanel", "uniform %1 %2"));
    }

    // The dialogs, the lesson bar, the load's progress and the recent files' menu.
    void dialogsAndBars()
    {
        CaptionDialog caption({{"en", "Hello"}, {"xx", "kept"}}, "de", 10);
        expectNone(problemsIn(&caption, {"en", "pt", "de"}));
        QVERIFY(m_translator.asked("lb::CaptionDialog", "German"));
        // A caption over the limit: the message names the language by its code.
        caption.field("de")->setPlainText(QString(11, 'x'));
        QString said;
        QTimer::singleShot(0, this, [&] {
            if (auto *box = qobject_cast<QMessageBox *>(QApplication::activeModalWidget())) {
                said = box->windowTitle() + '\n' + box->text();
                box->close();
            }
        });
        caption.accept();
        QVERIFY(!said.isEmpty());
        expectNone(problems(said, {"de"}));

        ExportSizeDialog size(QSize(640, 480));
        expectNone(problemsIn(&size));
        PreferencesDialog preferences(ImportLimits{}, 1.0);
        expectNone(problemsIn(&preferences));

        LessonBar bar;
        bar.showStep(1, 4, "Specular", "The *highlight* ![x](pic.png)", QString());
        expectNone(problemsIn(&bar, {"Specular", "The", "highlight"}));
        bar.showStep(2, 4, "Broken", QString(), "no such program");
        expectNone(problemsIn(&bar, {"Broken", "no", "such", "program"}));
        QVERIFY(!m_translator.asked("lb::LessonBar", "\u2715")); // a symbol, not a word

        LoadProgress progress;
        progress.start("teapot.obj");
        expectNone(problemsIn(&progress, {"teapot", "obj"}));
        progress.setProgress(0.5, "reading");
        expectNone(problemsIn(&progress, {"teapot", "obj", "reading"}));

        QTemporaryDir dir;
        QSettings settings(dir.filePath("recent.ini"), QSettings::IniFormat);
        RecentFiles recent("Recent", settings, "recent");
        expectNone(problemsIn(&recent, {"Recent"}));
        recent.add(dir.filePath("toon.json"));
        expectNone(problemsIn(&recent, wordsOf(dir.path(), {"Recent", "toon", "json"})));
    }

    // Why a box does not take a number; a count of decimals through Qt's plural forms.
    void numberBoxes()
    {
        NumberBox box;
        box.setRange(0.0, 10.0);
        for (int decimals : {0, 1, 3}) {
            box.setDecimals(decimals);
            for (const char *typed : {"abc", "1.000,5", "2.55555", "400"}) {
                box.findChild<QLineEdit *>()->setText(typed);
                expectNone(problems(box.problem()));
            }
        }
        QVERIFY(m_translator.asked("lb::NumberBox", "This box takes %n decimal(s)."));
        for (int n : {1, 3}) {
            bool counted = false;
            for (const Asked &a : m_translator.askedAll())
                counted = counted || (a.source == "This box takes %n decimal(s)." && a.n == n);
            QVERIFY2(counted, "the count goes to the translator, which picks the plural form");
        }
        IntegerBox whole;
        whole.setRange(1, 64);
        whole.setMaximumReason("(more would not fit the scene's memory)");
        whole.findChild<QLineEdit *>()->setText("100");
        expectNone(problems(whole.problem(), wordsOf("more would not fit the scene's memory")));
    }

    // The shader editor's panel: tabs with their files, the messages (the stage in the
    // user's words), the status line, the annotations under the lines.
    void editorPanel()
    {
        QTemporaryDir dir;
        ShaderDocument document;
        EditorPanel panel(&document);
        // The folder's and the files' names are data.
        std::set<QString> data = wordsOf(dir.path(), {"toon", "vert", "frag"});
        expectNone(problemsIn(&panel, data));
        // The Presets menu shows the presets' titles; their names are keys (files keep them).
        for (QAction *preset : panel.presetsMenu()->actions())
            QVERIFY2(oneSentence(preset->text()) && preset->text().contains("lb::Presets|"),
                     qPrintable(preset->text()));
        QVERIFY(panel.saveAs(dir.filePath("toon.vert")).isEmpty());
        expectNone(problemsIn(&panel, data));
        for (QTabBar *tabs : panel.findChildren<QTabBar *>())
            if (tabs->count() == 2)
                for (int i = 0; i < 2; ++i)
                    QVERIFY2(oneSentence(tabs->tabText(i)), qPrintable(tabs->tabText(i)));

        ProgramBuild build;
        build.diagnostics = {{Diagnostic::Severity::Error, ShaderStage::Fragment, 1, 1, "oops"},
                             {Diagnostic::Severity::Warning, ShaderStage::Vertex, 1, 0, "hmm"},
                             {Diagnostic::Severity::Error, ShaderStage::Link, 0, 0, "unlinked"}};
        panel.showBuild(build);
        const std::set<QString> said{"oops", "hmm", "unlinked"};
        data.insert(said.begin(), said.end());
        expectNone(problemsIn(&panel, data));
        QCOMPARE(panel.diagnosticsList()->count(), 3);
        for (int i = 0; i < 3; ++i)
            QVERIFY2(oneSentence(panel.diagnosticsList()->item(i)->text()),
                     qPrintable(panel.diagnosticsList()->item(i)->text()));
        for (ShaderStage stage : {ShaderStage::Vertex, ShaderStage::Fragment})
            expectNone(problems(panel.editor(stage)->annotation(0), said));
        // The words without their colour's markup, which is no translator's business.
        expectNone(problems(
            QTextDocumentFragment::fromHtml(panel.statusLabel()->text()).toPlainText(), said));
        build.diagnostics.resize(1);
        build.diagnostics[0].severity = Diagnostic::Severity::Warning;
        build.linked = true;
        panel.showBuild(build);
        QVERIFY(m_translator.asked("lb::EditorPanel", "linked, %n warning(s)"));
        // Keys are keys: Ctrl+Return is not a text to translate.
        QVERIFY(!m_translator.asked("lb::EditorPanel", "Ctrl+Return"));

        ShaderOrigin origin;
        origin.kind = ShaderOrigin::Kind::Scene;
        origin.edited = true;
        expectNone(problems(programDisplayName(origin)));
        origin.kind = ShaderOrigin::Kind::Preset;
        origin.name = presets().back().name; // a key, in English
        QVERIFY(oneSentence(programDisplayName(origin)));
        expectNone(problems(programDisplayName(origin)));
    }

    // The exercise panel: what an exercise is, its reference and grading, each kind of
    // outcome (the report's status words are data: compared, not shown).
    void exercisePanel()
    {
        ExercisePanel panel;
        expectNone(problemsIn(&panel));
        Exercise exercise;
        exercise.title = {{"en", "Per fragment"}};
        exercise.task = {{"en", "Write it"}};
        exercise.reference.shading = Shading::Gouraud;
        panel.setExercise(exercise);
        const std::set<QString> data = wordsOf("Per fragment Write it");
        expectNone(problemsIn(&panel, data));
        QVERIFY(m_translator.asked("lb::ChoiceLabels", "gouraud", "shading"));
        exercise.grading.vary = 0;
        panel.setExercise(exercise);
        expectNone(problemsIn(&panel, data));
        panel.setChecking(true);
        expectNone(problemsIn(&panel, data));
        panel.setChecking(false);

        const QStringList statuses{"does not compile", "does not link",   "refused",
                                   "timed out",        "could not start", "unreadable"};
        for (const QString &status : statuses)
            for (const QString &why : {QString(), QString("toon.frag:3: boom")}) {
                GradingReport report;
                report.status = status;
                report.diagnostic = why;
                panel.showReport(report);
                const QString text = panel.summaryLabel()->text();
                QVERIFY2(oneSentence(text), qPrintable(text));
                expectNone(problems(text, wordsOf(why + " unreadable")));
            }
        GradingReport report;
        report.status = "graded";
        report.cases.resize(3);
        report.cases[0] = {0, {-1, -1}, 1.0, 900, true};
        report.cases[1] = {40, {3, 4}, 0.5, 900, false};
        report.cases[2] = {0, {-1, -1}, 1.0, 0, false};
        panel.showReport(report);
        expectNone(problemsIn(&panel, data));
        panel.setOutOfDate(true);
        expectNone(problemsIn(&panel, data));
        // The varied aspects are the panel's own words, not QObject's.
        QVERIFY(m_translator.asked("lb::ExercisePanel", "light position"));
    }
};

int main(int argc, char **argv)
{
    QApplication app(argc, argv);
    TestWidgetsTranslated test;
    return QTest::qExec(&test, argc, argv);
}

#include "test_widgets_translated.moc"
