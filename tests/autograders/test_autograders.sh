#!/usr/bin/env bash
# The ready-made autograders (resources/autograders/) run here as each platform runs them,
# in temporary folders laid out as the platform lays them out, with the sample submissions
# (tests/data/grading): GitHub Classroom's grading step (grade.sh with $GITHUB_OUTPUT and
# $RUNNER_TEMP, its result decoded from base64 as the reporter decodes it), Gradescope's
# run_autograder (/autograder/{source,submission,results} under a temp root), CodeRunner's
# template (its Twig placeholder filled as CodeRunner fills it, run in a Jobe-like working
# folder with the support files). Each output's shape is checked; a broken exercise still
# gives each platform a result that says so, and CodeRunner's run writes nothing on stderr.
#   test_autograders.sh LIGHTBENCH SOURCE_DIR
set -euo pipefail
export LIGHTBENCH="$1"
src="$2"
autograders="$src/resources/autograders"
samples="$src/tests/data/grading"
exercise="$src/resources/examples/exercise_lighting.json"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failures=0
fail() { echo "FAIL: $*" >&2; failures=$((failures + 1)); }

# check_json KIND FILE EXPECT: FILE's JSON has KIND's shape; EXPECT is pass, fail or error.
check_json() {
    python3 - "$@" <<'PY' || return 1
import json, sys
kind, path, expect = sys.argv[1:4]
data = json.load(open(path, encoding="utf-8"))
def need(ok, what):
    if not ok:
        sys.exit("%s %s: %s\n%s" % (kind, path, what, json.dumps(data)[:2000]))
num = lambda v: isinstance(v, (int, float)) and not isinstance(v, bool)
if kind == "github":
    need(data.get("version") == 1, "version is not 1")
    need(data.get("status") in ("pass", "fail", "error"), "status")
    need(num(data.get("max_score")), "max_score")
    need(isinstance(data.get("tests"), list) and data["tests"], "tests")
    for t in data["tests"]:
        need(isinstance(t.get("name"), str) and t.get("status") in ("pass", "fail", "error"),
             "a test's name or status")
        need(num(t.get("score")) and isinstance(t.get("message", ""), str), "a test's score")
    score = sum(t["score"] for t in data["tests"])
    status = data["status"]
    need(status == expect, "status %s, expected %s" % (status, expect))
    if expect == "pass":
        need(abs(score - data["max_score"]) < 1e-6 and data["max_score"] > 0, "not full marks")
    else:
        need(score < data["max_score"] or data["max_score"] == 0, "full marks for a failure")
elif kind == "gradescope":
    need(num(data.get("score")), "score")
    need(isinstance(data.get("output", ""), str), "output")
    tests = data.get("tests")
    need(isinstance(tests, list), "tests")
    for t in tests:
        need(num(t.get("score")) and num(t.get("max_score")) and isinstance(t.get("name"), str),
             "a test's score, max_score or name")
        need(t.get("visibility", "visible") in ("hidden", "after_due_date", "after_published",
                                                "visible"), "a test's visibility")
        need(isinstance(t.get("output", ""), str), "a test's output")
    top = sum(t["max_score"] for t in tests)
    if expect == "pass":
        need(tests and abs(data["score"] - top) < 1e-6, "not full marks")
    elif expect == "fail":
        need(tests and data["score"] < top, "full marks for a failure")
    else:
        need(data["score"] == 0 and data.get("output"), "no score 0 with a reason")
elif kind == "coderunner":
    fraction = data.get("fraction")
    need(num(fraction) and 0 <= fraction <= 1, "fraction")
    need(isinstance(data.get("prologuehtml", ""), str), "prologuehtml")
    rows = data.get("testresults")
    if rows is not None:
        need(isinstance(rows, list) and rows and all(isinstance(r, list) for r in rows),
             "testresults is not a table")
        need(all(len(r) == len(rows[0]) for r in rows), "testresults' rows differ in length")
    if expect == "pass":
        need(fraction == 1 and rows and "iscorrect" in rows[0], "not full marks with a table")
    elif expect == "fail":
        need(fraction < 1, "full marks for a failure")
    else:
        need(fraction == 0 and data.get("prologuehtml"), "no fraction 0 with a reason")
PY
}

