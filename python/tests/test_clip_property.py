"""hlrdraw.clip against shapely on random polygons (Hypothesis).

Coordinates are small integers, so that the polygons share vertices, run along each other's edges
and meet at vertices: the degenerate cases an exact clipper must get right. Two checks:
  - exact: area(inside) + area(outside) = area(subject), in fractions.Fraction from the exact "p/q"
    vertices (exact=True), with the subject's area from its integer input;
  - against shapely (GEOS, floating point): the areas of subject ∩ clip and subject − clip, with a
    tolerance for shapely's rounding only (the exact areas are rounded once, to compare). Not
    piece by piece: GEOS misjudges rounded pieces along an edge (the @example below).
The examples are derandomised, so that the suite is the same on every run.
"""
import math
from fractions import Fraction

from hypothesis import HealthCheck, assume, example, given, settings
from hypothesis import strategies as st
from shapely.geometry import Polygon
from shapely.ops import unary_union

import hlrdraw

coordinate = st.integers(min_value=-6, max_value=6)


@st.composite
def simple_polygon(draw):
    """A simple polygon: integer points in angular order round their mean (a star-shaped
    polygon), kept when shapely calls it valid (no vertex repeated, no edge crossing)."""
    points = draw(st.lists(st.tuples(coordinate, coordinate), min_size=3, max_size=8, unique=True))
    cx = sum(p[0] for p in points) / len(points)
    cy = sum(p[1] for p in points) / len(points)
    points.sort(key=lambda p: math.atan2(p[1] - cy, p[0] - cx))
    polygon = Polygon(points)
    assume(polygon.is_valid and polygon.area > 0)
    return points


def exact_area(contour):
    """Signed area of a contour of exact "p/q" vertices."""
    points = [(Fraction(x), Fraction(y)) for x, y in contour]
    twice = sum(a[0] * b[1] - a[1] * b[0] for a, b in zip(points, points[1:] + points[:1]))
    return twice / 2


def piece_area(piece):
    area = exact_area(piece["outer_exact"])
    assert area > 0  # outer contours counter-clockwise
    for hole in piece.get("holes_exact", []):
        hole_area = exact_area(hole)
        assert hole_area < 0  # holes clockwise
        area += hole_area
    return area


# GEOS 3.11 (shapely 1.8) gets this one half wrong: the outside piece (5/11, 35/11), (1, 1), (1, 4),
# rounded, lies along the clip's edge from (1, 1) to (0, 5), and GEOS intersects it with the union
# of the clips as if it were all inside (area 0.818 instead of 0), though its totals are right. So
# the pieces are checked exactly here, and shapely is asked only for the total areas.
@example(subject=[(-1, 1), (1, 0), (1, 4)], clips=[[(0, 0), (1, 0), (0, 1)], [(0, 0), (1, 1), (0, 5)]])
@settings(max_examples=400, deadline=None, derandomize=True, database=None,
          suppress_health_check=[HealthCheck.filter_too_much, HealthCheck.too_slow])
@given(subject=simple_polygon(), clips=st.lists(simple_polygon(), min_size=1, max_size=2))
def test_clip_matches_shapely_and_keeps_the_exact_area_identity(subject, clips):
    result = hlrdraw.clip([subject], clips, exact=True)

    inside = sum((piece_area(p) for p in result["inside"]), Fraction(0))
    outside = sum((piece_area(p) for p in result["outside"]), Fraction(0))
    assert inside + outside == abs(exact_area(subject))
    stats = result["stats"]
    assert stats["area_identity"] is True
    assert (Fraction(stats["inside_area_exact"]), Fraction(stats["outside_area_exact"])) == (inside, outside)
    # Every output edge lies on the input edge it is tagged with, exactly.
    inputs = {"subject": [subject], "clip": clips}
    for piece in result["inside"] + result["outside"]:
        contour = [(Fraction(x), Fraction(y)) for x, y in piece["outer_exact"]]
        for k, (role, polygon, ring, edge) in enumerate(piece["outer_edges"]):
            assert ring == 0  # the inputs have no holes
            source = inputs[role][polygon]
            a, b = source[edge], source[(edge + 1) % len(source)]
            for p in (contour[k], contour[(k + 1) % len(contour)]):
                assert (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]) == 0

    shape = Polygon(subject)
    region = unary_union([Polygon(c) for c in clips])
    tolerance = 1e-9 * max(1.0, shape.area)
    assert abs(float(inside) - shape.intersection(region).area) <= tolerance
    assert abs(float(outside) - shape.difference(region).area) <= tolerance
