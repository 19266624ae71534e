#!/usr/bin/env python3
"""tools/validate.py rewrites doc/validation.md's parts A-C and keeps every section it did not
make: tools/sweep_report.py's, those written by hand after it (AFTER_PART_C), the comparison
with the published code and the 3d section, each once, word for word, in the document's order;
and every section doc/validation.md opens with a marker is one of those (a new hand-written
section that validate.py does not know would be lost at its next run).

    check_validate_sections.py
Exit 77 (skipped) without python3-matplotlib or python3-numpy, which validate.py imports.
"""
import os
import re
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "tools"))
import mesophyll_frames  # noqa: E402
# Debian's python3 where this one lacks them (the tools' rule); else skip
mesophyll_frames.require(["numpy", "matplotlib"], exit_code=77)
import validate  # noqa: E402


def main():
    problems = []
    known = [begin for begin, _ in validate.AFTER_PART_C] + [validate.PUB_BEGIN,
                                                             validate.THREED_BEGIN]
    doc = open(os.path.join(ROOT, "doc", "validation.md")).read()
    for marker in re.findall(r"^<!-- [^/].*-->$", doc, re.MULTILINE):
        if marker not in known:
            problems.append(f"doc/validation.md: the section {marker} is not kept by validate.py")
    sections = [f"{begin}\nbody {k}\n{end}\n"
                for k, (begin, end) in enumerate(validate.AFTER_PART_C)]
    published = f"{validate.PUB_BEGIN}\npart D\n{validate.PUB_END}\n"
    threed = f"{validate.THREED_BEGIN}\n3d\n{validate.THREED_END}\n"
    with tempfile.TemporaryDirectory() as scratch:
        path = os.path.join(scratch, "validation.md")
        with open(path, "w") as f:
            f.write("# Validation\n\nold part A\n\n" + "\n".join(sections) + "\n" + published
                    + threed)
        for attempt in (1, 2):    # a second rewrite must keep what the first kept
            validate.rewrite(path, ["# Validation", "", f"new part A {attempt}"])
            text = open(path).read()
            if "old part A" in text or f"new part A {attempt}" not in text:
                problems.append(f"rewrite {attempt}: parts A-C not replaced")
            kept = sections + [published, threed]
            for section in kept:
                if text.count(section) != 1:
                    problems.append(f"rewrite {attempt}: {section.splitlines()[0]} kept "
                                    f"{text.count(section)} times")
            if "\n".join(sections) not in text:
                problems.append(f"rewrite {attempt}: no blank line between the kept sections")
            where = [text.find(s) for s in kept]
            if sorted(where) != where:
                problems.append(f"rewrite {attempt}: the kept sections out of order")
    for p in problems:
        print("FAILED:", p)
    print(f"check_validate_sections: {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
