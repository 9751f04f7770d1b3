#!/usr/bin/env python3
"""Shared by the bench/*/run.sh scripts (see bench/common.sh).

As a command:
    common.py stats HLR.json
prints hlr's "stats" object of one output JSON as one line. It adds "faces" from "input" when
the stats lack it, and for hlr-lines/1 (hlr draw) the 2D lengths of ALL pieces in "lines",
visible and hidden, before ISO 128 precedence (hidden pieces under visible ones, duplicates kept):
"bench_visible_length_all", "bench_hidden_length_all". The pieces' a/b are view coordinates
(x right, y up, z toward the viewer, model units; view.world_to_view maps the input to them), so
the 2D length is the (x, y) length: the frame of drawn_visible/hidden_length.

As a module (the run scripts' CSV step):
    load_hlr(rows_tsv) -> (order, {(mesh, view): {tag: best stats or None}})
        best = the run with the least stats.seconds among the HLR_REPEAT runs
    load_peer(work)    -> {(mesh, view): row of the peer's CSV}
    sec(stats)         -> "%.6f" of stats.seconds, or "failed"
"""
import csv
import glob
import json
import math
import os
import sys


def stats_line(path):
    with open(path) as f:
        d = json.load(f)
    st = dict(d["stats"])
    if "faces" not in st and "faces" in d.get("input", {}):
        st["faces"] = d["input"]["faces"]
    if d.get("format") == "hlr-lines/1":
        vis = hid = 0.0
        for ln in d["lines"]:
            a, b = ln["a"], ln["b"]
            length = math.hypot(b[0] - a[0], b[1] - a[1])
            if ln["visible"]:
                vis += length
            else:
                hid += length
        st["bench_visible_length_all"] = vis
        st["bench_hidden_length_all"] = hid
    return json.dumps(st)


def load_hlr(rows_tsv):
    hlr, order = {}, []
    for line in open(rows_tsv):
        mesh, view, tag, status, path = line.rstrip("\n").split("\t")
        key = (mesh, view)
        if key not in hlr:
            hlr[key] = {}
            order.append(key)
        runs = [json.loads(l) for l in open(path) if l.strip()] if status == "ok" else []
        hlr[key][tag] = min(runs, key=lambda st: st["seconds"]) if runs else None
    return order, hlr


def load_peer(work):
    peer = {}
    for p in glob.glob(os.path.join(work, "peer_*.csv")):
        for r in csv.DictReader(open(p)):
            peer[(r["mesh"], r["view"])] = r
    return peer


def sec(s):
    return "%.6f" % s["seconds"] if s else "failed"


if __name__ == "__main__":
    if len(sys.argv) == 3 and sys.argv[1] == "stats":
        print(stats_line(sys.argv[2]))
    else:
        sys.exit("usage: common.py stats HLR.json")
