// Bounded fuzzing of what a class types and hands in: the command-line parser and the scene
// file reader get thousands of random and mutated inputs from a fixed seed (the same cases
// every run; LB_FUZZ_SEED picks others, LB_FUZZ_CASES more of them). Nothing may crash or trip
// a sanitizer (scripts/test --sanitize runs this too), every refusal is one bounded line, and
// what is accepted is a scene of finite numbers that survives a save and a reread unchanged.
#include "command_line.h"
#include "scene_file.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <QTest>

#include <cmath>
#include <random>

using namespace lb;

namespace {

// Refusals echo what was typed; past this a message is no longer one readable line.
constexpr int kMaxMessage = 2000;

quint32 seed()
{
    bool ok = false;
    const quint32 s = qEnvironmentVariableIntValue("LB_FUZZ_SEED", &ok);
    return ok ? s : 20261124u;
}

int cases(int normal)
{
    bool ok = false;
    const int n = qEnvironmentVariableIntValue("LB_FUZZ_CASES", &ok);
    return ok && n > 0 ? n : normal;
}

// The first number in `json` (recursively) that is not finite, as "path"; empty when none.
QString nonFinite(const QJsonValue &v, const QString &path)
{
    if (v.isDouble())
        return std::isfinite(v.toDouble()) ? QString() : path;
    if (v.isArray()) {
        const QJsonArray a = v.toArray();
        for (int i = 0; i < a.size(); ++i)
            if (QString p = nonFinite(a[i], path + '[' + QString::number(i) + ']'); !p.isEmpty())
                return p;
    }
    if (v.isObject()) {
        const QJsonObject o = v.toObject();
        for (auto it = o.begin(); it != o.end(); ++it)
            if (QString p = nonFinite(it.value(), path + '.' + it.key()); !p.isEmpty())
                return p;
    }
    return {};
}

class Random
{
public:
    explicit Random(quint32 s) : m_engine(s) {}
    int below(int n) { return n > 1 ? std::uniform_int_distribution<int>(0, n - 1)(m_engine) : 0; }
    bool chance(int percent) { return below(100) < percent; }
    template <typename T> const T &pick(const QList<T> &list)
    {
        return list[below(int(list.size()))];
    }
    double number()
    {
        switch (below(6)) {
        case 0:
            return below(3) - 1;
        case 1:
            return std::uniform_real_distribution<double>(-2, 2)(m_engine);
        case 2:
            return std::pow(10.0, below(80) - 20) * (chance(50) ? 1 : -1);
        case 3:
            return 1e308 * (chance(50) ? 10 : -10); // infinite
        case 4:
            return std::nan("");
        default:
            return below(100000);
        }
    }
    QString text()
    {
        static const QStringList atoms = {"",
                                          "0",
                                          "1",
                                          "-1",
                                          "0.5",
                                          "1e9",
                                          "1e39",
                                          "-1e39",
                                          "nan",
                                          "NaN",
                                          "inf",
                                          "-inf",
                                          "1,2,3",
                                          "1,2,3,4",
                                          "1,2",
                                          "1,,2",
                                          ",",
                                          "0x10",
                                          "1e",
                                          "--",
                                          "-",
                                          "abc",
                                          "1 2",
                                          "camera",
                                          "world",
                                          "object",
                                          "phong",
                                          "blinn",
                                          "gouraud",
                                          "sphere",
                                          "torus",
                                          "off",
                                          "on",
                                          "800x600",
                                          "0x0",
                                          "99999x99999",
                                          "-5x3",
                                          "10,10",
                                          "1.0.0",
                                          "\u00e9\u00e8",
                                          "\u4e2d",
                                          QString(300, 'x'),
                                          "/nonexistent/file.json",
                                          "../",
                                          "'",
                                          "\"",
                                          "\\"};
        QString t = pick(atoms);
        if (chance(30))
            t += QString::number(number(), 'g', 17);
        if (chance(10))
            t = QString(below(5000) + 1, QChar(u'0' + below(10)));
        if (chance(15))
            for (int i = below(4); i >= 0; --i)
                t += QChar(char16_t(below(0x3000) + 1));
        return t;
    }
    // What an option of some kind might well take: a word, a count, a size or a tuple.
    QString plausible()
    {
        static const QStringList words = {
            "on",     "off",   "camera", "world",       "object",       "phong", "blinn", "gouraud",
            "sphere", "torus", "cube",   "perspective", "orthographic", "file",  "flat"};
        switch (below(4)) {
        case 0:
            return pick(words);
        case 1:
            return QString::number(below(300));
        case 2:
            return QString("%1x%2").arg(below(2000)).arg(below(2000));
        default: {
            QStringList parts;
            for (int i = below(4); i >= 0; --i)
                parts << QString::number(std::uniform_real_distribution<double>(-1, 1)(m_engine));
            return parts.join(',');
        }
        }
    }
    QByteArray bytes(int n)
    {
        QByteArray b(n, '\0');
        for (char &c : b)
            c = char(below(256));
        return b;
    }
    QJsonValue json(int depth)
    {
        switch (below(depth > 3 ? 5 : 7)) {
        case 0:
            return QJsonValue();
        case 1:
            return chance(50);
        case 2:
            return number();
        case 3:
            return text();
        case 4:
            return below(1000);
        case 5: {
            QJsonArray a;
            for (int i = below(6); i > 0; --i)
                a.append(json(depth + 1));
            return a;
        }
        default: {
            QJsonObject o;
            for (int i = below(5); i > 0; --i)
                o.insert(pick(m_keys), json(depth + 1));
            return o;
        }
        }
    }
    // Replaces one value somewhere in `v` (or a key's value, or adds a key) by a random one.
    QJsonValue mutate(const QJsonValue &v, int depth = 0)
    {
        if (depth > 0 && chance(25))
            return json(depth);
        if (v.isObject()) {
            QJsonObject o = v.toObject();
            if (o.isEmpty() || chance(15)) {
                o.insert(pick(m_keys), json(depth + 1));
            } else if (chance(10)) {
                o.remove(o.keys()[below(int(o.size()))]);
            } else {
                const QString key = o.keys()[below(int(o.size()))];
                o.insert(key, mutate(o.value(key), depth + 1));
            }
            return o;
        }
        if (v.isArray()) {
            QJsonArray a = v.toArray();
            if (a.isEmpty() || chance(15)) {
                a.append(json(depth + 1));
            } else if (chance(10)) {
                a.removeAt(below(int(a.size())));
            } else if (chance(5)) {
                for (int i = below(200); i > 0; --i) // many lights, many values
                    a.append(a[0]);
            } else {
                const int i = below(int(a.size()));
                a.replace(i, mutate(a[i], depth + 1));
            }
            return a;
        }
        return json(depth);
    }
    void learnKeys(const QJsonValue &v)
    {
        if (v.isObject()) {
            const QJsonObject o = v.toObject();
            for (auto it = o.begin(); it != o.end(); ++it) {
                if (!m_keys.contains(it.key()))
                    m_keys << it.key();
                learnKeys(it.value());
            }
        } else if (v.isArray()) {
            for (const QJsonValue &e : v.toArray())
                learnKeys(e);
        }
    }

private:
    std::mt19937 m_engine;
    QStringList m_keys{"format", "version", "x", ""};
};

QList<QByteArray> sceneSeeds()
{
    QList<QByteArray> seeds;
    const QDir examples(LB_EXAMPLES_DIR);
    for (const QString &name : examples.entryList({"*.json"}, QDir::Files)) {
        QFile f(examples.filePath(name));
        if (f.open(QIODevice::ReadOnly))
            seeds << f.readAll();
    }
    SceneFile file;
    file.program = ProgramText{plainText("mine"), "void main() {}", "void main() {}", true};
    seeds << sceneFileBytes(file, QDir::temp());
    return seeds;
}

} // namespace

