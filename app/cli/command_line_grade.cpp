// The options of --grade and of its children (--grade-one, --grade-prepare), read apart from
// the scene options of command_line.cpp: the batch's own rules (which options go with it, its
// report's format).
#include "command_line_grade.h"

#include "grading_formats.h"
#include "message_text.h"

namespace lb {

QString parseGradeOptions(const QCommandLineParser &parser, CommandLine &cl)
{
    const auto given = [&](const char *name) { return parser.isSet(QString::fromLatin1(name)); };
    const auto value = [&](const char *name) { return parser.value(QString::fromLatin1(name)); };
    const auto bad = [](const char *option, const QString &what) {
        return QString("--%1: %2").arg(QLatin1String(option), what);
    };
    cl.grade = given("grade");
    if (given("grade-one")) {
        cl.gradeOne = value("grade-one");
        cl.gradeName = value("grade-name");
        cl.gradeFrames = value("grade-frames");
    }
    cl.gradePrepare = value("grade-prepare");
    const bool child = !cl.gradeOne.isEmpty() || !cl.gradePrepare.isEmpty();
    for (const char *option : {"exercise", "report", "report-format", "sheets", "seed"})
        if (given(option) && !cl.grade && !child)
            return bad(option, "goes with --grade");
    if (!cl.grade && !child)
        return {};
    // The exercise's scene and each submission's program are what is graded: any other
    // option would be ignored without a word.
    const QStringList allowed{"grade",        "grade-one", "grade-name", "grade-prepare",
                              "grade-frames", "exercise",  "report",     "report-format",
                              "sheets",       "seed"};
    for (const QString &name : parser.optionNames())
        if (!allowed.contains(name))
            return QString("--%1: does nothing with --grade (the exercise's scene and each "
                           "submission's program are graded)")
                .arg(name);
    cl.submissions = parser.positionalArguments();
    if (!given("exercise") || value("exercise").isEmpty())
        return bad("grade", "needs --exercise FILE.json");
    if (cl.grade && cl.submissions.isEmpty())
        return bad("grade", "needs submissions to grade (NAME.vert, a folder, or a scene file)");
    cl.exercisePath = value("exercise");
    cl.reportPath = value("report");
    if (given("report") && cl.reportPath.isEmpty())
        return bad("report", "needs a file name, or - for standard output");
    cl.sheetsDir = value("sheets");
    if (given("sheets") && cl.sheetsDir.isEmpty()) // it wrote no sheet and said nothing
        return bad("sheets", "needs a folder");
    if (given("report-format")) {
        const QString word = value("report-format");
        const auto format = parseReportFormat(word);
        if (!format)
            return bad("report-format",
                       QString("unknown value '%1' (expected %2)")
                           .arg(echoedValue(word, 80), reportFormatNames().join('|')));
        if (!given("report"))
            return bad("report-format", "goes with --report FILE (or --report - for standard "
                                        "output)");
        cl.reportFormat = int(*format);
    }
    if (given("seed")) {
        bool ok = false;
        const QString text = value("seed");
        const qint64 seed = text.toLongLong(&ok);
        if (!ok)
            return bad("seed", QString("'%1' is not a whole number").arg(echoedValue(text, 80)));
        if (seed < 0 || seed > 2147483647)
            return bad("seed", QString("%1 is outside 0 to 2147483647").arg(seed));
        cl.seed = std::uint32_t(seed);
    }
    return {};
}

} // namespace lb
