#!/usr/bin/env python3
"""Drawn lengths of hlr and Line Art under one rule, and where they differ, from a KEEP folder
of bench/draw/run.sh.

    bench/draw/union_lengths.py KEEP_DIR [-o OUT.csv] [--tol 1e-5] [--diff DIR]

bench/draw/run.sh compares hlr's drawn lengths (after ISO 128 precedence: hidden pieces under
visible ones removed, coincident duplicates once) with Line Art's raw stroke lengths (every
stroke summed, duplicates and hidden-under-visible included). This script applies one rule to
both, in 2D:
  vis = length of the union of the visible segments,
  hid = length of the union of the hidden segments minus the visible union,
with segments taken as coincident when they lie on one line within tol * extent (extent = the
larger side of hlr's 2D bounding box; angle bins of tol * 10 rad). Then it measures what one
tool draws and the other does not: *_hlr_only / *_la_only = length of one tool's drawn visible
(hidden) pieces farther than --match * extent from every drawn visible (hidden) piece of the
other tool (sampled every extent / 20000).

It reads
  hlr_<mesh>_<view>.json   hlr draw's hlr-lines/1 (view coordinates, exact doubles),
  peer/<mesh>_<view>.strokes.json  the peer's strokes (lineart_measure.py --strokes: float32
                           points, full precision) when present, else
  peer/<mesh>_<view>.svg   the peer's SVG; its <desc> gives the map back to view-plane units
                           (u0, v0, scale, margin), coordinates printed to 0.001 px (~1e-6 of
                           the extent),
  peer/<mesh>_<view>.json  the peer's record: view_origin/right/up place its view plane in
                           hlr's view frame (same axes, the origin differs; a mismatch is said).
hlr_vis_check / hlr_hid_check are hlr's unions at --check-tol (default 1e-12: exact coincidence)
minus stats.drawn_visible/hidden_length; near 0 they show that this script applies hlr's rule.
--diff DIR writes <mesh>_<view>_diff.svg: hlr's drawing thin grey, hlr-only pieces blue,
Line Art-only red (thick solid = visible, thick dashed = hidden).
"""
import argparse
import csv
import glob
import json
import math
import os
import re
import sys
from collections import defaultdict


def hlr_segments(path):
    with open(path) as f:
        d = json.load(f)
    segs = []
    for ln in d["lines"]:
        a, b = ln["a"], ln["b"]
        segs.append(((a[0], a[1]), (b[0], b[1]), bool(ln["visible"])))
    return segs, d["stats"], d["view"]["world_to_view"]


def peer_to_hlr(peer_json, m):
    """The affine map from the peer's view plane (u, v about its view_origin, along view_right
    and view_up) to hlr's view (x, y): x = row0 . (origin + u right + v up) + t0, y likewise.
    Also returns the 2x2 part, which is the identity when both frames agree."""
    with open(peer_json) as f:
        d = json.load(f)
    o, R, U = d["view_origin"], d["view_right"], d["view_up"]
    dot = lambda r, v: sum(r[i] * v[i] for i in range(3))
    A = [[dot(m[i], R), dot(m[i], U)] for i in (0, 1)]
    t = [dot(m[i], o) + m[i][3] for i in (0, 1)]
    f = lambda p: (A[0][0] * p[0] + A[0][1] * p[1] + t[0], A[1][0] * p[0] + A[1][1] * p[1] + t[1])
    return f, A


DESC = re.compile(r"u0=(\S+) v0=(\S+) scale=(\S+) margin=(\S+)</desc>")


def svg_segments(path):
    text = open(path).read()
    u0, v0, s, mg = (float(x) for x in DESC.search(text).groups())
    segs, layer = [], None
    for line in text.splitlines():
        if line.startswith('<g id="hidden"'):
            layer = False
        elif line.startswith('<g id="visible"'):
            layer = True
        elif line.startswith("<polyline"):
            pts = []
            for xy in line.split('"')[1].split():
                x, y = (float(c) for c in xy.split(","))
                pts.append(((x - mg) / s + u0, v0 - (y - mg) / s))
            segs += [(a, b, layer) for a, b in zip(pts, pts[1:])]
    return segs


