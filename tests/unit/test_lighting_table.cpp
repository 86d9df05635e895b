// Issue 50, part 1: the lighting model declared once. Every row of the parameters' table
// (lighting_parameters.h) is read and written by the scene's JSON, compared by the scene's
// equality, set by its command-line option and refused as the row says; every row of the
// specular models' table (lighting_models.h) is a word of the files, a uniform value the
// built-in shaders' text knows, and the cosine its formula gives. A new row that one of
// these places does not handle fails here, not silently on screen.
#include "command_line.h"
#include "lighting_models.h"
#include "lighting_parameters.h"
#include "presets.h"
#include "scene.h"

#include <QFile>
#include <QJsonArray>
#include <QRegularExpression>
#include <QTest>

#include <glm/geometric.hpp>

using namespace lb;

namespace {

// The owner's numbers of row `p` in light 1 or the selected object.
float *numbersIn(Scene &s, const LightingParameter &p)
{
    return p.owner == ParameterOwner::Light ? p.numbers(s.lights[0])
                                            : p.numbers(s.selectedObject().material);
}

// A value inside the row's range that no default has: a quarter of the way up.
std::vector<float> changed(const LightingParameter &p, const float *now)
{
    std::vector<float> v(now, now + p.count);
    for (int i = 0; i < p.count; ++i)
        v[std::size_t(i)] = p.lo + 0.25f * (p.hi - p.lo) + 0.125f * float(i);
    if (QByteArray(p.key) == "position")
        v[3] = 1.0f; // a point light: w is 0 or 1
    if (QByteArray(p.key) == "spot.cutoff")
        v[0] = 45.0f;
    return v;
}

QString joined(const std::vector<float> &v)
{
    QStringList parts;
    for (float x : v)
        parts << QString::number(double(x), 'g', 9);
    return parts.join(',');
}

// Light 1's (or the first object's material's) object in `json`, with `set` applied to the
// object that holds the row's key.
QJsonObject withField(QJsonObject json, const LightingParameter &p, const QJsonValue &value)
{
    const bool light = p.owner == ParameterOwner::Light;
    QJsonArray list = json[light ? "lights" : "objects"].toArray();
    QJsonObject owner = list[0].toObject();
    if (!light)
        owner = owner["material"].toObject();
    const QString key = QString::fromLatin1(p.key);
    if (key.contains('.')) {
        QJsonObject inner = owner[key.section('.', 0, 0)].toObject();
        inner[key.section('.', 1)] = value;
        owner[key.section('.', 0, 0)] = inner;
    } else {
        owner[key] = value;
    }
    if (!light) {
        QJsonObject object = list[0].toObject();
        object["material"] = owner;
        owner = object;
    }
    list[0] = owner;
    json[light ? "lights" : "objects"] = list;
    return json;
}

QJsonValue jsonOf(const std::vector<float> &v)
{
    if (v.size() == 1)
        return double(v[0]);
    QJsonArray a;
    for (float x : v)
        a.append(double(x));
    return a;
}

QString jsonPath(const LightingParameter &p)
{
    return (p.owner == ParameterOwner::Light ? "lights[0]." : "objects[0].material.") +
           QString::fromLatin1(p.key);
}

} // namespace

class TestLightingTable : public QObject
{
    Q_OBJECT

private slots:
    void everyParameterIsReadWrittenComparedAndSet_data()
    {
        QTest::addColumn<int>("row");
        for (int i = 0; i < int(lightingParameters().size()); ++i)
            QTest::newRow(lightingParameters()[std::size_t(i)].key) << i;
    }

