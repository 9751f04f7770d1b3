#!/usr/bin/env python3
"""The speed-versus-accuracy chart from the reports of bench/chart/run.sh.

    chart.py CHECK_DIR --out OUT.csv --images PATH_WITHOUT_EXTENSION [--label TEXT]
             [--lineart-lengths LENGTHS.csv --lineart-times DRAW.csv]
             [--lines-csv EARLIER.csv [--lines-label TEXT]]

CHECK_DIR holds NAME__VIEW__METHOD.json (hlr-check/1) and .rc (the exit code) for
METHOD in raster, epick, double, and NAME__LIGHTS__shadows.json for the shadow check (hlr check
--sun ... --raster N,...). Writes one CSV row per mesh, view (or lights) and method (status ok,
failed = the kernel threw, invalid, crashed = no report; column task: lines or shadows), the chart
as PATH.svg and PATH.png (lines on the left, shadows on the right when there are shadow reports),
and prints one table per task: cases, failures, pooled accuracy, summed and median time.
--lines-csv takes the line rows from an earlier run's CSV instead of CHECK_DIR (the line checks
take an hour; the shadow checks a minute), --lines-label says which run that was.

Shadow accuracy of a raster run: 1 - its lit-area error over the surface (hlr check's
relative_lit_area_error: the area-weighted sum of the faces' sunlit-fraction differences),
averaged over the lights; time: the shadow maps and sampling of all lights (the exact method:
cast_shadows of all lights).
"""
import argparse
import csv
import glob
import json
import os
import statistics
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.ticker  # noqa: E402

RASTER_SIZES = [256, 512, 1024, 2048, 4096]
SHADOW_SIZES = [64, 256, 1024, 4096]


def check_rows(check_dir):
    rows = []
    for rc_path in sorted(glob.glob(os.path.join(check_dir, "*.rc"))):
        base = rc_path[:-3]
        name, view, group = os.path.basename(base).split("__")
        if group == "shadows":
            continue
        rc = open(rc_path).read().strip()
        report = None
        if rc == "0" and os.path.exists(base + ".json"):
            with open(base + ".json") as f:
                report = json.load(f)
        expected = [f"raster {n}" for n in RASTER_SIZES] if group == "raster" else [group]
        if report is None:  # crashed or timed out: every method of that process
            for method in expected:
                rows.append(dict(mesh=name, view=view, method=method, status="crashed", seconds="",
                                 fraction=0.0, total_length="", message=f"exit {rc}"))
            continue
        ref_seconds = report["reference"]["seconds"]
        if group == "raster":  # one exact row per case, from the raster process's reference
            rows.append(dict(mesh=name, view=view, method="exact", status="ok", seconds=ref_seconds,
                             fraction=1.0, total_length="", message=""))
        for m in report["methods"]:
            method = m["method"] + (f" {m['resolution']}" if "resolution" in m else "")
            a = m.get("agreement", {})
            rows.append(dict(mesh=name, view=view, method=method, status=m["status"],
                             seconds=m["seconds"] if m["status"] != "failed" else "",
                             fraction=a.get("fraction", 0.0), total_length=a.get("total_length", ""),
                             message=m.get("message", "")))
    return rows


def shadow_rows(check_dir):
    rows = []
    for rc_path in sorted(glob.glob(os.path.join(check_dir, "*__shadows.rc"))):
        base = rc_path[:-3]
        name, lights, _ = os.path.basename(base).split("__")
        rc = open(rc_path).read().strip()
        report = None
        if rc == "0" and os.path.exists(base + ".json"):
            with open(base + ".json") as f:
                report = json.load(f)
        common = dict(task="shadows", mesh=name, view=lights, total_length="")
        if report is None:
            for method in ["exact"] + [f"raster {n}" for n in SHADOW_SIZES]:
                rows.append(dict(common, method=method, status="crashed", seconds="", fraction=0.0,
                                 message=f"exit {rc}"))
            continue
        rows.append(dict(common, method="exact", status="ok", seconds=report["reference"]["seconds"], fraction=1.0,
                         message=""))
        for m in report["shadow_methods"]:
            errors = [light["relative_lit_area_error"] for light in m["lights"]]
            worst = max(light["max_fraction_difference"] for light in m["lights"])
            rows.append(dict(common, method=f"raster {m['resolution']}", status=m["status"], seconds=m["seconds"],
                             fraction=1 - statistics.fmean(errors),
                             message=f"largest sunlit-fraction difference of a face {worst:.4g}"))
    return rows


