#!/usr/bin/env python3
"""Renders clip_bench's JSON output (--benchmark_out_format=json) as the Markdown tables of
docs/BENCHMARKS.md.

    python3 bench/bench_table.py clip_bench.json [--time cpu|real] [--aggregate median]

With --aggregate, reads the aggregate rows of a run with --benchmark_repetitions (e.g. median).

Times are per pair (BM_Pair) or per list of 1,000 triangles (BM_Triangles). Ratios:
"CGAL / hlr" is how many times faster hlr_exact is than CGAL (goal >= 10 up to 64 vertices),
"hlr / Clipper1" how many times slower hlr_exact is than Clipper1 (goal <= 2).
"""
import argparse
import json
import re
import sys

PAIR_METHODS = ["hlr_exact", "hlr_exact_prebuilt", "hlr_epick", "hlr_double", "cgal", "cgal_prebuilt", "clipper1"]
TRI_METHODS = ["hlr_exact", "hlr_epick", "hlr_double", "cgal", "clipper1"]
NAME = re.compile(r"^(BM_\w+)/(\w+)/(\d+)/holes:(\d)$")


def fmt_time(us):
    if us is None:
        return "—"
    if us >= 100_000:
        return f"{us / 1000:,.0f} ms"
    if us >= 10_000:
        return f"{us / 1000:.1f} ms"
    if us >= 1000:
        return f"{us / 1000:.2f} ms"
    if us >= 100:
        return f"{us:.0f} µs"
    return f"{us:.1f} µs"


def fmt_ratio(r):
    return "—" if r is None else (f"{r:.1f}×" if r < 100 else f"{r:.0f}×")


def to_us(b, key):
    scale = {"ns": 1e-3, "us": 1.0, "ms": 1e3, "s": 1e6}[b.get("time_unit", "ns")]
    return b[key] * scale


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("json")
    ap.add_argument("--time", choices=["cpu", "real"], default="cpu")
    ap.add_argument("--aggregate", help="use this aggregate (mean, median, ...) of repeated runs")
    args = ap.parse_args()
    data = json.load(open(args.json))
    key = "cpu_time" if args.time == "cpu" else "real_time"

    runs = {}  # (family, method, n, holes) -> benchmark
    for b in data["benchmarks"]:
        if args.aggregate:
            if b.get("run_type") != "aggregate" or b.get("aggregate_name") != args.aggregate:
                continue
        elif b.get("run_type", "iteration") != "iteration":
            continue
        m = NAME.match(b["run_name"] if "run_name" in b else b["name"])
        if not m:
            continue
        family, method, n, holes = m.group(1), m.group(2), int(m.group(3)), int(m.group(4))
        runs[(family, method, n, holes)] = b

    def t(family, method, n, holes):
        b = runs.get((family, method, n, holes))
        if b is None or b.get("error_occurred"):
            return None
        return to_us(b, key)

    out = []
    sizes = sorted({k[2] for k in runs if k[0] == "BM_Pair"})
    out.append("| n | holes | hlr exact | hlr exact (prebuilt) | hlr epick | hlr double | CGAL | CGAL (prebuilt) "
               "| Clipper1 | CGAL / hlr exact | hlr exact / Clipper1 |")
    out.append("|---:|:---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for holes in (0, 1):
        for n in sizes:
            times = {m: t("BM_Pair", m, n, holes) for m in PAIR_METHODS}
            he, cg, cl = times["hlr_exact"], times["cgal"], times["clipper1"]
            cells = [fmt_time(times[m]) for m in PAIR_METHODS]
            for m in ("hlr_epick", "hlr_double"):
                b = runs.get(("BM_Pair", m, n, holes))
                if b and (b.get("fail", 0) or b.get("fail_other", 0)):
                    i = PAIR_METHODS.index(m)
                    cells[i] += f" (fail {100 * (b.get('fail', 0) + b.get('fail_other', 0)):.0f}%)"
            r_cgal = cg / he if he and cg else None
            r_clip = he / cl if he and cl else None
            out.append(f"| {n} | {'4' if holes else '0'} | " + " | ".join(cells) +
                       f" | {fmt_ratio(r_cgal)} | {fmt_ratio(r_clip)} |")
    out.append("")

    out.append("| clip | hlr exact | hlr epick | hlr double | CGAL | Clipper1 | CGAL / hlr exact | hlr exact / Clipper1 |")
    out.append("|---|---:|---:|---:|---:|---:|---:|---:|")
    for holes in (0, 1):
        n = 64
        times = {m: t("BM_Triangles", m, n, holes) for m in TRI_METHODS}
        he, cg, cl = times["hlr_exact"], times["cgal"], times["clipper1"]
        out.append(f"| star {n}, {'4 holes' if holes else 'no holes'} | " +
                   " | ".join(fmt_time(times[m]) for m in TRI_METHODS) +
                   f" | {fmt_ratio(cg / he if he and cg else None)} | {fmt_ratio(he / cl if he and cl else None)} |")
    out.append("")

    # Agreement check: output polygon counts and areas of pool pair 0 per method.
    out.append("| n | holes | method | in_polys | out_polys | area_in (pair 0) | area_out (pair 0) | out_verts (pair 0) |")
    out.append("|---:|:---:|---|---:|---:|---:|---:|---:|")
    for holes in (0, 1):
        for n in sizes:
            for m in ("hlr_exact", "cgal", "clipper1"):
                b = runs.get(("BM_Pair", m, n, holes))
                if not b:
                    continue
                out.append(f"| {n} | {'4' if holes else '0'} | {m} | {b.get('in_polys', 0):.1f} | "
                           f"{b.get('out_polys', 0):.1f} | {b.get('area_in', 0):.4f} | {b.get('area_out', 0):.4f} | "
                           f"{b.get('out_verts', 0):.0f} |")
    print("\n".join(out))


if __name__ == "__main__":
    sys.exit(main())
