#!/usr/bin/env python3
"""The progress meter (--progress, --no-progress, -Q; docs/manual.md, "Progress").

Not timed: the stage lines are forced with --progress, and the meter line is made to update
every millisecond with the documented test hook DELTRI_PROGRESS_TICK_MS. Checked: the lines'
format, one line per stage in the pipeline's order, the refinement line's triangle count against
the .ele written by the same run, the in-place line on a pseudo-terminal, and silence with -Q
and --no-progress on a terminal and off one.

usage: progress.py DELTRI SOURCE_DIR
"""
import os
import pty
import re
import shutil
import subprocess
import sys
import tempfile

DELTRI, SOURCE = sys.argv[1], sys.argv[2]
os.environ.pop("DELTRI_NO_PROGRESS", None)  # the suite's default off; this test checks the real default
STAGE = re.compile(r"^deltri: (read|Delaunay|segments and holes|refinement|check|write) \d+\.\d\d s"
                   r"(, (\d+) triangles(, \d+ triangles/s)?)?$")
METER = re.compile(r"^deltri: [a-zA-Z ]+\.\.\. \d+\.\d s(, about \d+ triangles, -?\d+ triangles/s, "
                   r"queue \d+ \(about \d+% done\))?$")
failures = []


def check(ok, what):
    if not ok:
        failures.append(what)
        if len(failures) <= 10:
            print("FAIL:", what)


def run_pipe(args, env=None):
    r = subprocess.run([DELTRI] + args, capture_output=True, text=True, env=env, timeout=600)
    check(r.returncode == 0, f"{args}: exit {r.returncode}: {r.stderr}")
    return r.stderr


def run_pty(args, env=None):
    """Runs deltri with its standard error on a pseudo-terminal; returns what it wrote there."""
    master, slave = pty.openpty()
    p = subprocess.Popen([DELTRI] + args, stdout=subprocess.DEVNULL, stderr=slave, env=env)
    os.close(slave)
    chunks = []
    while True:
        try:
            data = os.read(master, 65536)
        except OSError:  # the terminal closes when deltri exits
            break
        if not data:
            break
        chunks.append(data)
    os.close(master)
    check(p.wait(timeout=600) == 0, f"{args} on a terminal: exit {p.returncode}")
    return b"".join(chunks).decode()


def ele_triangles(path):
    with open(path) as f:
        return int(f.readline().split()[0])


work = tempfile.mkdtemp(prefix="deltri-progress-")
try:
    shutil.copy(os.path.join(SOURCE, "data", "guitar.poly"), work)
    os.chdir(work)
    args = ["-pq30a0.001", "guitar.poly"]

    # Off a terminal: one line per stage, in order, nothing else.
    lines = run_pipe(args + ["--progress"]).splitlines()
    stages = []
    for line in lines:
        m = STAGE.match(line)
        check(m is not None, f"stage line format: {line!r}")
        if m:
            stages.append(m.group(1))
            if m.group(1) == "refinement":
                check(int(m.group(3)) == ele_triangles("guitar.1.ele"),
                      f"refinement line counts {m.group(3)} triangles, guitar.1.ele has {ele_triangles('guitar.1.ele')}")
    check(stages == ["read", "Delaunay", "segments and holes", "refinement", "write"], f"stages {stages}")

    # On a terminal: the same stage lines, each after a line clear, and the meter rewritten in place.
    env = dict(os.environ, DELTRI_PROGRESS_TICK_MS="5")
    text = run_pty(["-pq30a0.0005", "guitar.poly", "--progress"], env)
    pieces = [p for p in re.split(r"\r|\n|\x1b\[K", text) if p.strip()]
    finished = [p for p in pieces if STAGE.match(p)]
    updates = [p for p in pieces if not STAGE.match(p)]
    check([STAGE.match(p).group(1) for p in finished] == stages, f"terminal stage lines {finished}")
    for p in updates:
        check(METER.match(p) is not None, f"meter line format: {p!r}")
    check(any("about" in p and "refinement" in p for p in updates), f"no refinement meter line among {len(updates)} updates")
    check("\x1b[K" in text and text.count("\n") == len(finished), "the meter line is rewritten in place, not one line each")

    # -Q and --no-progress: nothing on standard error, on a terminal or off it (also with the fast tick).
    for flags in (["-Q"], ["--no-progress"], ["-Q", "--no-progress"]):
        check(run_pty(args + flags, env) == "", f"{flags} on a terminal wrote to standard error")
        check(run_pipe(args + flags, env) == "", f"{flags} off a terminal wrote to standard error")
    # Without a switch a short run (well under 2 s of work) shows nothing.
    check(run_pipe(["-pq", "guitar.poly"]) == "", "a short run without --progress wrote progress")
    # DELTRI_NO_PROGRESS turns the default off, not an explicit --progress.
    quiet_env = dict(os.environ, DELTRI_NO_PROGRESS="1", DELTRI_PROGRESS_TICK_MS="5")
    check(run_pty(["-Q", "-pq30a0.0005", "guitar.poly"], quiet_env) == "", "DELTRI_NO_PROGRESS: the meter still shown")
    check(len(run_pipe(args + ["--progress"], quiet_env).splitlines()) == 5, "DELTRI_NO_PROGRESS silenced --progress")
finally:
    shutil.rmtree(work, ignore_errors=True)

print(f"{len(failures)} failures" if failures else "progress meter: ok")
sys.exit(1 if failures else 0)