    void everyParameterIsReadWrittenComparedAndSet()
    {
        QFETCH(int, row);
        const LightingParameter &p = lightingParameters()[std::size_t(row)];
        QVERIFY(p.count >= 1 && p.count <= 4);
        QVERIFY(p.lo < p.hi);
        QVERIFY((p.owner == ParameterOwner::Light) == (p.ofLight != nullptr));
        QVERIFY((p.owner == ParameterOwner::Material) == (p.ofMaterial != nullptr));
        QVERIFY(p.tooltip && *p.tooltip && p.description && *p.description);
        QVERIFY(!p.semantics.empty());

        // Equality and the parts that differ see a change of any of its numbers.
        const Scene defaults;
        Scene edited;
        const std::vector<float> v = changed(p, numbersIn(edited, p));
        std::copy(v.begin(), v.end(), numbersIn(edited, p));
        QVERIFY(edited != defaults);
        const SceneParts part =
            p.owner == ParameterOwner::Light ? ScenePart::Lights : ScenePart::Material;
        QCOMPARE(differingParts(edited, defaults), SceneParts(part));

        // Written and read back whole, with nothing ignored.
        QStringList ignored;
        const Scene back = Scene::fromJson(edited.toJson(), &ignored);
        QVERIFY2(ignored.isEmpty(), qPrintable(ignored.join('\n')));
        QVERIFY(back == edited);

        // Out of its range: clamped to it, and named.
        std::vector<float> beyond = v;
        beyond[0] = p.hi + 1.0f;
        ignored.clear();
        Scene clamped = Scene::fromJson(withField(edited.toJson(), p, jsonOf(beyond)), &ignored);
        QCOMPARE(numbersIn(clamped, p)[0], p.hi);
        QVERIFY2(ignored.join('\n').contains(jsonPath(p) + " (out of range, clamped)"),
                 qPrintable(ignored.join('\n')));

        // The command line sets light 1's or the selected object's numbers, and refuses what
        // is outside the range with the option's name.
        if (p.option) {
            const QString option = "--" + QString::fromLatin1(p.option);
            const CommandLineResult set =
                parseCommandLine({"lightbench", option, joined(v), "--render", "x.png"});
            QVERIFY2(set.commandLine, qPrintable(set.message));
            Scene s;
            set.commandLine->applyTo(s);
            QVERIFY(std::equal(v.begin(), v.end(), numbersIn(s, p)));
            const CommandLineResult refused =
                parseCommandLine({"lightbench", option, joined(beyond), "--render", "x.png"});
            QVERIFY(!refused.commandLine);
            QCOMPARE(refused.exitCode, 2);
            QVERIFY2(refused.message.contains(option + ": ") &&
                         refused.message.contains(
                             QString("outside %1 to %2").arg(double(p.lo)).arg(double(p.hi))),
                     qPrintable(refused.message));
        }
    }

    // Each refusal is the same in the file, on the command line and in the panels (which ask
    // the row): numbers in range that the model cannot use.
    void refusalsAreOneRule_data()
    {
        QTest::addColumn<QString>("key");
        QTest::addColumn<QString>("numbers");
        QTest::addColumn<QString>("option");
        QTest::addColumn<QString>("why");
        QTest::newRow("w of 0.5") << "position"
                                  << "1,2,3,0.5"
                                  << "light"
                                  << "w must be 0 (directional) or 1 (point)";
        QTest::newRow("direction 0") << "position"
                                     << "0,0,0,0"
                                     << "light"
                                     << "a directional light (w = 0) with the direction 0, 0, 0";
        QTest::newRow("attenuation 0") << "attenuation"
                                       << "0,0,0"
                                       << "attenuation"
                                       << "kc, kl and kq all 0 (the light would be infinite)";
        QTest::newRow("spot axis 0") << "spot.direction"
                                     << "0,0,0"
                                     << "spot"
                                     << "a direction of length 0";
    }

    void refusalsAreOneRule()
    {
        QFETCH(QString, key);
        QFETCH(QString, numbers);
        QFETCH(QString, option);
        QFETCH(QString, why);
        const LightingParameter *p =
            lightingParameter(ParameterOwner::Light, key.toLatin1().constData());
        QVERIFY(p);
        std::vector<float> v;
        for (const QString &n : numbers.split(','))
            v.push_back(n.toFloat());
        QCOMPARE(p->refusalInEnglish(v.data()), why);

        const Scene defaults;
        QStringList ignored;
        const Scene read = Scene::fromJson(withField(defaults.toJson(), *p, jsonOf(v)), &ignored);
        QVERIFY(read == defaults); // the numbers keep what they were
        QVERIFY2(ignored.contains("lights[0]." + key + " (" + why + ")"),
                 qPrintable(ignored.join('\n')));

        const QString value = option == "spot" ? numbers + ",30,2" : numbers;
        const CommandLineResult r =
            parseCommandLine({"lightbench", "--" + option, value, "--render", "x.png"});
        QVERIFY(!r.commandLine);
        QVERIFY2(r.message.contains("--" + option + ": " + why), qPrintable(r.message));
    }

