#!/usr/bin/python3
"""Golden-file test of `hlr draw`: the bundled cube and L-bracket, and the filleted bracket with
--smooth-edges thin (fixtures/parts/), drawn to JSON, SVG and DXF must match tests/golden/ byte for byte (JSON: with the timings left out and the input paths cut to
their file names, which differ from run to run and clone to clone).

usage: golden_drawings.py HLR FIXTURES_DIR GOLDEN_DIR WORK_DIR [--update]

--update rewrites the golden files from the current build; review the diff before committing.
A mismatch prints a short unified diff and exits 1.
"""
import difflib
import json
import os
import re
import shutil
import subprocess
import sys

CASES = [  # (mesh, view, options, suffix): front views put hidden edges exactly under visible ones (precedence)
    ("cube.off", "front", [], ""),
    ("cube.off", "iso", [], ""),
    ("l_bracket.off", "front", [], ""),
    ("l_bracket.off", "iso", [], ""),
    # Smooth edges as thin lines: the inner fillet's tangent lines visible, the outer one's hidden
    # (left off the sheet); the SVG's thin group, the DXF's layer THIN.
    ("../parts/filleted_bracket.off", "iso", ["--smooth-edges", "thin"], "_thin"),
]


def normalized_json(text):
    """The JSON as hlr wrote it, byte for byte, but for what differs from run to run and clone to
    clone: the lines of stats.seconds and of the stats.stage_seconds object are left out, and the
    input paths are cut to their file names. (The golden files once held the document as Python
    re-dumped it, json.dumps(indent=1, sort_keys=True), which tested the values but not the bytes;
    for these files that is the same text, so they did not change when the bytes became the test.)"""
    json.loads(text)  # well-formed, whatever the layout
    text = re.sub(r'(?m)^  "seconds": [^\n]*,\n', "", text, count=1)
    text = re.sub(r'(?ms)^  "stage_seconds": \{\n.*?^  \},\n', "", text, count=1)

    def base_names(m):
        names = [json.dumps(os.path.basename(json.loads(f)), ensure_ascii=False)
                 for f in re.findall(r'(?m)^   ("(?:[^"\\]|\\.)*"),?$', m.group(2))]
        return m.group(1) + ",\n".join("   " + n for n in names) + "\n" + m.group(3)

    return re.sub(r'(?ms)^(  "files": \[\n)(.*?)(^  \])', base_names, text, count=1)


def main():
    args = [a for a in sys.argv[1:] if a != "--update"]
    update = "--update" in sys.argv
    if len(args) != 4:
        print(__doc__)
        return 2
    hlr, fixtures, golden, work = args
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    failures = 0
    for mesh, view, options, suffix in CASES:
        stem = f"{os.path.splitext(os.path.basename(mesh))[0]}_{view}{suffix}"
        outputs = [os.path.join(work, f"{stem}.{ext}") for ext in ("json", "svg", "dxf")]
        cmd = [hlr, "draw", os.path.normpath(os.path.join(fixtures, mesh)), "--view", view] + options
        for o in outputs:
            cmd += ["-o", o]
        run = subprocess.run(cmd, capture_output=True, text=True)
        if run.returncode != 0:
            print(f"FAIL {stem}: hlr exited {run.returncode}: {run.stderr.strip()}")
            failures += 1
            continue
        for path in outputs:
            with open(path, encoding="utf-8") as f:
                text = f.read()
            if path.endswith(".json"):
                text = normalized_json(text)
            name = os.path.basename(path)
            want_path = os.path.join(golden, name)
            if update:
                with open(want_path, "w", encoding="utf-8") as f:
                    f.write(text)
                print(f"updated {want_path}")
                continue
            if not os.path.exists(want_path):
                print(f"FAIL {name}: no golden file {want_path} (run with --update)")
                failures += 1
                continue
            with open(want_path, encoding="utf-8") as f:
                want = f.read()
            if text == want:
                print(f"ok   {name}")
                continue
            failures += 1
            diff = list(difflib.unified_diff(want.splitlines(), text.splitlines(), "golden/" + name, "now/" + name,
                                             lineterm="", n=2))
            print(f"FAIL {name}: differs from the golden file ({len(diff)} diff lines; first ones below)")
            print("\n".join(diff[:40]))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