# GitHub Classroom: the student's repository holds lighting.vert and lighting.frag.
github() { # SAMPLE_VERT SAMPLE_FRAG EXPECT EXIT [EXERCISE [PROGRAM]]
    local repo="$tmp/github-$3-$4-${6:+fallback}" out
    mkdir -p "$repo/.github/lightbench" "$repo/runner"
    cp "$1" "$repo/lighting.vert"
    cp "$2" "$repo/lighting.frag"
    cp "${5:-$exercise}" "$repo/.github/lightbench/exercise.json"
    cp "$autograders/github-classroom/grade.sh" "$repo/.github/lightbench/"
    local status=0
    (cd "$repo" && LIGHTBENCH="${6:-$LIGHTBENCH}" GITHUB_OUTPUT="$repo/output" RUNNER_TEMP="$repo/runner" \
        EXERCISE=.github/lightbench/exercise.json SUBMISSION="lighting.vert lighting.frag" \
        sh .github/lightbench/grade.sh >"$repo/log" 2>&1) || status=$?
    [[ $status -eq $4 ]] || fail "github $1: exit $status, expected $4: $(cat "$repo/log")"
    out=$(grep '^result=' "$repo/output" 2>/dev/null | tail -1 | cut -d= -f2-) || true
    [[ -n $out ]] || { fail "github $1: no result= output"; return; }
    base64 -d <<<"$out" >"$repo/result.json" || { fail "github $1: result is not base64"; return; }
    check_json github "$repo/result.json" "$3" || fail "github $1"
}
github "$samples/correct/lighting.vert" "$samples/correct/lighting.frag" pass 0
github "$samples/reflect_sign.vert" "$samples/reflect_sign.frag" fail 3
github "$samples/syntax.vert" "$samples/syntax.frag" error 3 # not graded: "error"
echo '{"format": "lightbench-scene"}' >"$tmp/broken.json"
github "$samples/syntax.vert" "$samples/syntax.frag" error 2 "$tmp/broken.json"
# No report at all (the program cannot start): grade.sh's own result, status error.
github "$samples/correct/lighting.vert" "$samples/correct/lighting.frag" error 1 "$exercise" /bin/false
# The workflow calls that step and hands its output to the reporter under the step's id.
workflow="$autograders/github-classroom/classroom.yml"
for needed in 'id: lightbench' 'sh .github/lightbench/grade.sh' \
    'LIGHTBENCH_RESULTS: "${{ steps.lightbench.outputs.result }}"' 'runners: lightbench' \
    'classroom-resources/autograding-grading-reporter@v1' 'if: always()'; do
    grep -qF "$needed" "$workflow" || fail "classroom.yml lacks: $needed"
done

# Gradescope: /autograder/source (the zip), /autograder/submission, /autograder/results.
gradescope() { # SAMPLE_DIR_OR_PAIR EXPECT [EXERCISE [PROGRAM [FOLDER]]]
    local root="$tmp/gradescope-$2-$(basename "$1")${4:+-fallback}${5:+-nested}"
    local upload="$root/submission${5:+/$5}"
    mkdir -p "$root/source" "$upload"
    cp "$autograders/gradescope/setup.sh" "$autograders/gradescope/run_autograder" "$root/source/"
    cp "${3:-$exercise}" "$root/source/exercise.json"
    if [[ -d $1 ]]; then cp "$1"/* "$upload/"; else cp "$1".vert "$1".frag "$upload/"; fi
    echo "notes the student uploaded too" >"$root/submission/README.txt"
    if [[ -n ${5:-} ]]; then # what a Mac's zip adds: a second "fragment shader" that is not one
        mkdir -p "$root/submission/__MACOSX/$5"
        printf '\0\5\26\7' >"$root/submission/__MACOSX/$5/._lighting.frag"
    fi
    LIGHTBENCH="${4:-$LIGHTBENCH}" AUTOGRADER_ROOT="$root" bash "$root/source/run_autograder" >"$root/log" 2>&1 ||
        fail "gradescope $1: run_autograder exit $?: $(cat "$root/log")"
    [[ -s $root/results/results.json ]] || { fail "gradescope $1: no results.json"; return; }
    check_json gradescope "$root/results/results.json" "$2" || fail "gradescope $1"
}
gradescope "$samples/correct" pass
gradescope "$samples/normal_matrix" fail
gradescope "$samples/loop" fail
gradescope "$samples/correct" error "$tmp/broken.json"
gradescope "$samples/correct" error "$exercise" /bin/false # no report: run_autograder's own
# A zip of a folder: the pair one level down, macOS's __MACOSX copies beside it.
gradescope "$samples/correct" pass "$exercise" "" shaders

# CodeRunner: the answer is the fragment shader; the vertex shader and the exercise are
# support files in Jobe's working folder. Twig's e('py') escapes for a Python string.
coderunner() { # SAMPLE_VERT SAMPLE_FRAG EXPECT [EXERCISE]
    local work="$tmp/coderunner-$3-$(basename "$2")"
    mkdir -p "$work"
    cp "$1" "$work/lighting.vert"
    cp "${4:-$exercise}" "$work/exercise.json"
    python3 - "$autograders/coderunner/template.py" "$2" "$work/prog.py" <<'PY'
import json, sys
template, answer, out = sys.argv[1:4]
text = open(template, encoding="utf-8").read()
# Twig's e('py') (CodeRunner's own escaper): backslashes and double quotes, nothing else.
escaped = open(answer, encoding="utf-8").read().replace("\\", "\\\\").replace('"', '\\"')
placeholder = "{{ STUDENT_ANSWER | e('py') }}"
assert placeholder in text, "the template has no answer placeholder"
open(out, "w", encoding="utf-8").write(text.replace(placeholder, escaped))
PY
    (cd "$work" && python3 prog.py >stdout 2>stderr) || fail "coderunner $2: exit $?"
    [[ ! -s $work/stderr ]] || fail "coderunner $2: stderr: $(head -c 500 "$work/stderr")"
    check_json coderunner "$work/stdout" "$3" || fail "coderunner $2"
}
coderunner "$samples/correct/lighting.vert" "$samples/correct/lighting.frag" pass
coderunner "$samples/reflect_sign.vert" "$samples/reflect_sign.frag" fail
coderunner "$samples/syntax.vert" "$samples/syntax.frag" fail
coderunner "$samples/syntax.vert" "$samples/syntax.frag" error "$tmp/broken.json"
LIGHTBENCH=/bin/false coderunner "$samples/correct/lighting.vert" "$samples/correct/lighting.frag" error

[[ $failures -eq 0 ]] || { echo "$failures failures" >&2; exit 1; }
echo "all autograders passed"
