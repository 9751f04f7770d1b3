#!/usr/bin/env python3
"""Lim's Table 1 for hlr: the room models (rooms.py) drawn from five eyes in a box in the first
room by `hlr frames`, with --cull none and --cull fuzzy. Per model: faces, faces culled, the
fuzzy pass's time, the five frames' solving time (the sum of their stats.seconds, and the
fuzzy pass) each way, the whole process's CPU time (user + system) each way, and whether the
outputs are the same (JSON without stats, SVG bytes).

With --rounds N the two runs alternate N times (none, fuzzy, none, fuzzy, ...) and every time is
the median of its N: on a machine that other jobs share, CPU time in interleaved rounds is what
can be compared.

  fuzzy_rooms.py HLR OUT_DIR [--rooms 1,2,3,4] [--cell 0.5] [--threads 2] [--rounds 3]
"""
import argparse
import json
import os
import resource
import statistics
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))


def run_frames(hlr, mesh, eyes, cull, out, threads):
    os.makedirs(out, exist_ok=True)
    cmd = [hlr, "frames", mesh, "--eyes", eyes, "--target", "5,8,1.5", "--cull", cull, "--threads", str(threads),
           "-o", os.path.join(out, "f%d.json"), "-o", os.path.join(out, "f%d.svg")]
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = after.ru_utime - before.ru_utime + after.ru_stime - before.ru_stime
    frames = [json.load(open(os.path.join(out, f"f{i}.json"))) for i in range(5)]
    return cpu, frames


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("hlr")
    ap.add_argument("out")
    ap.add_argument("--rooms", default="1,2,3,4")
    ap.add_argument("--cell", default="0.5")
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--rounds", type=int, default=1)
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    print("| rooms | faces | culled (all 5 eyes) | fuzzy pass (s) | 5 frames, --cull none (s) | 5 frames, --cull fuzzy (s) | speed-up | "
          "process CPU, none (s) | process CPU, fuzzy (s) | CPU speed-up | same output |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for n in map(int, a.rooms.split(",")):
        mesh = os.path.join(a.out, f"rooms{n}.off")
        subprocess.run([sys.executable, os.path.join(HERE, "rooms.py"), str(n), mesh, "--cell", a.cell], check=True,
                       stdout=subprocess.DEVNULL)
        eyes = mesh[:-4] + ".eyes.txt"
        runs, cpu, solves, passes = {}, {"none": [], "fuzzy": []}, {"none": [], "fuzzy": []}, []
        for _ in range(a.rounds):
            for cull in ("none", "fuzzy"):
                runs[cull] = run_frames(a.hlr, mesh, eyes, cull, os.path.join(a.out, f"rooms{n}_{cull}"), a.threads)
                cpu[cull].append(runs[cull][0])
                solve = sum(fr["stats"]["seconds"] for fr in runs[cull][1])
                if cull == "fuzzy":
                    passes.append(runs[cull][1][0]["stats"]["cull"]["fuzzy_seconds"])
                    solve += passes[-1]  # the passes run once for the group, before its frames
                solves[cull].append(solve)
        same = True
        for i in range(5):
            f, g = dict(runs["fuzzy"][1][i]), dict(runs["none"][1][i])
            f.pop("stats"), g.pop("stats")
            same = same and f == g
            svg = [open(os.path.join(a.out, f"rooms{n}_{c}", f"f{i}.svg"), "rb").read() for c in ("fuzzy", "none")]
            same = same and svg[0] == svg[1]
        cull = runs["fuzzy"][1][0]["stats"]["cull"]
        culled = [fr["stats"]["cull"]["culled"] for fr in runs["fuzzy"][1]]
        # With a split group the frames' parts cull different counts: all of them are shown.
        culled_text = f"{culled[0]} ({100 * culled[0] / cull['patches']:.0f} %)" if len(set(culled)) == 1 else \
            "/".join(map(str, culled)) + f" ({cull.get('parts', 1)} parts)"
        solve = {c: statistics.median(solves[c]) for c in solves}
        time_ = {c: statistics.median(cpu[c]) for c in cpu}
        print(f"| {n} | {cull['patches']} | {culled_text} | "
              f"{statistics.median(passes):.3f} | {solve['none']:.2f} | {solve['fuzzy']:.2f} | "
              f"{solve['none'] / solve['fuzzy']:.2f} | {time_['none']:.2f} | {time_['fuzzy']:.2f} | "
              f"{time_['none'] / time_['fuzzy']:.2f} | {'yes' if same else 'NO'} |", flush=True)


if __name__ == "__main__":
    main()
