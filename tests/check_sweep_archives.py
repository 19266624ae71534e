#!/usr/bin/env python3
"""The sweeps section of doc/validation.md is what tools/sweep_report.py makes from the archives
the repository keeps (validation/sweeps/<sweep>_summary.csv and what lies beside them).

    check_sweep_archives.py

Reads the command from the section's "Made by `...`" line, checks that it names only archives
(a sweep folder lives on the machine that ran it, so a section made from folders cannot be
remade here: remake it from the archives after a sweep ran), runs that command with the
document copied to a scratch folder, and compares the section it writes with the committed one,
line for line. This fails where a sweep file changed since its archive was made (the report
refuses an archive its sweep file no longer plans), where an archive was edited, or where the
report's rules or wording changed without the section being remade. The scratch folder sees
validation/sweeps through a link, so the figure links and the archives' own folder are those of
the package and nothing is written there.
"""
import os
import re
import shlex
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
REPORT = os.path.join(ROOT, "tools", "sweep_report.py")
DOC = os.path.join(ROOT, "doc", "validation.md")
ARCHIVES = os.path.join(ROOT, "validation", "sweeps")
sys.path.insert(0, os.path.join(ROOT, "tools"))
from sweep_report import SECTION_BEGIN as BEGIN, SECTION_END as END  # noqa: E402


def flagged(words):
    """(option in force, word) for each word of a command line; an option is its own."""
    flag = None
    for w in words:
        flag = w if w.startswith("--") else flag
        yield flag, w


def section(text):
    start, end = text.find(BEGIN), text.find(END)
    return text[start:end + len(END)] if 0 <= start < end else None


def remade_differs(scratch, words, committed):
    """Run the command in scratch, whose validation/sweeps is a link to the package's; return
    the problems (the first differing line, or the report's error)."""
    os.makedirs(os.path.join(scratch, "doc"))
    os.makedirs(os.path.join(scratch, "validation"))
    os.symlink(ARCHIVES, os.path.join(scratch, "validation", "sweeps"))    # rmtree unlinks it
    doc = os.path.join(scratch, "doc", "validation.md")
    with open(doc, "w") as f:
        f.write(open(DOC).read())
    out = os.path.join(scratch, "validation", "sweeps")
    # each archive as a path in the scratch folder, whose validation/sweeps is the package's;
    # --sweeps (a folder of sweep files) from the package's folder, --accept as it is
    args = [w if w == flag or flag == "--accept"
            else os.path.join(ROOT if flag == "--sweeps" else scratch, w)
            for flag, w in flagged(words)]
    result = subprocess.run([sys.executable, REPORT] + args + ["--out", out, "--doc", doc],
                            capture_output=True, text=True)
    if result.returncode != 0:
        return [f"the report of the archives failed ({result.returncode}): "
                f"{result.stderr.strip()}"]
    remade = section(open(doc).read())
    if remade is None:
        return ["the report wrote no section"]
    # the command names the scratch paths; the rest must be the committed text
    remade = remade.replace(os.path.join(scratch, ""), "")
    for k, (a, b) in enumerate(zip(committed.splitlines(), remade.splitlines()), 1):
        if a != b:
            return [f"line {k} of the section differs:\n  committed: {a[:300]}\n"
                    f"  remade:    {b[:300]}"]
    if len(committed.splitlines()) != len(remade.splitlines()):
        return [f"the section has {len(committed.splitlines())} lines, the remade one "
                f"{len(remade.splitlines())}"]
    return []


def main():
    problems = []
    committed = section(open(DOC).read())
    if committed is None:
        print(f"check_sweep_archives: {DOC} has no section {BEGIN}")
        return 1
    made_by = re.search(r"^Made by `(tools/sweep_report\.py [^`]*)`", committed, re.MULTILINE)
    if made_by is None:
        print("check_sweep_archives: the section has no 'Made by `tools/sweep_report.py ...`'")
        return 1
    words = shlex.split(made_by.group(1))[1:]
    # the sweeps: every word after --figN that is not an option or an option's value
    sources = [w for flag, w in flagged(words)
               if w != flag and flag in ("--fig4", "--fig5", "--fig6")]
    folders = [s for s in sources if not s.endswith("_summary.csv")]
    if folders:
        print(f"check_sweep_archives: the section was made from sweep folders "
              f"({', '.join(folders)}), which only the machine that ran them has; remake it "
              f"from their archives (validation/sweeps/<sweep>_summary.csv)")
        return 1
    with tempfile.TemporaryDirectory(prefix="sweep_archives_") as scratch:
        problems += remade_differs(scratch, words, committed)
    for p in problems:
        print(f"FAILED: {p}")
    print(f"check_sweep_archives: {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
