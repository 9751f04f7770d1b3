#!/usr/bin/env python3
"""The examples (examples/) call the library's entry points; what they make must be what the hlr
program makes for the same job: the same SVG bytes, the same hlr-surfaces/1 document apart from
its timings, and the clipper's exact area identity.

usage: check_examples.py HLR DRAW_PART SOLVE_SURFACES CLIP_SQUARES FIXTURES WORK
"""
import json
from fractions import Fraction
import pathlib
import subprocess
import sys


def run(*args, **kwargs):
    return subprocess.run([str(a) for a in args], check=True, capture_output=True, **kwargs)


def without_stats(document):
    document = dict(document)
    document.pop("stats", None)
    return document


def main():
    hlr, draw_part, solve_surfaces, clip_squares, fixtures, work = sys.argv[1:7]
    fixtures, work = pathlib.Path(fixtures), pathlib.Path(work)
    work.mkdir(parents=True, exist_ok=True)
    failures = []
    cases = [(fixtures / "parts" / "anchor.off", "iso"), (fixtures / "scenes" / "l_bracket.off", "front")]
    for mesh, view in cases:
        library, cli = work / f"{mesh.stem}_{view}_library.svg", work / f"{mesh.stem}_{view}_cli.svg"
        run(draw_part, mesh, library, view)
        run(hlr, "draw", mesh, "--view", view, "-o", cli)
        if library.read_bytes() != cli.read_bytes():
            failures.append(f"draw_part {mesh.name} {view}: SVG differs from hlr draw's")

        surfaces = json.loads(run(solve_surfaces, mesh, view).stdout)
        cli_json = work / f"{mesh.stem}_{view}_cli.json"
        run(hlr, "surfaces", mesh, "--view", view, "-o", cli_json)
        if without_stats(surfaces) != without_stats(json.loads(cli_json.read_text())):
            failures.append(f"solve_surfaces {mesh.name} {view}: document differs from hlr surfaces'")

    # A 4 x 4 square with a unit hole at x in [1, 2], clipped by x >= 2, y >= 0.1 (the double
    # nearest 0.1): inside 2 (4 - 0.1), outside the rest of 15, as exact rationals.
    line = run(clip_squares).stdout.decode().strip()
    areas = line.split("areas ")[1].split(" (")[0].replace("+", " ").replace("=", " ").split()
    inside, outside, subject = (Fraction(a) for a in areas)
    if inside != 2 * (4 - Fraction(0.1)) or subject != 15 or inside + outside != subject:
        failures.append(f"clip_squares: {line}")
    for failure in failures:
        print(failure)
    print(f"examples_match_cli: {len(cases)} drawings and surface documents, one clip: "
          f"{'all equal' if not failures else str(len(failures)) + ' differ'}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
