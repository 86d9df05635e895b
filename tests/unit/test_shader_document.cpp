// The shader document without a window: built-in tracking, edits, file pairs and the disk,
// scene programs and the session settings.
#include "presets.h"
#include "scene_file.h"
#include "shader_document.h"

#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSettings>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <sys/stat.h>

using namespace lb;

namespace {

bool writeFile(const QString &path, const QString &text)
{
    QFile f(path);
    return f.open(QIODevice::WriteOnly | QIODevice::Truncate) &&
           f.write(text.toUtf8()) == text.toUtf8().size();
}

QString readFile(const QString &path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? QString::fromUtf8(f.readAll()) : QString();
}

const Preset &toon()
{
    return presets().back();
}

} // namespace

class TestShaderDocument : public QObject
{
    Q_OBJECT
private:
    QTemporaryDir m_dir;

private slots:
    // Undoing a replacement stage by stage brings the whole document back: origin, files,
    // built-in; what the slides' presets fix and what an edited built-in keeps follow.
    void undoingAReplacementBringsTheDocumentBack()
    {
        const QString base = m_dir.filePath("mine");
        QVERIFY(writeFile(base + ".vert", toon().vertexSource()));
        QVERIFY(writeFile(base + ".frag", toon().fragmentSource() + "// mine\n"));
        ShaderDocument d;
        QCOMPARE(d.openFiles({base + ".vert"}), QString());
        d.setSource(ShaderStage::Fragment, d.source(ShaderStage::Fragment) + "// typed\n");
        const QString vertex = d.source(ShaderStage::Vertex);
        const QString fragment = d.source(ShaderStage::Fragment);
        const ShaderOrigin origin = d.origin();
        QVERIFY(origin.edited);
        QVERIFY(!d.fixedModel().gouraud); // a file's program is free

        d.loadPreset(presets()[2]); // the slides' Gouraud: fixes Gouraud, N.H and V
        QVERIFY(d.fixedModel().gouraud && *d.fixedModel().gouraud);
        QCOMPARE(d.fixedModel().specular, std::optional(SpecularModel::Blinn));
        QVERIFY(d.fixedModel().parallelView);
        QVERIFY(!d.otherStageAwaitsUndo(ShaderStage::Fragment));
        // The editor's Ctrl+Z on the fragment stage: the vertex stage should follow.
        d.setSource(ShaderStage::Fragment, fragment);
        QVERIFY(d.otherStageAwaitsUndo(ShaderStage::Fragment));
        d.setSource(ShaderStage::Vertex, vertex);
        QVERIFY(!d.otherStageAwaitsUndo(ShaderStage::Vertex));
        QCOMPARE(d.origin(), origin);
        QCOMPARE(d.filePath(ShaderStage::Fragment), QFileInfo(base + ".frag").absoluteFilePath());
        QVERIFY(d.isModified(ShaderStage::Fragment)); // the typed line is still unsaved
        QVERIFY(!d.isModified(ShaderStage::Vertex));
        QVERIFY(!d.fixedModel().gouraud);

        // An edited built-in Gouraud program keeps its shading; replaced and brought back,
        // it keeps it again.
        d.loadPreset(builtInPreset(true));
        QVERIFY(!d.fixedModel().gouraud); // untouched: it follows the panel
        d.setSource(ShaderStage::Vertex, d.source(ShaderStage::Vertex) + "// note\n");
        QVERIFY(d.fixedModel().gouraud && *d.fixedModel().gouraud);
        const QString edited = d.source(ShaderStage::Vertex);
        const QString builtInFragment = d.source(ShaderStage::Fragment);
        d.loadPreset(builtInPreset(false));
        d.setSource(ShaderStage::Vertex, edited);
        d.setSource(ShaderStage::Fragment, builtInFragment);
        QCOMPARE(d.builtInBase(), std::optional<bool>(true));
        QVERIFY(d.fixedModel().gouraud && *d.fixedModel().gouraud);
    }

