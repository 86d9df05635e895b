"""Moodle CodeRunner: a combinator template grader that grades the student's answer with
lightbench. Make a question type with this file as its template (Python 3, "Is combinator"
and "Template does grading" both on), the exercise (exercise.json) and the program's other
stage (lighting.vert when the answer is the fragment shader) as support files. The Jobe server
needs lightbench and xvfb installed, and room for them: a memory limit of 2000 MB, 120 s
and 64 processes (the question's sandbox settings). lightbench prints CodeRunner's JSON (fraction,
testresults, prologuehtml) and nothing on stderr; this template passes it on."""

import html
import json
import os
import signal
import subprocess

ANSWER_STAGE = "fragment"  # the stage the student writes: "fragment" or "vertex"
EXERCISE = "exercise.json"
LIGHTBENCH = os.environ.get("LIGHTBENCH", "lightbench")
# Below the question's sandbox limit (120 s), so that a run too long still says so here:
# lightbench's own limit for an answer is longer (30 s, 4 s a case, 2 s a known mistake and
# failing case), and an answer takes about a second.
TIME_LIMIT_S = 100

answer = """{{ STUDENT_ANSWER | e('py') }}"""
with open("lighting.frag" if ANSWER_STAGE == "fragment" else "lighting.vert", "w",
          encoding="utf-8") as f:
    f.write(answer)

# -noreset: without it, the reset after lightbench exits can make xvfb-run exit 5 and leave
# Xvfb running.
command = ["xvfb-run", "-a", "-s", "-screen 0 1280x1024x24 -noreset", LIGHTBENCH,
           "--grade", "lighting.vert", "lighting.frag", "--exercise", EXERCISE,
           "--report-format", "coderunner", "--report", "-"]
# Mesa's software renderer starts a thread per core for each program that draws; Jobe counts
# threads as processes: four are plenty at the grading size.
environment = dict(os.environ, LP_NUM_THREADS="4")
output, why = "", ""
try:
    # A session of its own, so that a timeout stops Xvfb and lightbench too, not only xvfb-run.
    with subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL,
                          env=environment, start_new_session=True) as run:
        try:
            stdout, _ = run.communicate(timeout=TIME_LIMIT_S)
            output, why = stdout.decode("utf-8", "replace"), "exit %d" % run.returncode
        except subprocess.TimeoutExpired:
            os.killpg(run.pid, signal.SIGKILL)
            run.communicate()
            why = "more than %d s" % TIME_LIMIT_S
except OSError as error:
    why = str(error)
try:
    result = json.loads(output)
    if not isinstance(result, dict) or "fraction" not in result:
        raise ValueError("no fraction")
except ValueError:
    # Nothing on stderr here either: CodeRunner counts any as a failed run.
    result = {"fraction": 0.0,
              "prologuehtml": "<p>lightbench gave no grade (%s).</p>" % html.escape(why)}
print(json.dumps(result))