def strokes_segments(path):
    with open(path) as f:
        d = json.load(f)
    segs = []
    for st in d["strokes"]:
        pts = [tuple(p) for p in st["uv"]]
        segs += [(a, b, st["layer"] == "visible") for a, b in zip(pts, pts[1:])]
    return segs


def extent_of(segs):
    pts = [p for sg in segs for p in sg[:2]]
    if not pts:
        return 1.0
    return max(max(p[0] for p in pts) - min(p[0] for p in pts),
               max(p[1] for p in pts) - min(p[1] for p in pts), 1e-300)


def cluster(items, tol, dth):
    """Groups items (theta, rho, ...) whose (theta, rho) bins touch; theta wraps at pi."""
    parent = {}

    def find(k):
        while parent[k] != k:
            parent[k] = parent[parent[k]]
            k = parent[k]
        return k

    nth = int(round(math.pi / dth))
    keys = []
    for it in items:
        k = (int(round(it[0] / dth)) % nth, int(round(it[1] / tol)))
        keys.append(k)
        parent.setdefault(k, k)
    for k in list(parent):
        for i in (-1, 0, 1):
            for j in (-1, 0, 1):
                kt, kr = k[0] + i, k[1] + j
                if kt < 0 or kt >= nth:      # across the wrap the line's rho changes sign
                    kt %= nth
                    kr = -kr
                if (kt, kr) in parent:
                    r1, r2 = find(k), find((kt, kr))
                    if r1 != r2:
                        parent[r1] = r2
    groups = defaultdict(list)
    for k, it in zip(keys, items):
        groups[find(k)].append(it)
    return groups.values()


def merge(iv):
    out = []
    for t0, t1 in sorted(iv):
        if out and t0 <= out[-1][1]:
            out[-1][1] = max(out[-1][1], t1)
        else:
            out.append([t0, t1])
    return out


def minus(a, b):
    """The intervals of a (sorted, disjoint) minus b (sorted, disjoint)."""
    out, j = [], 0
    for t0, t1 in a:
        while j < len(b) and b[j][1] <= t0:
            j += 1
        k, s = j, t0
        while k < len(b) and b[k][0] < t1:
            if b[k][0] > s:
                out.append((s, b[k][0]))
            s = max(s, b[k][1])
            k += 1
        if s < t1:
            out.append((s, t1))
    return out


def drawn(segs, tol, dth):
    """Raw visible/hidden sums, and the drawn pieces: visible union, hidden union minus it."""
    raw = [0.0, 0.0]
    items = []
    for a, b, vis in segs:
        dx, dy = b[0] - a[0], b[1] - a[1]
        L = math.hypot(dx, dy)
        if L <= tol * 1e-3:
            continue
        raw[0 if vis else 1] += L
        th = math.atan2(dy, dx) % math.pi
        rho = -math.sin(th) * a[0] + math.cos(th) * a[1]
        if th >= math.pi - dth / 2:      # the bin of theta = pi is the bin of 0, with -rho
            th, rho = th - math.pi, -rho
        items.append((th, rho, a, b, vis))
    V, H = [], []
    for its in cluster(items, tol, dth):
        th0, rho0 = its[0][0], its[0][1]
        ux, uy = math.cos(th0), math.sin(th0)
        nx, ny = -uy, ux
        iv, ih = [], []
        for th, rho, a, b, vis in its:
            (iv if vis else ih).append(tuple(sorted((a[0] * ux + a[1] * uy,
                                                     b[0] * ux + b[1] * uy))))
        mv = merge(iv)
        pt = lambda s: (s * ux + rho0 * nx, s * uy + rho0 * ny)
        V += [(pt(t0), pt(t1)) for t0, t1 in mv]
        H += [(pt(t0), pt(t1)) for t0, t1 in minus(merge(ih), mv)]
    return raw, V, H


