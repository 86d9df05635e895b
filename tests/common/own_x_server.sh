#!/usr/bin/env bash
# own_x_server.sh COMMAND [ARGS...]: runs COMMAND on an X server of its own (Xvfb, with the
# screen scripts/setup.sh gives the suite), so that the window tests can run side by side:
# windows on one display take the keyboard focus from each other, which made them wait for
# one another (ctest's RESOURCE_LOCK) while a core stood idle. Exits with COMMAND's status.
#
# Xvfb picks a free display itself (-displayfd), so two of these started at once never race
# for one. It is stopped when COMMAND ends, and within a second of this script's end if that
# comes first (ctest killing it at its time limit). Not when its last client goes
# (-terminate): test_installed_tree's commands come and go one after another.
set -u
ready=$(mktemp "${TMPDIR:-/tmp}/lightbench-display.XXXXXX") || exit 1
Xvfb -displayfd 3 -screen 0 1920x1080x24 -nolisten tcp 3>"$ready" 2>"$ready.log" &
server=$!
# The watcher lets go of the output: ctest waits for every holder of the test's pipe, and
# would wait for its next second after each test (every window test took N.1 s).
(
    while kill -0 $$ 2>/dev/null; do sleep 1; done
    kill "$server" 2>/dev/null
) </dev/null >/dev/null 2>&1 &
for _ in $(seq 400); do
    [[ -s $ready ]] && break
    kill -0 "$server" 2>/dev/null || break
    sleep 0.025
done
display=$(head -n 1 "$ready")
if [[ -z $display ]]; then
    echo "own_x_server: Xvfb did not start in 10 s: $(tail -n 5 "$ready.log")" >&2
    kill "$server" 2>/dev/null
    rm -f "$ready" "$ready.log"
    exit 1
fi
rm -f "$ready" "$ready.log"
# The X server just started, and no other (a desktop's Wayland session) instead.
DISPLAY=:$display env -u WAYLAND_DISPLAY "$@"
status=$?
kill "$server" 2>/dev/null
wait "$server" 2>/dev/null
exit $status