class TestFuzzInputs : public QObject
{
    Q_OBJECT
private slots:
    void commandLines()
    {
        const CommandLineResult help = parseCommandLine({"lightbench", "--help"});
        QStringList options;
        for (const QRegularExpressionMatch &m :
             QRegularExpression("--[a-z0-9-]+").globalMatch(help.message))
            if (!options.contains(m.captured()))
                options << m.captured();
        QVERIFY2(options.size() > 20, qPrintable(help.message));
        // Options that open files, or make the program wait or write: their values are kept
        // to paths that do not exist, so the fuzzing reads and writes nothing.
        const QStringList fileOptions = {"--scene", "--vertex", "--fragment", "--mesh"};

        Random random(seed());
        const int n = cases(3000);
        int accepted = 0;
        for (int i = 0; i < n; ++i) {
            QStringList args{"lightbench"};
            for (int k = random.below(4); k >= 0; --k) {
                if (random.chance(90)) {
                    const QString option = random.pick(options);
                    args << option;
                    if (fileOptions.contains(option))
                        args << "/nonexistent/" + random.text();
                    else if (random.chance(60))
                        args << random.plausible();
                    else if (random.chance(90))
                        args << random.text();
                } else {
                    args << random.text();
                }
            }
            if (args.contains("--help") || args.contains("--version"))
                continue;
            const CommandLineResult r = parseCommandLine(args);
            const QString what = args.join(' ').left(300);
            QVERIFY2(r.exitCode == 0 || r.exitCode == 2, qPrintable(what));
            if (!r.commandLine) {
                QCOMPARE(r.exitCode, 2);
                QVERIFY2(!r.message.isEmpty() && r.message.size() <= kMaxMessage,
                         qPrintable(what + " -> " + r.message.left(300)));
                QVERIFY2(!r.message.trimmed().contains('\n'), qPrintable(r.message.left(300)));
                continue;
            }
            ++accepted;
            Scene scene;
            r.commandLine->applyTo(scene);
            const QString bad = nonFinite(scene.toJson(), "scene");
            QVERIFY2(bad.isEmpty(), qPrintable(what + " made " + bad + " not finite"));
            QVERIFY(r.commandLine->size.width() > 0 && r.commandLine->size.height() > 0);
        }
        qInfo("%d command lines, %d accepted (seed %u)", n, accepted, seed());
        QVERIFY(accepted > n / 40); // the generator gets past the refusals (~3% of lines)
    }

