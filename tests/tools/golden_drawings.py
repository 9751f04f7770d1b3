#!/usr/bin/python3
"""Golden-file test of `hlr draw`: the bundled cube and L-bracket drawn to JSON, SVG and DXF must
match tests/golden/ byte for byte (JSON: after dropping the timings and the input paths, which
differ from run to run and clone to clone).

usage: golden_drawings.py HLR FIXTURES_DIR GOLDEN_DIR WORK_DIR [--update]

--update rewrites the golden files from the current build; review the diff before committing.
A mismatch prints a short unified diff and exits 1.
"""
import difflib
import json
import os
import shutil
import subprocess
import sys

CASES = [  # (mesh, view): front views put hidden edges exactly under visible ones (precedence)
    ("cube.off", "front"),
    ("cube.off", "iso"),
    ("l_bracket.off", "front"),
    ("l_bracket.off", "iso"),
]


def normalized_json(text):
    doc = json.loads(text)
    doc["stats"].pop("seconds", None)
    doc["stats"].pop("stage_seconds", None)
    doc["input"]["files"] = [os.path.basename(f) for f in doc["input"]["files"]]
    return json.dumps(doc, indent=1, sort_keys=True) + "\n"


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
    for mesh, view in CASES:
        stem = f"{os.path.splitext(mesh)[0]}_{view}"
        outputs = [os.path.join(work, f"{stem}.{ext}") for ext in ("json", "svg", "dxf")]
        cmd = [hlr, "draw", os.path.join(fixtures, mesh), "--view", view]
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