def lineart_rows(lengths_csv, draw_csv):
    times = {}
    with open(draw_csv) as f:
        for r in csv.DictReader(f):
            times[(r["mesh"], r["view"])] = r["lineart_s"]
    rows = []
    with open(lengths_csv) as f:
        for r in csv.DictReader(f):
            total = float(r["hlr_vis"]) + float(r["hlr_hid"])
            missed = float(r["vis_hlr_only"]) + float(r["hid_hlr_only"])
            t = times.get((r["mesh"], r["view"]), "failed")
            ok = t not in ("failed", "", "n/a")
            rows.append(dict(mesh=r["mesh"], view=r["view"], method="Line Art", status="ok" if ok else "crashed",
                             seconds=float(t) if ok else "", fraction=(1 - missed / total) if total > 0 else 1.0,
                             total_length=total, message="drawn length matched within 1e-4 of the extent"))
    return rows


def summarize(rows):
    # Time is summed over the cases every hlr method finished, so that a kernel that fails on the
    # large meshes is not charted as fast; Line Art over its own cases (the shared meshes). Rows of
    # one task (lines or shadows).
    hlr_rows = [r for r in rows if r["method"] != "Line Art"]
    cases = {(r["mesh"], r["view"]) for r in hlr_rows}
    common = {c for c in cases if all(r["status"] == "ok" for r in hlr_rows if (r["mesh"], r["view"]) == c)}
    methods = []
    for r in rows:
        if r["method"] not in methods:
            methods.append(r["method"])
    order = (["exact", "epick", "double"] + [f"raster {n}" for n in sorted(set(RASTER_SIZES + SHADOW_SIZES))]
             + ["Line Art"])
    methods.sort(key=lambda m: order.index(m) if m in order else len(order))
    out = []
    for m in methods:
        rs = [r for r in rows if r["method"] == m]
        ok = [r for r in rs if r["status"] == "ok"]
        timed = rs if m == "Line Art" else [r for r in rs if (r["mesh"], r["view"]) in common]
        seconds = [float(r["seconds"]) for r in timed if r["seconds"] != ""]
        out.append(dict(method=m, cases=len(rs), ok=len(ok), timed_cases=len(seconds),
                        failed=sum(r["status"] == "failed" for r in rs),
                        invalid=sum(r["status"] == "invalid" for r in rs),
                        crashed=sum(r["status"] == "crashed" for r in rs),
                        accuracy=statistics.fmean(float(r["fraction"]) for r in rs) if rs else 0.0,
                        accuracy_ok=statistics.fmean(float(r["fraction"]) for r in ok) if ok else 0.0,
                        worst=min((float(r["fraction"]) for r in ok), default=0.0),
                        seconds=sum(seconds), median_seconds=statistics.median(seconds) if seconds else 0.0))
    return out


def print_cases(rows, meshes):
    methods = ["epick", "double"] + [f"raster {n}" for n in RASTER_SIZES]
    print("\n| mesh | view | " + " | ".join(methods) + " |")
    print("|---|---|" + "---|" * len(methods))
    for mesh in meshes:
        for view in sorted({r["view"] for r in rows if r["mesh"] == mesh}):
            cells = []
            for m in methods:
                r = next((r for r in rows if r["mesh"] == mesh and r["view"] == view and r["method"] == m), None)
                cells.append("" if r is None else f"{100 * float(r['fraction']):.2f}%" if r["status"] == "ok"
                             else r["status"])
            print(f"| {mesh} | {view} | " + " | ".join(cells) + " |")


def plot_lines(ax, summary, label):
    colors = {"exact": "#000000", "epick": "#d62728", "double": "#ff7f0e", "Line Art": "#2ca02c"}
    raster = [s for s in summary if s["method"].startswith("raster")]
    if raster:
        ax.plot([s["seconds"] for s in raster], [100 * s["accuracy"] for s in raster], "-o", color="#1f77b4",
                label="raster P-buffer, 256 to 4096 px")
        for s in raster:
            ax.annotate(s["method"].split()[1], (s["seconds"], 100 * s["accuracy"]), textcoords="offset points",
                        xytext=(4, -12), fontsize=8, color="#1f77b4")
    for s in summary:
        if s["method"].startswith("raster"):
            continue
        bad = s["failed"] + s["invalid"] + s["crashed"]
        text = s["method"] + (f" ({bad} of {s['cases']} runs failed)" if bad else "")
        marker = "s" if s["method"] == "Line Art" else "D"
        ax.plot([s["seconds"]], [100 * s["accuracy"]], marker, color=colors.get(s["method"], "#7f7f7f"),
                markersize=8, label=text)
    ax.set_xscale("log")
    timed = next((s["timed_cases"] for s in summary if s["method"] == "exact"), 0)
    ax.set_xlabel(f"time summed over the {timed} cases every hlr method finished (s, log scale)")
    ax.set_ylabel("line length classified as exact does (%, mean of cases;\nfailed runs count 0)")
    ax.set_title("lines: speed against accuracy" + (f" ({label})" if label else ""), fontsize=10)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8, loc="lower right")