    void sceneFiles()
    {
        const QList<QByteArray> seeds = sceneSeeds();
        QVERIFY(seeds.size() >= 2);
        Random random(seed() + 1);
        for (const QByteArray &s : seeds)
            random.learnKeys(QJsonDocument::fromJson(s).object());
        const QDir dir = QDir::temp();
        const int n = cases(3000);
        int opened = 0;
        for (int i = 0; i < n; ++i) {
            const QByteArray seedBytes = random.pick(seeds);
            QByteArray bytes;
            switch (random.below(5)) {
            case 0: { // bytes flipped, cut or spliced
                bytes = seedBytes;
                for (int k = random.below(8); k >= 0; --k)
                    bytes[random.below(int(bytes.size()))] = char(random.below(256));
                if (random.chance(30))
                    bytes.truncate(random.below(int(bytes.size())));
                if (random.chance(20))
                    bytes.insert(random.below(int(bytes.size())), random.bytes(random.below(40)));
                break;
            }
            case 1: // random bytes
                bytes = random.bytes(random.below(400));
                break;
            case 2: // deep nesting
                bytes = QByteArray(random.below(3000), '[') + "{}";
                break;
            default: { // values replaced, keys added and removed, arrays grown
                QJsonValue doc = QJsonDocument::fromJson(seedBytes).object();
                for (int k = random.below(4); k >= 0; --k)
                    doc = random.mutate(doc);
                bytes = QJsonDocument(doc.toObject()).toJson(QJsonDocument::Compact);
                break;
            }
            }
            const SceneFileRead read = parseSceneFile(bytes, dir, "fuzz.json");
            const QString what = QString::fromLatin1(bytes.left(200).toPercentEncoding());
            if (!read.file) {
                QVERIFY2(!read.error.isEmpty() && read.error.size() <= kMaxMessage,
                         qPrintable(what + " -> " + read.error.left(300)));
                continue;
            }
            ++opened;
            const QString bad = nonFinite(read.file->scene.toJson(), "scene");
            QVERIFY2(bad.isEmpty(), qPrintable(what + " made " + bad + " not finite"));
            QVERIFY2(read.ignored.join(", ").size() <= 100000, qPrintable(what));
            // What was accepted is a scene: written and read again, it is the same one.
            const SceneFileRead again =
                parseSceneFile(sceneFileBytes(*read.file, dir), dir, "again.json");
            QVERIFY2(again.file, qPrintable(what + " -> " + again.error));
            QVERIFY2(again.file->scene == read.file->scene,
                     qPrintable(what + ": the scene changed on a save and a reread"));
            QVERIFY2(again.file->program == read.file->program, qPrintable(what));
            // (An exercise section that cannot be graded against is kept as it was, on purpose.)
            QStringList againIgnored = again.ignored;
            againIgnored.removeIf(
                [](const QString &i) { return i.endsWith("(the section is kept as it is)"); });
            QVERIFY2(againIgnored.isEmpty(), qPrintable(what + ": " + againIgnored.join(", ")));
        }
        qInfo("%d scene files, %d opened (seed %u)", n, opened, seed());
        QVERIFY(opened > n / 10);
    }
};

QTEST_GUILESS_MAIN(TestFuzzInputs)
#include "test_fuzz_inputs.moc"