    // The specular models: words, uniform values the shaders' text knows, their cosines.
    void everySpecularModelIsKnownEverywhere()
    {
        QFile file(LB_SHADERS_DIR "/lighting.glsl");
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QString glsl = QString::fromUtf8(file.readAll());
        const QString phong = builtInPreset(false).fragmentSource();
        const QString gouraud = builtInPreset(true).vertexSource();
        // Both built-in programs hold the shared model whole, in place of the include line.
        QVERIFY(phong.contains(glsl) && gouraud.contains(glsl));
        QVERIFY(!phong.contains("\n// @include") && !gouraud.contains("\n// @include"));

        QSet<int> uniforms;
        QStringList words;
        for (const SpecularModelRow &row : specularModels()) {
            const QString word = QString::fromLatin1(row.word);
            words << word;
            QCOMPARE(parseSpecularModel(word), std::optional(row.model));
            QCOMPARE(toName(row.model), word);
            QVERIFY2(!uniforms.contains(row.uniform), row.word);
            uniforms << row.uniform;
            // lighting.glsl numbers the model as the table does and has its branch.
            const QString name = "SPECULAR_" + word.toUpper();
            const QRegularExpression define("#define " + name + " (\\d+)");
            const QRegularExpressionMatch m = define.match(glsl);
            QVERIFY2(m.hasMatch(), qPrintable(name));
            QCOMPARE(m.captured(1).toInt(), row.uniform);
            QVERIFY2(glsl.contains("uSpecularModel == " + name), qPrintable(name));
            QCOMPARE(specularModel(row.model).model, row.model);
            QVERIFY(!row.curves.empty());
            for (const SpecularPlotCurve &c : row.curves)
                QCOMPARE(specularModelOfCurve(QString::fromLatin1(c.key)), &row);
        }
        QCOMPARE(specularModelNames(), words);
        // The shaders name no model the table lacks.
        const QRegularExpression anyDefine("#define SPECULAR_(\\w+) ");
        for (auto it = anyDefine.globalMatch(glsl); it.hasNext();)
            QVERIFY2(words.contains(it.next().captured(1).toLower()), "a model the table lacks");
        // Ctrl+B's toggle visits every model once.
        SpecularModel m = specularModels().front().model;
        QSet<int> visited;
        for (std::size_t i = 0; i < specularModels().size(); ++i) {
            visited << int(m);
            m = nextSpecularModel(m);
        }
        QCOMPARE(m, specularModels().front().model);
        QCOMPARE(int(visited.size()), int(specularModels().size()));

        // The cosines as the slides write them, from vectors not at any special angle.
        const glm::vec3 N = glm::normalize(glm::vec3(0.1f, 0.9f, 0.3f));
        const glm::vec3 L = glm::normalize(glm::vec3(0.6f, 0.7f, 0.2f));
        const glm::vec3 V = glm::normalize(glm::vec3(-0.3f, 0.5f, 0.8f));
        LightingInputs in;
        for (const SpecularModelRow &row : specularModels()) {
            in.specular = row.model;
            const LightingTerms t = lightingTerms(L, N, V, 0.0f, in);
            const float expected = row.model == SpecularModel::Phong
                                       ? glm::dot(2.0f * glm::dot(N, L) * N - L, V)
                                       : glm::dot(N, glm::normalize(L + V));
            QVERIFY2(std::abs(t.specularAngle - expected) < 1e-6f, row.word);
            QVERIFY(std::abs(t.specularFactor - std::pow(expected, in.material.shininess)) < 1e-6f);
            QCOMPARE(t.*row.vectorOf, row.model == SpecularModel::Phong ? t.R : t.H);
        }
    }
};

QTEST_GUILESS_MAIN(TestLightingTable)
#include "test_lighting_table.moc"