def plot_shadows(ax, summary, label):
    raster = [s for s in summary if s["method"].startswith("raster")]
    if raster:
        ax.plot([s["seconds"] for s in raster], [100 * (1 - s["accuracy"]) for s in raster], "-o", color="#9467bd",
                label="raster shadow map, " + " to ".join(s["method"].split()[1] for s in (raster[0], raster[-1]))
                + " px")
        for s in raster:
            ax.annotate(s["method"].split()[1], (s["seconds"], 100 * (1 - s["accuracy"])), textcoords="offset points",
                        xytext=(4, 4), fontsize=8, color="#9467bd")
    exact = next((s for s in summary if s["method"] == "exact"), None)
    if exact:
        ax.axvline(exact["seconds"], color="#000000", linestyle="--", linewidth=1,
                   label=f"exact (hlr shadows): lit-area error 0, {exact['seconds']:.3g} s")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.yaxis.set_major_formatter(matplotlib.ticker.FormatStrFormatter("%g"))
    ax.yaxis.set_minor_formatter(matplotlib.ticker.FormatStrFormatter("%g"))
    cases = exact["cases"] if exact else 0
    ax.set_xlabel(f"time summed over {cases} meshes (s, log scale)")
    ax.set_ylabel("lit-area error of the surface (%, mean of meshes\nand lights, log scale)")
    ax.set_title("shadows: speed against accuracy" + (f" ({label})" if label else ""), fontsize=10)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8, loc="upper right")


def plot(lines_summary, shadows_summary, images, lines_label, shadows_label):
    panels = 2 if shadows_summary else 1
    fig, axes = plt.subplots(1, panels, figsize=(8 * panels, 5.2), squeeze=False)
    plot_lines(axes[0][0], lines_summary, lines_label)
    if shadows_summary:
        plot_shadows(axes[0][1], shadows_summary, shadows_label)
    fig.text(0.01, 0.01, "Line Art: its own time on the shared meshes; accuracy = share of hlr's exact drawn length"
             " it draws in the same class (another measure).",
             fontsize=7, color="#555555")
    fig.tight_layout(rect=(0, 0.03, 1, 1))
    os.makedirs(os.path.dirname(images), exist_ok=True)
    fig.savefig(images + ".svg")
    fig.savefig(images + ".png", dpi=110)


def print_summary(summary):
    print("| method | cases | ok | failed | invalid | crashed | accuracy (mean, failures 0) | accuracy of ok runs"
          " | worst ok | timed cases | time summed (s) | median (s) |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|")
    for s in summary:
        print(f"| {s['method']} | {s['cases']} | {s['ok']} | {s['failed']} | {s['invalid']} | {s['crashed']} | "
              f"{100 * s['accuracy']:.3f}% | {100 * s['accuracy_ok']:.3f}% | {100 * s['worst']:.2f}% | "
              f"{s['timed_cases']} | {s['seconds']:.3g} | {s['median_seconds']:.3g} |")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("check_dir")
    ap.add_argument("--out", required=True)
    ap.add_argument("--images", required=True)
    ap.add_argument("--label", default="")
    ap.add_argument("--lineart-lengths")
    ap.add_argument("--lineart-times")
    ap.add_argument("--lines-csv", help="the line rows of an earlier run's CSV, instead of CHECK_DIR's")
    ap.add_argument("--lines-label", help="which run --lines-csv is (default: --label)")
    ap.add_argument("--cases", help="comma list of mesh names: also print their cases, one row per mesh and view "
                                    "(docs/STABILITY.md quotes it)")
    args = ap.parse_args()
    if args.lines_csv:
        with open(args.lines_csv) as f:
            rows = [dict(r, task=r.get("task") or "lines") for r in csv.DictReader(f)
                    if (r.get("task") or "lines") == "lines"]
    else:
        rows = [dict(r, task="lines") for r in check_rows(args.check_dir)]
        if args.lineart_lengths and args.lineart_times:
            rows += [dict(r, task="lines") for r in lineart_rows(args.lineart_lengths, args.lineart_times)]
    shadows = shadow_rows(args.check_dir)
    if not rows and not shadows:
        sys.exit("chart.py: no reports in " + args.check_dir)
    os.makedirs(os.path.dirname(os.path.abspath(args.out)), exist_ok=True)
    fields = ["task", "mesh", "view", "method", "status", "seconds", "fraction", "total_length", "message"]
    with open(args.out, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=fields)
        w.writeheader()
        w.writerows(rows + shadows)
    lines_summary = summarize(rows) if rows else []
    shadows_summary = summarize(shadows) if shadows else []
    plot(lines_summary, shadows_summary, args.images, args.lines_label or args.label, args.label)
    if lines_summary:
        print("lines:")
        print_summary(lines_summary)
    if shadows_summary:
        print("\nshadows (accuracy: 1 - lit-area error over the surface, mean of the lights):")
        print_summary(shadows_summary)
    if args.cases:
        print_cases(rows, args.cases.split(","))
    print(f"wrote {args.out}, {args.images}.svg, {args.images}.png")


if __name__ == "__main__":
    main()
