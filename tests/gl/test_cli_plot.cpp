// --plot from the command line, as a teacher makes a slide: the CSV's columns against the
// formulas computed here (cos(θ)^n, cos(θ/2)^n and ^4n, max(cos α, 0), 1 / (kc + kl·d +
// kq·d²), a spotlight's cos(β)^e inside its cone), the lobe at a probed pixel against the
// probe's own JSON, the PNG and the SVG read back. Bad input: an unknown kind, no output, an
// output in a folder that is not there or on a FIFO, a frame's option beside it, a plot with
// nothing to draw; each gets its message and writes nothing.
#include "program_run.h"

#include <QFile>
#include <QFileInfo>
#include <QImage>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QSet>
#include <QTemporaryDir>
#include <QTest>
#include <QXmlStreamReader>

#include <cmath>
#include <functional>
#include <optional>

#include <sys/stat.h>

namespace {

constexpr int kLimitMs = 60000;

double radians(double degrees)
{
    return degrees * M_PI / 180.0;
}

struct Csv
{
    QList<QByteArray> header;
    std::vector<std::vector<double>> rows;
};

Csv readCsv(const QString &path)
{
    Csv csv;
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return csv;
    const QList<QByteArray> lines = f.readAll().trimmed().split('\n');
    csv.header = lines.value(0).split(',');
    for (int i = 1; i < lines.size(); ++i) {
        std::vector<double> row;
        for (const QByteArray &cell : lines[i].split(','))
            row.push_back(cell.toDouble());
        csv.rows.push_back(row);
    }
    return csv;
}

// Column `column` of every row against `expected(x)` (none: not compared); the first
// difference, or empty.
QString compareColumn(const Csv &csv, int column,
                      const std::function<std::optional<double>(double)> &expected,
                      double tolerance)
{
    for (const std::vector<double> &row : csv.rows) {
        if (int(row.size()) != csv.header.size())
            return "a row of another length";
        const std::optional<double> want = expected(row[0]);
        if (want && std::abs(row[std::size_t(column)] - *want) > tolerance)
            return QString("%1 at %2: %3, expected %4")
                .arg(QString(csv.header[column]))
                .arg(row[0])
                .arg(row[std::size_t(column)])
                .arg(*want);
    }
    return {};
}

} // namespace

class TestCliPlot : public QObject
{
    Q_OBJECT
private:
    QTemporaryDir m_dir;

    ProgramRun plot(const QStringList &args) { return runProgram(LIGHTBENCH_EXE, args, kLimitMs); }
    QString path(const QString &name) const { return m_dir.filePath(name); }

private slots:
    void curvesAreTheFormulas()
    {
        ProgramRun r =
            plot({"--plot", "specular", "--shininess", "40", "--plot-data", path("specular.csv")});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        Csv csv = readCsv(path("specular.csv"));
        QCOMPARE(csv.header, QList<QByteArray>({"angle_degrees", "phong", "blinn", "blinn_4n"}));
        QCOMPARE(csv.rows.size(), std::size_t(361));
        QCOMPARE(csv.rows.back()[0], 180.0);
        const auto power = [](double n, double scale) {
            return [n, scale](double x) -> std::optional<double> {
                return std::pow(std::max(std::cos(radians(x * scale)), 0.0), n);
            };
        };
        for (auto [column, n, scale] :
             {std::tuple{1, 40.0, 1.0}, std::tuple{2, 40.0, 0.5}, std::tuple{3, 160.0, 0.5}}) {
            const QString diff = compareColumn(csv, column, power(n, scale), 2e-4);
            QVERIFY2(diff.isEmpty(), qPrintable(diff));
        }

        r = plot({"--plot", "diffuse", "--plot-data", path("diffuse.csv")});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        csv = readCsv(path("diffuse.csv"));
        QCOMPARE(csv.header, QList<QByteArray>({"angle_degrees", "diffuse"}));
        QString diff = compareColumn(csv, 1, power(1.0, 1.0), 1e-5);
        QVERIFY2(diff.isEmpty(), qPrintable(diff));

        r = plot({"--plot", "attenuation", "--attenuation", "0.5,0.2,0.1", "--plot-data",
                  path("attenuation.csv")});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        csv = readCsv(path("attenuation.csv"));
        QCOMPARE(csv.header, QList<QByteArray>({"distance", "light1"}));
        QVERIFY(csv.rows.back()[0] >= 5.0);
        diff = compareColumn(
            csv, 1, [](double d) { return 1.0 / (0.5 + 0.2 * d + 0.1 * d * d); }, 1e-5);
        QVERIFY2(diff.isEmpty(), qPrintable(diff));

        r = plot({"--plot", "spot", "--spot", "0,-1.8,-1.3,30,5", "--plot-data", path("spot.csv")});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        csv = readCsv(path("spot.csv"));
        diff = compareColumn(
            csv, 1,
            [](double b) -> std::optional<double> {
                if (std::abs(b - 30.0) < 0.01)
                    return std::nullopt; // the edge itself: float against double
                return b > 30.0 ? 0.0 : std::pow(std::cos(radians(b)), 5.0);
            },
            1e-5);
        QVERIFY2(diff.isEmpty(), qPrintable(diff));
    }

