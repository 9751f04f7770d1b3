#!/usr/bin/env python3
"""The scaling chart (issue 12, goal 2) from a CSV of bench/scaling/run.sh.

usage:
    chart.py RESULTS.csv [--images PATH_WITHOUT_EXTENSION=docs/images/scaling] [--label TEXT]

Writes PATH.svg and PATH.png: on the left, seconds against input faces, log-log, for hlr draw
(exact), Blender's Line Art and OCC's PolyAlgo, with a dashed line of slope 1 ("linear") through
hlr's smallest assembly and the goal (1M faces in 10 s) as a star; on the right, microseconds
per face, with hlr's goal band (within 2x of its figure at the smallest assembly). A run that
timed out is drawn as an open marker at its time limit, with an arrow up (the time is longer);
OCC runs skipped after a timeout are not drawn. One series per tool and view (the view is named
when the CSV has more than one).

needs: python3-matplotlib (apt-get install -y python3-matplotlib)
"""
import argparse
import csv
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

TOOLS = [  # label, time column, status test, timeout column, colour, marker
    ("hlr draw (exact)", "hlr_s", "hlr_status", "hlr_timeout_s", "tab:blue", "o"),
    ("Blender Line Art", "lineart_s", None, None, "tab:orange", "s"),
    ("OCC HLRBRep_PolyAlgo", "occ_s", "occ_s", "occ_timeout_s", "tab:green", "^"),
]


def num(text):
    try:
        return float(text)
    except (TypeError, ValueError):
        return None


def series(rows, col, status_col, timeout_col):
    """(faces, seconds) of finished runs and (faces, limit) of timed-out ones."""
    done, timed_out = [], []
    for r in rows:
        faces = num(r["faces"])
        s = num(r[col])
        if faces is None:
            continue
        if s is not None:
            done.append((faces, s))
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
    fig, (ax, ax2) = plt.subplots(1, 2, figsize=(11, 4.6))
    for view in views:
        vrows = [r for r in rows if r["view"] == view]
        suffix = (", %s" % view) if len(views) > 1 else ""
        for label, col, status_col, timeout_col, colour, marker in TOOLS:
            done, timed_out = series(vrows, col, status_col, timeout_col)
            if done:
                xs, ys = zip(*done)
                ax.plot(xs, ys, marker=marker, color=colour, label=label + suffix)
                ax2.plot(xs, [1e6 * y / x for x, y in done], marker=marker, color=colour,
                         label=label + suffix)
            for x, limit in timed_out:
                ax.plot([x], [limit], marker=marker, color=colour, markerfacecolor="none",
                        linestyle="none", label="%s: timed out at %g s%s" % (label, limit, suffix))
                ax.annotate("", xy=(x, limit * 1.8), xytext=(x, limit),
                            arrowprops=dict(arrowstyle="->", color=colour))
                ax2.plot([x], [1e6 * limit / x], marker=marker, color=colour,
                         markerfacecolor="none", linestyle="none")
                ax2.annotate("", xy=(x, 1.8e6 * limit / x), xytext=(x, 1e6 * limit / x),
                             arrowprops=dict(arrowstyle="->", color=colour))
        hlr_done, _ = series(vrows, "hlr_s", "hlr_status", "hlr_timeout_s")
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
        axis.set_xlabel("input faces (assembly)")
        axis.grid(True, which="both", alpha=0.3)
    ax.set_ylabel("seconds (1 view)")
    ax2.set_ylabel("microseconds per face")
    ax.set_title("time against faces")
    ax2.set_title("time per face")
    ax.legend(fontsize=7.5, loc="upper left")
    ax2.legend(fontsize=7.5, loc="best")
    if a.label:
        fig.suptitle(a.label, fontsize=10)
    fig.tight_layout()
    os.makedirs(os.path.dirname(os.path.abspath(a.images)), exist_ok=True)
    for ext in ("svg", "png"):
        fig.savefig("%s.%s" % (a.images, ext), dpi=110)
        print("wrote %s.%s" % (a.images, ext))


if __name__ == "__main__":
    main()
