// The bash completion, written from the options the parser knows (cli_docs.h). It needs
// bash 4 and nothing else: it works with or without the bash-completion package's helpers.
#include "cli_docs.h"

#include "command_line.h"

#include <QStringList>

#include <algorithm>
#include <utility>
#include <vector>

namespace lb {

namespace {

// One word for the shell, quoted so that nothing in it is expanded.
QString shellQuoted(const QString &word)
{
    QString quoted = word;
    return "'" + quoted.replace("'", "'\\''") + "'";
}

QString quotedWords(const QStringList &words)
{
    QStringList quoted;
    for (const QString &word : words)
        quoted << shellQuoted(word);
    return quoted.join(' ');
}

// What the shell offers for the option's value, as the lines of a `case` branch; empty for a
// value with nothing to offer (a number, a list).
QString valueCompletion(const OptionInfo &o)
{
    QString lines;
    if (!o.words.isEmpty()) {
        // compgen -W splits its list at blanks: one quoted word list, each word quoted again.
        lines += QString("            COMPREPLY=($(compgen -W %1 -- \"$cur\"))\n")
                     .arg(shellQuoted(o.words.join(' ')));
    }
    if (o.files)
        lines += "            _lightbench_files" +
                 (o.suffixes.isEmpty() ? QString() : " " + quotedWords(o.suffixes)) + "\n";
    if (o.directory)
        lines += "            _lightbench_folders\n";
    return lines;
}

} // namespace

QString bashCompletion()
{
    // The options whose values complete alike share a branch, in the order --help lists them.
    std::vector<std::pair<QString, QStringList>> branches; // lines, options
    QStringList names;
    for (const OptionInfo &o : visibleOptions()) {
        for (const QString &name : o.names)
            names << (name.size() == 1 ? "-" : "--") + name;
        if (o.valueName.isEmpty())
            continue;
        const QString lines = valueCompletion(o);
        auto same = std::find_if(branches.begin(), branches.end(),
                                 [&](const auto &branch) { return branch.first == lines; });
        if (same == branches.end())
            branches.push_back({lines, {"--" + o.longName()}});
        else
            same->second << "--" + o.longName();
    }

    QString script;
    script += "# bash completion for lightbench                          -*- shell-script -*-\n"
              "# Written by lightbench-docs from the options lightbench knows; do not edit.\n"
              "\n"
              "# Files whose names end in one of the endings given (any file without one), and\n"
              "# folders to look into.\n"
              "_lightbench_files()\n"
              "{\n"
              "    local IFS=$'\\n' name ending\n"
              "    compopt -o filenames 2>/dev/null\n"
              "    for name in $(compgen -f -- \"$cur\"); do\n"
              "        if [[ $# -eq 0 || -d $name ]]; then\n"
              "            COMPREPLY+=(\"$name\")\n"
              "            continue\n"
              "        fi\n"
              "        for ending in \"$@\"; do\n"
              "            if [[ ${name,,} == *.\"$ending\" ]]; then\n"
              "                COMPREPLY+=(\"$name\")\n"
              "                break\n"
              "            fi\n"
              "        done\n"
              "    done\n"
              "}\n"
              "\n"
              "_lightbench_folders()\n"
              "{\n"
              "    local IFS=$'\\n'\n"
              "    compopt -o filenames 2>/dev/null\n"
              "    COMPREPLY+=($(compgen -d -- \"$cur\"))\n"
              "}\n"
              "\n"
              "_lightbench()\n"
              "{\n"
              "    local cur=${COMP_WORDS[COMP_CWORD]} prev=${COMP_WORDS[COMP_CWORD-1]} word\n"
              "    COMPREPLY=()\n"
              "    case $prev in\n";
    for (const auto &[lines, options] : branches) {
        // Six to a line: a pattern continues after a backslash at a line's end.
        QStringList rows;
        for (qsizetype i = 0; i < options.size(); i += 6)
            rows << options.mid(i, 6).join('|');
        script += "        " + rows.join("|\\\n        ") + ")\n";
        script += lines;
        script += "            return\n            ;;\n";
    }
    script += "    esac\n";
    script += "    if [[ $cur == -* ]]; then\n";
    script += QString("        COMPREPLY=($(compgen -W %1 -- \"$cur\"))\n")
                  .arg(shellQuoted(names.join(' ')));
    script +=
        "        return\n"
        "    fi\n"
        "    # FILE...: scenes and lessons for the window; after --grade, submissions (shader\n"
        "    # files, folders, scene files).\n"
        "    for word in \"${COMP_WORDS[@]}\"; do\n"
        "        if [[ $word == --grade ]]; then\n"
        "            _lightbench_files\n"
        "            return\n"
        "        fi\n"
        "    done\n";
    QStringList endings = sceneFileSuffixes();
    for (const QString &ending : lessonFileSuffixes())
        if (!endings.contains(ending))
            endings << ending;
    script += "    _lightbench_files " + quotedWords(endings) + "\n";
    script += "}\n\ncomplete -F _lightbench lightbench\n";
    return script;
}

} // namespace lb
