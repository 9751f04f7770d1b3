#!/usr/bin/env python3
"""The scaling chart (issue 12, goal 2) from a CSV of bench/scaling/run.sh.

usage:
    chart.py RESULTS.csv [--images PATH_WITHOUT_EXTENSION=docs/images/scaling] [--label TEXT]

Writes PATH.svg and PATH.png: on the left, seconds against input faces, log-log, for hlr draw
(exact), Blender's Line Art and OCC's PolyAlgo, with a dashed line of slope 1 ("linear") through
hlr's smallest assembly and the goal (1M faces in 10 s) as a star; on the right, microseconds
per face, with hlr's goal band (within 2x of its figure at the smallest assembly). OCC is drawn
twice: PolyAlgo alone (occ_s, solid) and with the B-rep build it needs first (occ_build_s +
occ_s, dotted); its time limit covers both, so a timed-out OCC run is an x at the limit on the
dotted series ("> 300 s"), as is a timed-out hlr run on hlr's. OCC runs skipped after a timeout
are not drawn. One series per tool and view (the view is named when the CSV has more than one).
The SVG carries no date and fixed ids, so the same CSV gives the same file.

needs: python3-matplotlib (apt-get install -y python3-matplotlib)
"""
import argparse
import csv
import os

import matplotlib

matplotlib.use("Agg")
matplotlib.rcParams["svg.hashsalt"] = "hlr-scaling"   # fixed ids: the same CSV, the same SVG
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib import ticker  # noqa: E402

TOOLS = [  # label, time column(s) summed, status column, timeout column, colour, marker, style
    ("hlr draw (exact)", ["hlr_s"], "hlr_status", "hlr_timeout_s", "tab:blue", "o", "-"),
    ("Blender Line Art", ["lineart_s"], None, None, "tab:orange", "s", "-"),
    ("OCC PolyAlgo", ["occ_s"], None, None, "tab:green", "^", "-"),
    ("OCC B-rep build + PolyAlgo", ["occ_build_s", "occ_s"], "occ_s", "occ_timeout_s",
     "tab:green", "^", ":"),
]


def num(text):
    try:
        return float(text)
    except (TypeError, ValueError):
        return None


def series(rows, cols, status_col, timeout_col):
    """(faces, seconds summed over cols) of finished runs and (faces, limit) of timed-out ones."""
    done, timed_out = [], []
    for r in rows:
        faces = num(r["faces"])
        parts = [num(r.get(c)) for c in cols]
        if faces is None:
            continue
        if all(p is not None for p in parts):
            done.append((faces, sum(parts)))
        elif status_col and r.get(status_col) == "timeout" and num(r.get(timeout_col)):
            timed_out.append((faces, num(r[timeout_col])))
    return sorted(done), sorted(timed_out)


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("csv")
    ap.add_argument("--images", default=os.path.join(here, "..", "..", "docs", "images", "scaling"))
    ap.add_argument("--label", default="")
    a = ap.parse_args()

    rows = list(csv.DictReader(open(a.csv)))
    views = sorted({r["view"] for r in rows})
    fig, (ax, ax2) = plt.subplots(1, 2, figsize=(11, 5.4))
    for view in views:
        vrows = [r for r in rows if r["view"] == view]
        suffix = (", %s" % view) if len(views) > 1 else ""
        for label, cols, status_col, timeout_col, colour, marker, style in TOOLS:
            done, timed_out = series(vrows, cols, status_col, timeout_col)
            fill = "none" if style != "-" else colour
            if done:
                xs, secs = zip(*done)
                us = [1e6 * y / x for x, y in done]
                for axis, ys in ((ax, secs), (ax2, us)):
                    axis.plot(xs, ys, marker=marker, markerfacecolor=fill, color=colour,
                              linestyle=style, label=label + suffix if axis is ax else None)
            for x, limit in timed_out:
                for axis, y in ((ax, limit), (ax2, 1e6 * limit / x)):
                    axis.plot([x], [y], marker="x", color=colour, markersize=8, linestyle="none",
                              label="%s: over %g s (timeout)%s" % (label, limit, suffix)
                              if axis is ax else None)
                    axis.annotate("> %g s" % limit, xy=(x, y), xytext=(-40, -13),
                                  textcoords="offset points", fontsize=7.5, color=colour)
        hlr_done, _ = series(vrows, ["hlr_s"], "hlr_status", "hlr_timeout_s")
        if hlr_done:
            x0, y0 = hlr_done[0]
            xmax = max(num(r["faces"]) for r in vrows)
            ax.plot([x0, xmax], [y0, y0 * xmax / x0], linestyle="--", color="grey", linewidth=1,
                    label="linear (from hlr at %s faces)%s" % (format(int(x0), ","), suffix))
            us0 = 1e6 * y0 / x0
            ax2.axhspan(us0, 2 * us0, color="tab:blue", alpha=0.08,
                        label="hlr goal: within 2x of %s faces%s" % (format(int(x0), ","), suffix))
    ax.plot([1e6], [10.0], marker="*", markersize=13, color="tab:red", linestyle="none",
            label="goal: 1M faces in 10 s")
    for axis in (ax, ax2):
        axis.set_xscale("log")
        axis.set_yscale("log")
        axis.yaxis.set_major_locator(ticker.LogLocator(subs=(1.0, 2.0, 5.0)))
        axis.yaxis.set_major_formatter(ticker.FuncFormatter(lambda v, _: "%g" % v))
        axis.yaxis.set_minor_formatter(ticker.NullFormatter())
        axis.set_xlabel("input faces (assembly)")
        axis.grid(True, which="both", alpha=0.3)
    ax.set_ylabel("seconds (1 view)")
    ax2.set_ylabel("microseconds per face")
    ax.set_title("time against faces")
    ax2.set_title("time per face")
    handles, labels = [], []
    for axis in (ax, ax2):
        h, l = axis.get_legend_handles_labels()
        handles += h
        labels += l
    fig.legend(handles, labels, loc="lower center", ncol=3, fontsize=8, frameon=False)
    if a.label:
        fig.suptitle(a.label, fontsize=10)
    fig.tight_layout(rect=(0, 0.17, 1, 1))
    os.makedirs(os.path.dirname(os.path.abspath(a.images)), exist_ok=True)
    for ext in ("svg", "png"):
        fig.savefig("%s.%s" % (a.images, ext), dpi=110,
                    metadata={"Date": None} if ext == "svg" else None)
        print("wrote %s.%s" % (os.path.normpath(a.images), ext))


if __name__ == "__main__":
    main()
