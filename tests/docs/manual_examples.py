#!/usr/bin/env python3
"""Runs the shell examples of a Markdown manual and compares what they print with what it says.

    manual_examples.py DELTRI_DIR MANUAL.md [INPUT_DIR ...] [--show]

Every fenced block is read as a session: a line starting with "$ " is a command, the lines after
it, up to the next command, are what it should print (stdout and stderr together). The commands
of the whole manual run in order, in one scratch directory holding copies of the INPUT_DIRs'
files, with DELTRI_DIR first on PATH. A `cat FILE` of a file that does not exist yet writes the
block's text into FILE first (that is how the manual shows its small inputs), and a block that
begins with a `#` comment line and no command is saved as plate.poly (the manual's example PSLG).
Run times such as "(0.002 s)" and the stage timings of -V are not compared, and an expected line
ending in "..." matches any line that starts with the rest. Commands that need tools or context
the scratch directory lacks (gmsh, meshio, pipes from made-up programs, ulimit tricks and the
listings around them, batch files from elsewhere) are run but not compared, and so are commands
whose expected output is empty or elided with a line "...". Exit status 1 if any example prints
something else; --show prints every mismatch as a diff.
"""
import difflib
import os
import re
import shutil
import subprocess
import sys
import tempfile

SKIP = ("gmsh", "meshio", "gen_points", "/path/to", "batch.mk", "ulimit", "mkdir plate.1.poly", "python3")
UNCOMPARED = ("ls", "echo $?")  # listings of the scratch directory, status of a skipped command
TIME = re.compile(r"\(\d+\.\d+ s\)")
STAGE = re.compile(r"^(  \S.*?)\s+\d+\.\d+ s$")


def matches(expected, got):
    if len(expected) != len(got):
        return False
    for e, g in zip(expected, got):
        if e.endswith("...") and e.strip() != "...":
            if not g.startswith(e[:-3]):
                return False
        elif e != g:
            return False
    return True


def normalise(text):
    out = []
    for line in text.rstrip("\n").split("\n"):
        line = TIME.sub("(T s)", line.rstrip())
        m = STAGE.match(line)
        out.append(m.group(1) + " T s" if m else line)
    return out


def sessions(manual):
    """Yields (line number, command, expected lines) for every example, and ('file', text) for the
    example PSLG block."""
    lines = open(manual, encoding="utf-8").read().split("\n")
    i = 0
    while i < len(lines):
        if not lines[i].startswith("```"):
            i += 1
            continue
        j = i + 1
        while j < len(lines) and not lines[j].startswith("```"):
            j += 1
        block = lines[i + 1:j]
        if block and block[0].startswith("#") and not any(l.startswith("$ ") for l in block):
            yield ("file", "plate.poly", "\n".join(block) + "\n")
        k = 0
        while k < len(block):
            if block[k].startswith("$ "):
                command, expected = block[k][2:], []
                k += 1
                while k < len(block) and not block[k].startswith("$ "):
                    expected.append(block[k])
                    k += 1
                yield (i + 1 + k, command, expected)
            else:
                k += 1
        i = j + 1


def main():
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    show = "--show" in sys.argv
    deltri_dir, manual, inputs = os.path.abspath(args[0]), args[1], args[2:]
    work = tempfile.mkdtemp(prefix="manual-")
    try:
        for d in inputs:
            for name in os.listdir(d):
                if os.path.isfile(os.path.join(d, name)):
                    shutil.copy(os.path.join(d, name), work)
        env = dict(os.environ, PATH=deltri_dir + os.pathsep + os.environ["PATH"])
        checked = mismatched = skipped = 0
        for item in sessions(manual):
            if item[0] == "file":
                if not os.path.exists(os.path.join(work, item[1])):
                    open(os.path.join(work, item[1]), "w").write(item[2])
                continue
            line, command, expected = item
            bare = command.split("#")[0].strip() if " # " in command or "  #" in command else command
            m = re.match(r"cat (\S+)$", bare)
            if m and not os.path.exists(os.path.join(work, m.group(1))):
                open(os.path.join(work, m.group(1)), "w").write("\n".join(expected) + "\n")
            if (any(s in command for s in SKIP) or bare in UNCOMPARED or not expected
                    or any(l.strip() == "..." for l in expected)):
                skipped += 1
                subprocess.run(["bash", "-c", bare], cwd=work, env=env, capture_output=True)
                continue
            got = subprocess.run(["bash", "-c", "{ " + bare + "\n} 2>&1"], cwd=work, env=env,
                                 capture_output=True, text=True).stdout
            checked += 1
            if not matches(normalise("\n".join(expected)), normalise(got)):
                mismatched += 1
                print(f"{manual}:{line}: $ {command}")
                if show:
                    for d in difflib.unified_diff(normalise("\n".join(expected)), normalise(got), "manual", "deltri",
                                                  lineterm="", n=1):
                        print("    " + d)
        print(f"{checked} examples compared, {mismatched} differ, {skipped} skipped")
        return 1 if mismatched else 0
    finally:
        shutil.rmtree(work)


if __name__ == "__main__":
    sys.exit(main())