def length(pieces):
    return sum(math.dist(a, b) for a, b in pieces)


def unmatched(pieces, others, dist, step, cell):
    """The parts of pieces (sampled every step) farther than dist (< cell) from all of others."""
    grid = defaultdict(set)
    for a, b in others:
        # every cell within one cell of the segment (walked in half-cell steps)
        n = max(1, int(math.ceil(2 * math.dist(a, b) / cell)))
        for k in range(n + 1):
            x = a[0] + (b[0] - a[0]) * k / n
            y = a[1] + (b[1] - a[1]) * k / n
            i, j = int(math.floor(x / cell)), int(math.floor(y / cell))
            for di in (-1, 0, 1):
                for dj in (-1, 0, 1):
                    grid[(i + di, j + dj)].add((a, b))

    def near(p):
        for a, b in grid.get((int(math.floor(p[0] / cell)), int(math.floor(p[1] / cell))), ()):
            dx, dy = b[0] - a[0], b[1] - a[1]
            L2 = dx * dx + dy * dy
            t = 0.0 if L2 == 0 else max(0.0, min(1.0, ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / L2))
            if math.hypot(a[0] + t * dx - p[0], a[1] + t * dy - p[1]) <= dist:
                return True
        return False

    out = []
    for a, b in pieces:
        L = math.dist(a, b)
        n = max(1, int(math.ceil(L / step)))
        run = None
        for k in range(n):
            s0, s1 = k / n, (k + 1) / n
            sm = (s0 + s1) / 2
            p = (a[0] + sm * (b[0] - a[0]), a[1] + sm * (b[1] - a[1]))
            if near(p):
                if run is not None:
                    out.append(run)
                    run = None
            else:
                q0 = (a[0] + s0 * (b[0] - a[0]), a[1] + s0 * (b[1] - a[1]))
                q1 = (a[0] + s1 * (b[0] - a[0]), a[1] + s1 * (b[1] - a[1]))
                run = (run[0], q1) if run is not None else (q0, q1)
        if run is not None:
            out.append(run)
    return out


