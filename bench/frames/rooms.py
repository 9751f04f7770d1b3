#!/usr/bin/env python3
"""Lim's room models for the fuzzy culling benchmark (seeds/000, section 10, figure 5).

N rooms (1 to 4) in a row along +Y, each 10 x 8 x 3 m, joined by doorways (1 x 2.2 m, at
alternating sides, so that they do not line up), furnished with boxes (tables, cabinets) and
cylinders (columns, stools). Walls, floors and ceilings are open sheets subdivided into square
patches (--cell), as Lim's surfaces are subdivided; furniture is closed and outward.
Writes ROOMS.off and, beside it, ROOMS.eyes.txt: five eyes in a 0.4 m box in the first room, and
prints the target they look at.

  rooms.py 3 out/rooms3.off [--cell 0.25] [--segments 24] [--seed 1]
"""
import argparse
import math
import random

W, L, H = 10.0, 8.0, 3.0  # room width (x), length (y), height (z)
DOOR_W, DOOR_H = 1.0, 2.2


class Off:
    def __init__(self):
        self.v, self.f = [], []

    def vertex(self, p):
        self.v.append(p)
        return len(self.v) - 1

    def sheet(self, origin, du, dv, nu, nv, hole=None, flip=False):
        """A grid of nu x nv quads over origin + i du + j dv; `hole` (i0, i1, j0, j1) is left out."""
        idx = {}
        for i in range(nu + 1):
            for j in range(nv + 1):
                idx[i, j] = self.vertex(tuple(origin[k] + i * du[k] + j * dv[k] for k in range(3)))
        for i in range(nu):
            for j in range(nv):
                if hole and hole[0] <= i < hole[1] and hole[2] <= j < hole[3]:
                    continue
                q = [idx[i, j], idx[i + 1, j], idx[i + 1, j + 1], idx[i, j + 1]]
                self.f.append(q[::-1] if flip else q)

    def box(self, lo, hi):
        o = len(self.v)
        for c in range(8):
            self.vertex(tuple(hi[k] if c >> k & 1 else lo[k] for k in range(3)))
        for q in ((0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)):
            self.f.append([o + c for c in q])

    def cylinder(self, centre, radius, z0, z1, n):
        bottom = [self.vertex((centre[0] + radius * math.cos(2 * math.pi * i / n),
                               centre[1] + radius * math.sin(2 * math.pi * i / n), z0)) for i in range(n)]
        top = [self.vertex((self.v[b][0], self.v[b][1], z1)) for b in bottom]
        self.f.append(bottom[::-1])
        self.f.append(top)
        for i in range(n):
            j = (i + 1) % n
            self.f.append([bottom[i], bottom[j], top[j], top[i]])

    def write(self, path):
        with open(path, "w") as out:
            out.write(f"OFF\n{len(self.v)} {len(self.f)} 0\n")
            for p in self.v:
                out.write("%.17g %.17g %.17g\n" % p)
            for f in self.f:
                out.write(f"{len(f)} " + " ".join(map(str, f)) + "\n")


def rooms(n, cell, segments, seed):
    rng = random.Random(seed)
    off = Off()
    nx, ny, nz = round(W / cell), round(L / cell), round(H / cell)
    dw, dh = round(DOOR_W / cell), round(DOOR_H / cell)
    for r in range(n):
        y0 = r * L
        off.sheet((0, y0, 0), (cell, 0, 0), (0, cell, 0), nx, ny)  # floor
        off.sheet((0, y0, H), (cell, 0, 0), (0, cell, 0), nx, ny)  # ceiling
        off.sheet((0, y0, 0), (0, cell, 0), (0, 0, cell), ny, nz)  # side walls
        off.sheet((W, y0, 0), (0, cell, 0), (0, 0, cell), ny, nz)
        if r == 0:
            off.sheet((0, 0, 0), (cell, 0, 0), (0, 0, cell), nx, nz)  # the first room's back wall
        # The far wall: a doorway into the next room, or none at the end.
        side = 0.2 if r % 2 == 0 else 0.7
        i0 = round(side * nx)
        hole = (i0, i0 + dw, 0, dh) if r + 1 < n else None
        off.sheet((0, y0 + L, 0), (cell, 0, 0), (0, 0, cell), nx, nz, hole)
        # Furniture: tables and cabinets, columns and stools.
        for _ in range(10):
            x, y = rng.uniform(0.5, W - 2), rng.uniform(y0 + 1.5, y0 + L - 1.5)
            sx, sy, sz = rng.uniform(0.4, 1.5), rng.uniform(0.4, 1.2), rng.uniform(0.4, 2.0)
            off.box((x, y, 0), (x + sx, y + sy, sz))
        for _ in range(8):
            x, y = rng.uniform(0.6, W - 0.6), rng.uniform(y0 + 1.5, y0 + L - 0.6)
            off.cylinder((x, y), rng.uniform(0.1, 0.35), 0, rng.uniform(0.5, H), segments)
    return off


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("rooms", type=int, choices=[1, 2, 3, 4])
    ap.add_argument("out")
    ap.add_argument("--cell", type=float, default=0.25, help="patch size of walls, floors and ceilings (m)")
    ap.add_argument("--segments", type=int, default=24, help="sides of a cylinder")
    ap.add_argument("--seed", type=int, default=1)
    a = ap.parse_args()
    off = rooms(a.rooms, a.cell, a.segments, a.seed)
    off.write(a.out)
    eyes = a.out[:-4] + ".eyes.txt" if a.out.endswith(".off") else a.out + ".eyes.txt"
    with open(eyes, "w") as out:
        out.write("# five eyes in a 0.4 m box in the first room, looking along +Y\n")
        for dx, dy, dz in ((0, 0, 0), (0.4, 0, 0), (0, 0.4, 0.2), (0.2, 0.2, 0.4), (0.4, 0.4, 0.1)):
            out.write(f"{4.8 + dx} {0.6 + dy} {1.5 + dz}\n")
    print(f"{len(off.f)} faces; eyes in {eyes}; target 5,8,1.5")


if __name__ == "__main__":
    main()