    void builtInFollowsTheShadingUntilEdited()
    {
        ShaderDocument d;
        QSignalSpy compiles(&d, &ShaderDocument::compileRequested);
        d.loadPreset(builtInPreset(false));
        QCOMPARE(compiles.size(), 1); // a loaded program is asked for at once
        QVERIFY(d.showsBuiltIn());
        QVERIFY(!d.program()); // scene files store none: the shading mode's built-in
        QCOMPARE(d.origin(), (ShaderOrigin{ShaderOrigin::Kind::Preset, builtInPreset(false).name}));

        d.followShading(true);
        QCOMPARE(d.source(ShaderStage::Vertex), builtInPreset(true).vertexSource());
        QVERIFY(d.showsBuiltIn());
        QCOMPARE(d.origin().name, builtInPreset(true).name);

        d.setSource(ShaderStage::Fragment, d.source(ShaderStage::Fragment) + "// mine\n");
        QVERIFY(!d.showsBuiltIn());
        d.followShading(false); // the user's program stays
        QCOMPARE(d.source(ShaderStage::Vertex), builtInPreset(true).vertexSource());
        QVERIFY(d.program());
        QVERIFY(d.program()->edited);
        QCOMPARE(d.program()->name, plainText(builtInPreset(true).name));
    }

    void anEditMarksTheStageModifiedAndTheOriginEdited()
    {
        ShaderDocument d;
        d.loadPreset(toon());
        QVERIFY(!d.isModified());
        QVERIFY(!d.origin().edited);
        QSignalSpy files(&d, &ShaderDocument::filesChanged);
        QSignalSpy changed(&d, &ShaderDocument::changed);
        QSignalSpy compiles(&d, &ShaderDocument::compileRequested);
        const QString original = d.source(ShaderStage::Vertex);
        d.setSource(ShaderStage::Vertex, original + "// edit\n");
        QVERIFY(d.isModified(ShaderStage::Vertex));
        QVERIFY(!d.isModified(ShaderStage::Fragment));
        QCOMPARE(d.origin(), (ShaderOrigin{ShaderOrigin::Kind::Preset, toon().name, true}));
        QCOMPARE(files.size(), 1);
        QCOMPARE(changed.size(), 1);
        QCOMPARE(compiles.size(), 0); // typing: the view decides when to compile
        d.setSource(ShaderStage::Vertex, original + "// edit again\n");
        QCOMPARE(files.size(), 1); // no new modified flag, nothing new to show in the tabs
        // Back to the text as loaded: no longer modified (as an undo to the save point).
        d.setSource(ShaderStage::Vertex, original);
        QVERIFY(!d.isModified());
        QVERIFY(!d.origin().edited);
        d.requestCompile();
        QCOMPARE(compiles.size(), 1);
        QCOMPARE(compiles[0][0].toString(), original);
    }

    void openTakesAPairOrFindsThePartner()
    {
        const QString vert = m_dir.filePath("lecture.vert"), frag = m_dir.filePath("lecture.frag");
        QVERIFY(writeFile(vert, "// v\n") && writeFile(frag, "// f\n"));
        ShaderDocument d;
        d.loadPreset(builtInPreset(false));
        QCOMPARE(d.openFiles({vert, frag}), QString());
        QCOMPARE(d.source(ShaderStage::Vertex), QString("// v\n"));
        QCOMPARE(d.source(ShaderStage::Fragment), QString("// f\n"));
        QCOMPARE(d.origin(), (ShaderOrigin{ShaderOrigin::Kind::Files, "lecture"}));
        QVERIFY(!d.showsBuiltIn());
        QVERIFY(!d.isModified());

        ShaderDocument single;
        QCOMPARE(single.openFiles({frag}), QString()); // the .vert comes along
        QCOMPARE(single.filePath(ShaderStage::Vertex), QFileInfo(vert).absoluteFilePath());
        QCOMPARE(single.filePath(ShaderStage::Fragment), QFileInfo(frag).absoluteFilePath());
        QCOMPARE(single.source(ShaderStage::Vertex), QString("// v\n"));

        // A file that cannot be read changes nothing.
        QVERIFY(single.openFiles({m_dir.filePath("missing.vert")}).contains("Cannot open"));
        QCOMPARE(single.source(ShaderStage::Vertex), QString("// v\n"));
        QCOMPARE(single.filePath(ShaderStage::Vertex), QFileInfo(vert).absoluteFilePath());
        // Nor does a FIFO (it would wait for a writer) or a file too big for a shader: refused
        // before reading, the path and the limit named.
        const QString fifo = m_dir.filePath("fifo.frag"), big = m_dir.filePath("big.frag");
        QCOMPARE(::mkfifo(QFile::encodeName(fifo).constData(), 0600), 0);
        QVERIFY(single.openFiles({fifo}).contains(fifo + ": not a regular file"));
        QFile b(big);
        QVERIFY(b.open(QIODevice::WriteOnly));
        b.write(QByteArray(1024 * 1024 + 1, ' '));
        b.close();
        QVERIFY(
            single.openFiles({big}).contains("1025 KiB is more than a shader may be (1024 KiB)"));
        QCOMPARE(single.source(ShaderStage::Vertex), QString("// v\n"));
    }

