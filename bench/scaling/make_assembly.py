#!/usr/bin/env python3
"""Builds one OFF assembly of about N faces from the shared scene meshes, for bench/scaling/run.sh.

usage:
    make_assembly.py N -o OUT.off [--seed S=1] [--scenes DIR=../shared/scenes]
                     [--meshes fandisk,refined_elephant,...] [--spacing F=0.625]

N is a face count (10000, 10k, 1M, 1.5M). The assembly is copies of the meshes placed on a 3D
grid, overlapping each other in every view, written as one OFF file (one part for hlr, one object
for Line Art and OCC). The same N, seed and meshes always give the same file, byte for byte.

Which meshes: copies are added one by one, each of the mesh whose face total would then be the
smallest (water-filling: every mesh gets about the same share of the faces), among the meshes
that bring the face count closer to N than it is without them, until none does. A small N can
take only the small meshes: refined_elephant (89k faces) comes in from about 600k faces on. The
counts per mesh are printed, and saved beside the OFF file as OUT.off.txt with the other
figures below. The seed decides ties and every copy's turn, scale, grid cell and jitter.

Exact moves only. Each source mesh is first brought to a size of about 1 by a power-of-two scale
and its coordinates rounded ONCE to multiples of 2^-40 (a change of at most 2^-41, about 5e-13
of the part's size: the raw doubles of a mesh cannot all be translated exactly, since a sum of
two doubles of different exponents rounds). From then on every coordinate is an integer number
of units u = 2^-42 (int64), and each copy is moved by integer operations only:
  - a quarter-turn rotation: one of the 24 proper rotations of the cube (signed permutations of
    x, y, z with determinant +1: no reflection, so faces keep their winding and the copy stays
    outward oriented),
  - a scale 1/2, 1 or 2 (weights 1:2:1),
  - a translation: its bounding-box centre onto its grid cell (spacing F of the nominal part
    size, default 0.625 = 5/8, smaller than the parts so that neighbours interpenetrate) plus a
    jitter of up to 0.1 part sizes per axis in multiples of 2^-20.
The output coordinates are integer * 2^-42 with |integer| < 2^53, so each is a double exactly,
and the file prints them with repr (shortest text that reads back as the same double): the
numbers hlr reads are exactly the ones computed here (checked before writing). The script also
checks that no vertex of one copy lands exactly on a vertex of another (hlr would weld them:
the jitter of such a copy is drawn again) and reports, per view (front, top, right, iso), the
share of copies whose screen bounding box overlaps another copy's.

needs: python3-numpy (apt-get install -y python3-numpy)
"""
import argparse
import itertools
import math
import os
import random
import re
import sys

import numpy as np

SNAP_BITS = 40          # source coordinates rounded to multiples of 2^-SNAP_BITS (part size ~1)
UNIT_BITS = 42          # output unit u = 2^-UNIT_BITS: scales 1/2, 1, 2 are 2, 4, 8 snap units
JITTER_BITS = 20        # jitter in multiples of 2^-JITTER_BITS
JITTER_MAX = 0.1        # jitter up to this many part sizes per axis
DEFAULT_MESHES = "fandisk,refined_elephant,elephant,couplingdown,rotor,pinion,anchor"
SCALES = ((2, 1), (4, 2), (8, 1))   # (multiplier of the snapped integers, weight): 1/2, 1, 2
VIEWS = {  # direction from the scene to the viewer, as DESIGN.md's named views
    "front": (0, -1, 0), "top": (0, 0, 1), "right": (1, 0, 0), "iso": (1, -1, 1)}


def parse_count(text):
    m = re.fullmatch(r"([0-9]*\.?[0-9]+)([kKmM]?)", text)
    if not m:
        raise argparse.ArgumentTypeError("not a face count: %r" % text)
    return int(round(float(m.group(1)) * {"": 1, "k": 1e3, "m": 1e6}[m.group(2).lower()]))


def read_off(path):
    """Vertices (float64, parsed by Python's correctly rounded float()) and faces (int array)."""
    with open(path) as f:
        toks = [ln.split("#", 1)[0].split() for ln in f]
    toks = [t for t in toks if t]
    if not toks[0][0].upper().endswith("OFF"):
        sys.exit("%s: not an OFF file" % path)
    counts, k = (toks[0][1:], 1) if len(toks[0]) >= 3 else (toks[1], 2)
    nv, nf = int(counts[0]), int(counts[1])
    verts = np.array([[float(x) for x in t[:3]] for t in toks[k:k + nv]], dtype=np.float64)
    faces = [[int(x) for x in t[1:1 + int(t[0])]] for t in toks[k + nv:k + nv + nf]]
    if len(verts) != nv or len(faces) != nf:
        sys.exit("%s: OFF counts do not match the file" % path)
    if len({len(fc) for fc in faces}) != 1:
        sys.exit("%s: faces of different sizes (only one face size per mesh is supported)" % path)
    return verts, np.array(faces, dtype=np.int64)


