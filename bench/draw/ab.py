#!/usr/bin/env python3
"""A/B of two hlr binaries on the shared scenes: the same drawing, and how much faster.

usage (from the repo root): bench/draw/ab.py BEFORE AFTER [MESH...]

For every mesh (default: ../shared/scenes/*.off) and view (VIEWS, default front,top,right,iso) it
runs `hlr draw MESH --view V --threads T -o X.json` with each binary RUNS times (default 3), the two
interleaved, keeps each binary's least stats.seconds, and checks that both wrote the same
hlr-lines/1 document apart from its stats. Prints one line per case (the times, their ratio and
the stages that changed most) and the median and geometric mean of the ratios; exits 1 when a
drawing differs. Env: VIEWS, RUNS, T (threads, default 1). What docs/BENCHMARKS.md's before/after
figures of the shared scenes come from; no peer (bench/draw/run.sh runs Line Art).
"""
import glob
import json
import math
import os
import subprocess
import sys
import tempfile


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    before, after = sys.argv[1], sys.argv[2]
    meshes = sys.argv[3:] or sorted(glob.glob("../shared/scenes/*.off"))
    views = os.environ.get("VIEWS", "front,top,right,iso").split(",")
    runs = int(os.environ.get("RUNS", "3"))
    threads = os.environ.get("T", "1")
    out = os.path.join(tempfile.mkdtemp(), "x.json")

    def run(binary, mesh, view):
        subprocess.run([binary, "draw", mesh, "--view", view, "--threads", threads, "-o", out],
                       check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        with open(out) as f:
            doc = json.load(f)
        return doc, doc.pop("stats")

    ratios, differ = [], 0
    for mesh in meshes:
        for view in views:
            best = {}
            docs = {}
            for r in range(runs):
                for name, binary in ((("before", before), ("after", after)) if r % 2 == 0
                                     else (("after", after), ("before", before))):
                    doc, stats = run(binary, mesh, view)
                    docs[name] = doc
                    if name not in best or stats["seconds"] < best[name]["seconds"]:
                        best[name] = stats
            same = docs["before"] == docs["after"]
            differ += not same
            a, b = best["before"], best["after"]
            ratio = b["seconds"] / a["seconds"]
            ratios.append(ratio)
            stages = sorted(a["stage_seconds"], key=lambda s: b["stage_seconds"][s] - a["stage_seconds"][s])[:2]
            print("%-24s %-6s %-9s %9.1f -> %9.1f ms (%.2f)  %s" % (
                os.path.basename(mesh), view, "same" if same else "DIFFERENT", 1e3 * a["seconds"],
                1e3 * b["seconds"], ratio, ", ".join("%s %.1f -> %.1f" % (s, 1e3 * a["stage_seconds"][s],
                                                                         1e3 * b["stage_seconds"][s]) for s in stages)),
                  flush=True)
    ratios.sort()
    print("%d cases, %d different; after/before: median %.3f, geometric mean %.3f" % (
        len(ratios), differ, ratios[len(ratios) // 2], math.exp(sum(map(math.log, ratios)) / len(ratios))))
    sys.exit(1 if differ else 0)


if __name__ == "__main__":
    main()
