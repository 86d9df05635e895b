#!/bin/sh
# GitHub Classroom's grading step (classroom.yml): grades $SUBMISSION (the student's files,
# separated by spaces) against $EXERCISE and gives the Classroom reporter its result: the
# report in GitHub's shape, base64-encoded, as the step's output `result`. The step fails
# (lightbench's exit 3) when a case fails, so the commit shows a red cross; the reporter still
# runs (`if: always()`). $LIGHTBENCH: the program (default: lightbench on the PATH).
set -u
: "${EXERCISE:?the exercise file}" "${SUBMISSION:?the files of the student}"
: "${GITHUB_OUTPUT:?set by GitHub Actions: the file of the step outputs}"
report="${RUNNER_TEMP:-/tmp}/lightbench-result.json"
rm -f "$report"
# shellcheck disable=SC2086 # SUBMISSION is a list of files
# -noreset: without it, the reset after lightbench exits can make xvfb-run exit 5, not with
# lightbench's status, and leave Xvfb running.
xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" "${LIGHTBENCH:-lightbench}" --grade $SUBMISSION \
    --exercise "$EXERCISE" --report-format github --report "$report"
status=$?
if [ ! -s "$report" ]; then
    # No report (lightbench could not start, or the exercise is broken: its log says why):
    # the reporter still gets a result, one test that says so, and the job fails.
    printf '%s' '{"version":1,"status":"error","max_score":0,"tests":[{"name":"lightbench",' \
        '"status":"error","score":0,"message":"lightbench gave no report: see the log of the' \
        ' step Grade the shaders"}]}' > "$report"
    [ "$status" -eq 0 ] && status=1
fi
echo "result=$(base64 -w0 "$report")" >> "$GITHUB_OUTPUT"
exit "$status"