    void saveAsWritesBothFilesAndSaveClearsModified()
    {
        ShaderDocument d;
        QVERIFY(d.save().contains("Save As")); // no files yet
        d.loadPreset(toon());
        d.setSource(ShaderStage::Fragment, d.source(ShaderStage::Fragment) + "// mine\n");
        const QString base = m_dir.filePath("pair");
        QCOMPARE(d.saveAs(base + ".frag"), QString());
        QCOMPARE(readFile(base + ".vert"), d.source(ShaderStage::Vertex));
        QCOMPARE(readFile(base + ".frag"), d.source(ShaderStage::Fragment));
        QCOMPARE(d.filePath(ShaderStage::Vertex), QFileInfo(base + ".vert").absoluteFilePath());
        QVERIFY(!d.isModified());
        QCOMPARE(d.origin(), (ShaderOrigin{ShaderOrigin::Kind::Files, "pair"}));

        d.setSource(ShaderStage::Vertex, d.source(ShaderStage::Vertex) + "// more\n");
        QVERIFY(d.isModified(ShaderStage::Vertex));
        QCOMPARE(d.save(), QString());
        QVERIFY(!d.isModified());
        QCOMPARE(readFile(base + ".vert"), d.source(ShaderStage::Vertex));

        // A file that cannot be written: a message; the text and its files stay.
        const QString text = d.source(ShaderStage::Vertex);
        QVERIFY(!d.saveAs(m_dir.filePath("missing/dir/x.vert"))
                     .isEmpty()); // inside our folder: a path outside it may exist
        QCOMPARE(d.source(ShaderStage::Vertex), text);
        QCOMPARE(d.filePath(ShaderStage::Vertex), QFileInfo(base + ".vert").absoluteFilePath());
    }

    void aFileChangedOnDiskReloadsUnlessTheStageHasEdits()
    {
        const QString vert = m_dir.filePath("watched.vert"), frag = m_dir.filePath("watched.frag");
        QVERIFY(writeFile(vert, "// v1\n") && writeFile(frag, "// f1\n"));
        ShaderDocument d;
        QCOMPARE(d.openFiles({vert}), QString());
        QSignalSpy disk(&d, &ShaderDocument::diskChanged);
        QSignalSpy compiles(&d, &ShaderDocument::compileRequested);

        QVERIFY(writeFile(frag, "// f2\n"));
        QTRY_COMPARE(d.source(ShaderStage::Fragment), QString("// f2\n"));
        QVERIFY(!d.isModified());
        QCOMPARE(compiles.size(), 1);
        QCOMPARE(disk.last()[1].value<ShaderDocument::DiskChange>(),
                 ShaderDocument::DiskChange::Reloaded);

        d.setSource(ShaderStage::Fragment, "// my edit\n");
        QVERIFY(writeFile(frag, "// f3\n"));
        QTRY_COMPARE(disk.last()[1].value<ShaderDocument::DiskChange>(),
                     ShaderDocument::DiskChange::KeptEdits);
        QCOMPARE(d.source(ShaderStage::Fragment), QString("// my edit\n"));
        QCOMPARE(disk.last()[2].toString(), QFileInfo(frag).absoluteFilePath());

        // Our own save is no change from outside.
        disk.clear();
        QCOMPARE(d.save(), QString());
        QTest::qWait(200);
        QVERIFY(disk.isEmpty());
    }

    void programRoundTripsThroughSetProgram()
    {
        ShaderDocument d;
        d.loadPreset(toon());
        const ProgramText untouched = *d.program();
        QCOMPARE(untouched.name, plainText(toon().name));
        QVERIFY(!untouched.edited);
        d.setSource(ShaderStage::Fragment, untouched.fragment + "// tuned\n");
        const ProgramText edited = *d.program();
        QVERIFY(edited.edited);
        QCOMPARE(edited.name,
                 plainText(toon().name)); // the name is data; "edited" is its own field

        ShaderDocument other;
        other.setProgram(edited, false);
        QVERIFY(other.program() == edited);
        QCOMPARE(other.origin(), (ShaderOrigin{ShaderOrigin::Kind::Scene, toon().name, true}));
        QVERIFY(!other.isModified()); // as the scene has it
        other.setProgram(untouched, false);
        QVERIFY(other.program() == untouched);

        // No program: the shading mode's built-in, following the shading.
        other.setProgram(std::nullopt, true);
        QVERIFY(other.showsBuiltIn());
        QCOMPARE(other.source(ShaderStage::Vertex), builtInPreset(true).vertexSource());
        QVERIFY(!other.program());
    }