    // The lobe at a probed pixel: ambient and diffuse the same from every direction, and the
    // probe's own (its JSON on standard output); the specular term's peak along R.
    void lobeAtAProbedPixelIsTheProbes()
    {
        const ProgramRun r = plot({"--plot", "lobe", "--probe", "420,260", "--specular", "phong",
                                   "--plot-data", path("lobe.csv"), "--render", path("lobe.png")});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        const QJsonObject probe = QJsonDocument::fromJson(r.out).object();
        QVERIFY2(probe["hit"].toBool(), r.out.constData());
        const QJsonObject light = probe["lights"].toArray()[0].toObject();
        const auto mean = [&](const char *term) {
            const QJsonArray c = light[term].toArray();
            return (c[0].toDouble() + c[1].toDouble() + c[2].toDouble()) / 3.0;
        };
        const Csv csv = readCsv(path("lobe.csv"));
        QCOMPARE(csv.header,
                 QList<QByteArray>({"angle_degrees", "ambient", "diffuse", "specular"}));
        QCOMPARE(csv.rows.front()[0], -90.0);
        QCOMPARE(csv.rows.back()[0], 90.0);
        QString diff = compareColumn(
            csv, 1, [&](double) { return mean("ambient"); }, 1e-5);
        QVERIFY2(diff.isEmpty(), qPrintable(diff));
        diff = compareColumn(
            csv, 2, [&](double) { return mean("diffuse"); }, 1e-5);
        QVERIFY2(diff.isEmpty(), qPrintable(diff));
        // The peak where V is R: at minus the angle of incidence (L's side is positive).
        const double incidence = std::acos(light["NdotL"].toDouble()) * 180.0 / M_PI;
        std::size_t peak = 0;
        for (std::size_t i = 0; i < csv.rows.size(); ++i)
            if (csv.rows[i][3] > csv.rows[peak][3])
                peak = i;
        QVERIFY2(std::abs(csv.rows[peak][0] + incidence) <= 1.0,
                 qPrintable(QString("peak at %1, R at %2").arg(csv.rows[peak][0]).arg(-incidence)));
        const QImage image(path("lobe.png"));
        QCOMPARE(image.size(), QSize(800, 600));
    }

    void picturesAreReadBack()
    {
        ProgramRun r =
            plot({"--plot", "specular", "--render", path("specular.png"), "--size", "640x480"});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        const QImage png(path("specular.png"));
        QCOMPARE(png.size(), QSize(640, 480));
        QSet<QRgb> colours;
        for (int y = 0; y < png.height(); y += 3)
            for (int x = 0; x < png.width(); x += 3)
                colours.insert(png.pixel(x, y));
        QVERIFY2(colours.size() > 50, "a picture of one or two colours"); // curves, text, grid

        r = plot({"--plot", "lobe", "--render", path("lobe.svg")});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        QFile svg(path("lobe.svg"));
        QVERIFY(svg.open(QIODevice::ReadOnly));
        QXmlStreamReader xml(&svg);
        int lines = 0;
        bool root = false;
        while (!xml.atEnd())
            if (xml.readNext() == QXmlStreamReader::StartElement) {
                root = root || xml.name() == u"svg";
                lines += xml.name() == u"polyline" || xml.name() == u"path";
            }
        QVERIFY2(!xml.hasError(), qPrintable(xml.errorString()));
        QVERIFY(root && lines > 5);

        // --language: a slide for a German class (the SVG's text is searchable).
        r = plot({"--plot", "diffuse", "--language", "de", "--render", path("de.svg")});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        QFile de(path("de.svg"));
        QVERIFY(de.open(QIODevice::ReadOnly));
        const QByteArray words = de.readAll();
        QVERIFY(words.contains("Diffuser Faktor"));
        QVERIFY(!words.contains("Diffuse factor"));
    }