class Source:
    """A scene mesh brought to size ~1 by 2^k and snapped: integer coordinates in 2^-SNAP_BITS."""

    def __init__(self, name, path):
        self.name = name
        verts, self.faces = read_off(path)
        extent = float((verts.max(0) - verts.min(0)).max())
        self.pow2 = -int(round(math.log2(extent)))
        scaled = verts * 2.0 ** self.pow2                  # exact (power of two, no underflow)
        q = scaled * 2.0 ** SNAP_BITS                      # exact
        self.ints = np.rint(q).astype(np.int64)            # the one rounding
        self.snapped = int(np.count_nonzero(q != self.ints))
        self.coords = verts.size
        if len(np.unique(self.ints, axis=0)) != len(np.unique(verts, axis=0)):
            sys.exit("%s: rounding to 2^-%d merged vertices" % (name, SNAP_BITS))
        self.nfaces = len(self.faces)


def rotations():
    """The 24 proper rotations of the cube as signed permutation matrices (integer)."""
    out = []
    for perm in itertools.permutations(range(3)):
        for signs in itertools.product((1, -1), repeat=3):
            m = np.zeros((3, 3), dtype=np.int64)
            for row, (col, s) in enumerate(zip(perm, signs)):
                m[row, col] = s
            if round(np.linalg.det(m)) == 1:
                out.append(m)
    assert len(out) == 24
    return out


def choose(sources, target, rng):
    """Water-filling: each copy is of the mesh that leaves the largest per-mesh face total
    smallest (ties: the seeded generator), among the meshes that still fit in what is left of
    the target: whose faces bring the assembly closer to the target than it is without them."""
    picks, left = [], target
    total = {s.name: 0 for s in sources}
    while True:
        fit = [s for s in sources if s.nfaces < 2 * left]
        if not fit:
            return picks
        best = min(total[s.name] + s.nfaces for s in fit)
        s = rng.choice([s for s in fit if total[s.name] + s.nfaces == best])
        picks.append(s)
        total[s.name] += s.nfaces
        left -= s.nfaces


def grid_dims(n):
    a = max(1, math.ceil(round(n ** (1 / 3), 9)))
    b = max(1, math.ceil(math.sqrt(n / a)))
    c = max(1, math.ceil(n / (a * b)))
    return a, b, c