def write_diff_svg(path, segs_h, only, title, size=900.0, margin=20.0):
    pts = [p for sg in segs_h for p in sg[:2]] or [(0, 0), (1, 1)]
    umin = min(p[0] for p in pts); umax = max(p[0] for p in pts)
    vmin = min(p[1] for p in pts); vmax = max(p[1] for p in pts)
    sc = (size - 2 * margin) / max(umax - umin, vmax - vmin, 1e-300)
    W, H = (umax - umin) * sc + 2 * margin, (vmax - vmin) * sc + 2 * margin + 20

    def xy(p):
        return "%.2f,%.2f" % ((p[0] - umin) * sc + margin, (vmax - p[1]) * sc + margin + 20)

    def lines(segs, style):
        return "".join('<polyline %s points="%s %s"/>\n' % (style, xy(a), xy(b)) for a, b in segs)

    with open(path, "w") as f:
        f.write('<svg xmlns="http://www.w3.org/2000/svg" width="%.0f" height="%.0f">\n' % (W, H))
        f.write('<rect width="100%" height="100%" fill="white"/>\n')
        f.write('<text x="5" y="15" font-size="13">%s</text>\n' % title)
        f.write(lines([(a, b) for a, b, v in segs_h if not v],
                      'fill="none" stroke="#bbb" stroke-width="0.5" stroke-dasharray="3,2"'))
        f.write(lines([(a, b) for a, b, v in segs_h if v],
                      'fill="none" stroke="#777" stroke-width="0.7"'))
        for t, col in ((0, "#1060ff"), (1, "#e02020")):
            f.write(lines(only["hid"][t], 'fill="none" stroke="%s" stroke-width="2.5" '
                                          'stroke-dasharray="5,3" opacity="0.8"' % col))
            f.write(lines(only["vis"][t], 'fill="none" stroke="%s" stroke-width="3" '
                                          'opacity="0.7"' % col))
        f.write("</svg>\n")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("keep")
    ap.add_argument("-o", "--out", default="")
    ap.add_argument("--tol", type=float, default=1e-5, help="coincidence, relative to the extent")
    ap.add_argument("--match", type=float, default=1e-4,
                    help="distance under which a piece counts as drawn by both tools, relative "
                         "to the extent")
    ap.add_argument("--check-tol", type=float, default=1e-12, help="for the hlr_*_check columns")
    ap.add_argument("--diff", default="", help="folder for the <mesh>_<view>_diff.svg files")
    args = ap.parse_args()
    cols = ["mesh", "view", "la_source", "hlr_vis_raw", "hlr_hid_raw", "hlr_vis", "hlr_hid",
            "hlr_vis_check", "hlr_hid_check", "la_vis_raw", "la_hid_raw", "la_vis", "la_hid",
            "vis_ratio", "hid_ratio", "vis_hlr_only", "vis_la_only", "hid_hlr_only",
            "hid_la_only"]
    rows = []
    if args.diff:
        os.makedirs(args.diff, exist_ok=True)
    nan = float("nan")
    for hp in sorted(glob.glob(os.path.join(args.keep, "hlr_*.json"))):
        mesh, view = os.path.basename(hp)[4:-5].rsplit("_", 1)
        base = os.path.join(args.keep, "peer", "%s_%s" % (mesh, view))
        hs, stats, m = hlr_segments(hp)
        ext = extent_of(hs)
        _, cV, cH = drawn(hs, args.check_tol * ext, args.check_tol * 10)
        tol, dth = args.tol * ext, args.tol * 10
        hraw, hV, hH = drawn(hs, tol, dth)
        row = [mesh, view]
        if os.path.exists(base + ".json"):
            to_hlr, A = peer_to_hlr(base + ".json", m)
            if max(abs(A[0][0] - 1), abs(A[0][1]), abs(A[1][0]), abs(A[1][1] - 1)) > 1e-6:
                print("%s %s: the peer's view frame differs from hlr's: %s" % (mesh, view, A),
                      file=sys.stderr)
            if os.path.exists(base + ".strokes.json"):
                src, ls = "strokes", strokes_segments(base + ".strokes.json")
            else:
                src, ls = "svg", svg_segments(base + ".svg")
            ls = [(to_hlr(a), to_hlr(b), v) for a, b, v in ls]
            lraw, lV, lH = drawn(ls, tol, dth)
            g = (args.match * ext, ext / 20000, ext / 500)     # distance, sampling step, cell
            only = {"vis": [unmatched(hV, lV, *g), unmatched(lV, hV, *g)],
                    "hid": [unmatched(hH, lH, *g), unmatched(lH, hH, *g)]}
            lv, lh = length(lV), length(lH)
            la = [lraw[0], lraw[1], lv, lh, length(hV) / lv if lv else nan,
                  length(hH) / lh if lh else nan] + \
                 [length(only[k][t]) for k in ("vis", "hid") for t in (0, 1)]
            if args.diff:
                write_diff_svg(os.path.join(args.diff, "%s_%s_diff.svg" % (mesh, view)), hs, only,
                               "%s %s: blue = hlr only, red = Line Art only; solid visible, "
                               "dashed hidden" % (mesh, view))
        else:
            src, la = "none", [nan] * 10
        rows.append(row + [src, hraw[0], hraw[1], length(hV), length(hH),
                           length(cV) - stats["drawn_visible_length"],
                           length(cH) - stats["drawn_hidden_length"]] + la)
    fmt = lambda x: x if isinstance(x, str) else "%.6g" % x
    print(",".join(cols))
    for r in rows:
        print(",".join(map(fmt, r)))
    if args.out:
        with open(args.out, "w", newline="") as f:
            w = csv.writer(f)
            w.writerow(cols)
            w.writerows([list(map(fmt, r)) for r in rows])


if __name__ == "__main__":
    sys.exit(main())