    // Without --probe a plot needs no OpenGL: it is drawn where no X server is.
    void withoutADisplay()
    {
        QProcess run;
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.remove("DISPLAY");
        env.remove("WAYLAND_DISPLAY");
        env.remove("QT_QPA_PLATFORM");
        run.setProcessEnvironment(env);
        run.start(LIGHTBENCH_EXE, {"--plot", "attenuation", "--attenuation", "1,0,1", "--render",
                                   path("nodisplay.png"), "--plot-data", path("nodisplay.csv")});
        QVERIFY(run.waitForFinished(kLimitMs));
        QVERIFY2(run.exitCode() == 0, run.readAllStandardError().constData());
        QCOMPARE(QImage(path("nodisplay.png")).size(), QSize(800, 600));
        QCOMPARE(readCsv(path("nodisplay.csv")).rows.size(), std::size_t(361));
        // --probe draws a frame: that still needs the X server, and says so.
        run.start(LIGHTBENCH_EXE, {"--plot", "lobe", "--probe", "1,1", "--render", path("x.png")});
        QVERIFY(run.waitForFinished(kLimitMs));
        QCOMPARE(run.exitCode(), 1);
        QVERIFY(run.readAllStandardError().contains("no display"));
    }

    void badInputGetsAMessageAndWritesNothing()
    {
        struct Bad
        {
            QStringList args;
            const char *says;
        };
        const QString fifo = path("pipe.csv");
        QCOMPARE(mkfifo(QFile::encodeName(fifo).constData(), 0600), 0);
        const QList<Bad> bad{
            {{"--plot", "phong", "--plot-data", path("a.csv")}, "--plot: unknown value 'phong'"},
            {{"--plot", "specular"}, "--plot: needs --render"},
            {{"--plot-data", path("b.csv")}, "--plot-data: goes with --plot"},
            {{"--plot", "diffuse", "--plot-data", fifo}, "--plot-data:"},
            {{"--plot", "diffuse", "--render", path("missing/c.png")}, "--render:"},
            {{"--plot", "diffuse", "--render", path("d.png"), "--bench-frames", "3"},
             "--bench-frames: does not go with --plot"},
            {{"--render", path("e.svg")}, "--render: a frame is written as PNG"},
        };
        for (const Bad &b : bad) {
            const ProgramRun r = plot(b.args);
            QVERIFY2(r.exitCode == 2, qPrintable(b.args.join(' ')));
            QVERIFY2(r.err.contains(b.says), r.err.constData());
        }
        for (const char *never : {"a.csv", "b.csv", "d.png", "e.svg", "missing"})
            QVERIFY2(!QFile::exists(path(never)), never);
        QVERIFY(QFileInfo(fifo).exists() && !QFileInfo(fifo).isFile());

        // Nothing to draw is no error: the plot says why, the CSV has its header alone.
        const ProgramRun r = plot({"--plot", "spot", "--plot-data", path("spot.csv")});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        QVERIFY2(r.err.contains("No spotlight"), r.err.constData());
        QCOMPARE(readCsv(path("spot.csv")).header, QList<QByteArray>({"angle_degrees"}));
    }

    // The lobe with the light at the point itself (issue 49): 361 rows of NaN and 724
    // warnings before; now said, with the CSV's header alone.
    void noLobeWhereTheLightIsAtThePoint()
    {
        const ProgramRun r =
            plot({"--plot", "lobe", "--light", "0,0,0,1", "--plot-data", path("at.csv")});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        QVERIFY2(r.err.contains("No lobe: the light is at the surface's point"), r.err.constData());
        QVERIFY2(!r.err.contains("nan") && r.err.count('\n') == 1, r.err.constData());
        QCOMPARE(readCsv(path("at.csv")).header, QList<QByteArray>({"angle_degrees"}));
    }
};

QTEST_GUILESS_MAIN(TestCliPlot)
#include "test_cli_plot.moc"