    void anOldSceneFilesEditedNameReadsBackAsEdited()
    {
        // Scene files before the "edited" field: the English suffix on the name.
        const QJsonObject old{
            {"version", 2},
            {"program", QJsonObject{{"name", "Toon (edited)"},
                                    {"vertex", toon().vertexSource()},
                                    {"fragment", toon().fragmentSource() + "// tuned\n"}}}};
        const SceneFileRead read =
            parseSceneFile(QJsonDocument(old).toJson(), QDir(m_dir.path()), "old.json");
        QVERIFY(read.file && read.file->program);
        ShaderDocument d;
        d.setProgram(read.file->program, false);
        QCOMPARE(d.origin(), (ShaderOrigin{ShaderOrigin::Kind::Scene, "Toon", true}));
        // Saved again, the name is the name and edited is a field.
        SceneFile file;
        file.program = d.program();
        const QJsonObject saved =
            QJsonDocument::fromJson(sceneFileBytes(file, QDir())).object()["program"].toObject();
        QCOMPARE(saved["name"].toString(), QString("Toon"));
        QCOMPARE(saved["edited"].toBool(), true);
    }

    void stateRoundTripsWithOriginAndUnsavedEdits()
    {
        const QString ini = m_dir.filePath("state.ini");
        const QString vert = m_dir.filePath("state.vert"), frag = m_dir.filePath("state.frag");
        QVERIFY(writeFile(vert, "// v\n") && writeFile(frag, "// f\n"));
        {
            QSettings settings(ini, QSettings::IniFormat);
            ShaderDocument d;
            QCOMPARE(d.openFiles({vert, frag}), QString());
            d.setSource(ShaderStage::Vertex, "// v, unsaved\n");
            d.saveState(settings);
        }
        QSettings settings(ini, QSettings::IniFormat);
        ShaderDocument d;
        QSignalSpy compiles(&d, &ShaderDocument::compileRequested);
        QVERIFY(d.restoreState(settings));
        QCOMPARE(compiles.size(), 1);
        QCOMPARE(d.source(ShaderStage::Vertex), QString("// v, unsaved\n"));
        QCOMPARE(d.source(ShaderStage::Fragment), QString("// f\n"));
        QCOMPARE(d.filePath(ShaderStage::Vertex), QFileInfo(vert).absoluteFilePath());
        // What saveState wrote is what restoreState reads: the origin comes back.
        QCOMPARE(d.origin(), (ShaderOrigin{ShaderOrigin::Kind::Files, "state", true}));
        QVERIFY(d.isModified(ShaderStage::Vertex)); // the unsaved edit is still unsaved
        QVERIFY(!d.isModified(ShaderStage::Fragment));
        QCOMPARE(readFile(vert), QString("// v\n"));
        QCOMPARE(d.save(), QString());
        QVERIFY(!d.isModified());
        QCOMPARE(readFile(vert), QString("// v, unsaved\n"));

        // A scene's program, edited, comes back under its own name.
        ShaderDocument scene;
        scene.setProgram(ProgramText{plainText("Lesson"), "// a\n", "// b\n", true}, false);
        scene.saveState(settings);
        ShaderDocument back;
        QVERIFY(back.restoreState(settings));
        QCOMPARE(back.origin(), (ShaderOrigin{ShaderOrigin::Kind::Scene, "Lesson", true}));
        QVERIFY(back.program() == scene.program());

        // An untouched built-in comes back following the shading.
        ShaderDocument builtIn;
        builtIn.loadPreset(builtInPreset(true));
        builtIn.saveState(settings);
        ShaderDocument again;
        QVERIFY(again.restoreState(settings));
        QVERIFY(again.showsBuiltIn());
        again.followShading(false);
        QCOMPARE(again.source(ShaderStage::Vertex), builtInPreset(false).vertexSource());

        QSettings empty(m_dir.filePath("empty.ini"), QSettings::IniFormat);
        QVERIFY(!ShaderDocument().restoreState(empty));
    }
};

QTEST_GUILESS_MAIN(TestShaderDocument)
#include "test_shader_document.moc"
