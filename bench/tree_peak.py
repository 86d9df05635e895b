#!/usr/bin/env python3
"""Runs COMMAND and prints, on stderr at its end, the peak of the resident memory of its whole
process tree (the workbench and its import helper together, as they overlap in time), sampled
every 5 ms from /proc: `tree_peak_mb=N seconds=S`. GNU time's %M gives only the largest single
process. Linux only. Usage: bench/tree_peak.py COMMAND [ARGS...]   (exits with its exit code)"""
import os
import subprocess
import sys
import time


def children(pid):
    kids = []
    try:
        for task in os.listdir(f"/proc/{pid}/task"):
            with open(f"/proc/{pid}/task/{task}/children") as f:
                kids += [int(k) for k in f.read().split()]
    except OSError:
        pass
    return kids


def resident_kb(pid):
    try:
        with open(f"/proc/{pid}/status") as f:
            for line in f:
                if line.startswith("VmRSS:"):
                    return int(line.split()[1])
    except OSError:
        pass
    return 0


start = time.monotonic()
process = subprocess.Popen(sys.argv[1:])
peak = 0
while process.poll() is None:
    total, todo = 0, [process.pid]
    while todo:
        pid = todo.pop()
        total += resident_kb(pid)
        todo += children(pid)
    peak = max(peak, total)
    time.sleep(0.005)
print(f"tree_peak_mb={peak / 1024:.0f} seconds={time.monotonic() - start:.2f}", file=sys.stderr)
sys.exit(process.returncode)