def screen_overlap(boxes, direction):
    """Share of copies whose projected bounding box overlaps another copy's (floating point:
    a report, not part of the geometry)."""
    d = np.array(direction, dtype=float)
    d /= np.linalg.norm(d)
    helper = np.array([0.0, 0.0, 1.0]) if abs(d[2]) < 0.9 else np.array([0.0, 1.0, 0.0])
    r = np.cross(helper, d)
    r /= np.linalg.norm(r)
    u = np.cross(d, r)
    lo, hi = [], []
    for bmin, bmax in boxes:
        corners = np.array(list(itertools.product(*zip(bmin, bmax))), dtype=float)
        p = np.stack([corners @ r, corners @ u], axis=1)
        lo.append(p.min(0))
        hi.append(p.max(0))
    lo, hi = np.array(lo), np.array(hi)
    n = len(boxes)
    if n < 2:
        return 0.0
    ov = np.all((lo[:, None, :] < hi[None, :, :]) & (lo[None, :, :] < hi[:, None, :]), axis=2)
    np.fill_diagonal(ov, False)
    return float(np.count_nonzero(ov.any(1))) / n


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("target", type=parse_count, help="face count, e.g. 10k, 100k, 1M")
    ap.add_argument("-o", "--out", required=True)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--scenes", default=os.path.join(here, "..", "..", "..", "shared", "scenes"))
    ap.add_argument("--meshes", default=DEFAULT_MESHES, help="comma list of mesh names")
    ap.add_argument("--spacing", type=float, default=0.625,
                    help="grid spacing in part sizes (a multiple of 2^-10)")
    a = ap.parse_args()

    rng = random.Random(a.seed)
    sources = [Source(n, os.path.join(a.scenes, n + ".off")) for n in a.meshes.split(",")]
    picks = choose(sources, a.target, rng)
    if not picks:
        sys.exit("no mesh has at most %d faces" % a.target)
    dims = grid_dims(len(picks))
    cells = list(itertools.product(*(range(d) for d in dims)))
    rng.shuffle(cells)
    rots = rotations()
    step = int(round(a.spacing * 1024)) << (UNIT_BITS - 10)  # exact: spacing is k / 1024
    jit_unit = 1 << (UNIT_BITS - JITTER_BITS)
    jit_max = int(JITTER_MAX * (1 << JITTER_BITS))
    centre = [(d - 1) * step // 2 for d in dims]            # step is even: exact

    copies = []   # (source, rotated+scaled+centred integer vertices, cell)
    for s, cell in zip(picks, cells):
        rot = rots[rng.randrange(24)]
        mult = rng.choices([m for m, _ in SCALES], weights=[w for _, w in SCALES])[0]
        v = (s.ints @ rot.T) * mult
        v -= (v.min(0) + v.max(0)) // 2
        v += np.array([cell[i] * step - centre[i] for i in range(3)], dtype=np.int64)
        copies.append([s, v, np.zeros(3, dtype=np.int64)])

    def draw_jitter():
        return np.array([rng.randint(-jit_max, jit_max) * jit_unit for _ in range(3)], dtype=np.int64)

    for c in copies:
        c[2] = draw_jitter()
    redrawn = 0
    for _ in range(50):   # no vertex of one copy exactly on a vertex of another
        allv = np.concatenate([v + j for _, v, j in copies])
        owner = np.concatenate([np.full(len(v), i) for i, (_, v, _) in enumerate(copies)])
        _, inv, cnt = np.unique(allv, axis=0, return_inverse=True, return_counts=True)
        inv = inv.reshape(-1)
        shared = cnt[inv] > 1
        if not shared.any():
            break
        # per welded point, the copies touching it; re-draw all but the first copy of each
        bad = set()
        for key in np.unique(inv[shared]):
            owners = sorted(set(owner[inv == key].tolist()))
            if len(owners) > 1:
                bad.update(owners[1:])
        if not bad:
            break   # only duplicates inside one copy (as in its source mesh): fine
        for i in sorted(bad):
            copies[i][2] = draw_jitter()
            redrawn += 1
    else:
        sys.exit("could not place the copies without shared vertices")

    verts = np.concatenate([v + j for _, v, j in copies])
    if np.abs(verts).max() >= 1 << 53:
        sys.exit("coordinates too large for exact doubles")
    out = verts.astype(np.float64) * 2.0 ** -UNIT_BITS     # exact: |int| < 2^53, times 2^-42
    assert np.array_equal((out * 2.0 ** UNIT_BITS).astype(np.int64), verts)
    faces, base = [], 0
    for s, v, _ in copies:
        faces.append(s.faces + base)
        base += len(v)
    faces = np.concatenate(faces)
    k = faces.shape[1]

    tmp = a.out + ".tmp"
    with open(tmp, "w") as f:
        f.write("OFF\n%d %d 0\n" % (len(out), len(faces)))
        f.write("".join("%r %r %r\n" % tuple(p) for p in out.tolist()))
        f.write("".join(("%d" % k) + (" %d" * k) % tuple(fc) + "\n" for fc in faces.tolist()))
    # read back what was written: every coordinate text is the computed double exactly
    with open(tmp) as f:
        f.readline(), f.readline()
        back = np.array([[float(x) for x in f.readline().split()] for _ in range(len(out))])
    assert np.array_equal(back, out), "printed coordinates do not read back exactly"
    os.replace(tmp, a.out)

    boxes = [((v + j).min(0) * 2.0 ** -UNIT_BITS, (v + j).max(0) * 2.0 ** -UNIT_BITS)
             for _, v, j in copies]
    counts = {}
    for s in picks:
        counts[s.name] = counts.get(s.name, 0) + 1
    lines = [
        "assembly %s: %d faces (target %d), %d vertices, %d copies on a %dx%dx%d grid, seed %d"
        % (os.path.basename(a.out), len(faces), a.target, len(out), len(picks), *dims, a.seed),
        "copies: " + ", ".join("%s %d (%d faces)" % (n, c, c * next(s.nfaces for s in sources if s.name == n))
                               for n, c in sorted(counts.items())),
        "snapped to 2^-%d: %s" % (SNAP_BITS, ", ".join(
            "%s %.0f%% of coordinates" % (s.name, 100.0 * s.snapped / s.coords) for s in sources)),
        "extent: %s (part size 1, spacing %g); jitter re-drawn %d times (shared vertices)"
        % (" x ".join("%.3f" % e for e in (out.max(0) - out.min(0))), a.spacing, redrawn),
        "copies overlapping another in screen: " + ", ".join(
            "%s %.0f%%" % (vn, 100 * screen_overlap(boxes, d)) for vn, d in VIEWS.items()),
    ]
    with open(a.out + ".txt", "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
