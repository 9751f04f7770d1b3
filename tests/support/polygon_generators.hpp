// Random polygon generators shared by the property tests and the benchmarks.
//
// Every generator is deterministic for a given rng state and returns a valid polygon with holes
// (simple contours, holes inside the outer contour and apart from each other; contours may touch
// at points only when snapped). Coordinates are plain doubles, so the same polygon can be fed to
// every kernel, to CGAL's Boolean operations and to Clipper1.
//
// Determinism: the generators draw only raw 64-bit words from the engine (no std::*_distribution,
// whose output differs between standard libraries), so a seed names the same polygon everywhere.
#pragma once

#include <array>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace hlr::testing {

using RawPoint = std::array<double, 2>;
using RawContour = std::vector<RawPoint>;

struct RawPolygon {
  RawContour outer;
  std::vector<RawContour> holes;
  std::size_t vertex_count() const;
};

using Rng = std::mt19937_64;

// Star-shaped around (cx, cy): `vertices` points at increasing angles, radii in [0.2, 1] * radius.
RawPolygon random_star(Rng& rng, int vertices, double radius, double cx = 0, double cy = 0);
// A comb: a spine with teeth, concave everywhere, about `vertices` points.
RawPolygon random_comb(Rng& rng, int vertices, double size, double cx = 0, double cy = 0);
// A thick spiral, about `vertices` points.
RawPolygon random_spiral(Rng& rng, int vertices, double size, double cx = 0, double cy = 0);
// Adds up to `holes` star-shaped holes of `hole_vertices` points, each inside the outer contour
// and apart from the others.
RawPolygon with_random_holes(Rng& rng, RawPolygon polygon, int holes, int hole_vertices);
// A polygon whose coordinates are integers in [0, grid]: coincident vertices, vertices on edges
// and collinear overlaps with another polygon on the same grid are frequent. Retries until valid.
RawPolygon random_grid_polygon(Rng& rng, int grid, int max_vertices, bool allow_holes);

// True when the polygon is valid in the sense above (checked exactly with CGAL).
bool is_valid(const RawPolygon& polygon);

// Twice the signed area, in double (positive counter-clockwise): for orienting, not for checking.
double twice_signed_area(const RawContour& c);

// ---- helpers (extensions used by the property tests and the stability run) ----

// Uniform draws from raw engine words (portable, see above).
double uniform01(Rng& rng);                           // [0, 1)
double uniform(Rng& rng, double lo, double hi);       // [lo, hi)
int uniform_int(Rng& rng, int lo, int hi);            // [lo, hi], inclusive

// Why the polygon is not valid (first defect found), or an empty string when it is. Exact.
std::string validity_defect(const RawPolygon& polygon);
// The same for a polygon known to be valid without its last hole: checks only that hole against
// the outer contour and the other holes (for adding holes one at a time).
std::string last_hole_defect(const RawPolygon& polygon);

// Geometric transforms, evaluated in double (rounded once per coordinate).
RawPolygon translated(const RawPolygon& p, double dx, double dy);
RawPolygon scaled(const RawPolygon& p, double factor, double cx = 0, double cy = 0);
RawPolygon rotated(const RawPolygon& p, double angle, double cx, double cy);
// Reverses every contour (same point set, other orientation).
RawPolygon reversed(const RawPolygon& p);
// Starts every contour at another vertex (same polygon, other numbering).
RawPolygon rotated_start(const RawPolygon& p, std::size_t shift);

struct RawBox {
  double xmin, ymin, xmax, ymax;
};
RawBox bounding_box(const RawPolygon& p);
RawContour box_contour(const RawBox& b);  // counter-clockwise rectangle
double max_abs_coordinate(const RawPolygon& p);
double perimeter(const RawPolygon& p);

// hlr-polygons/1 JSON (coordinates with 17 significant digits: they read back exactly).
std::string to_json(const std::vector<RawPolygon>& polygons);
// A C++ initializer ({{{x, y}, ...}, {{{x, y}, ...}}}) that can be pasted into a unit test;
// coordinates are printed as exact hexadecimal floating literals when they are not integers.
std::string to_cpp(const RawPolygon& p);

}  // namespace hlr::testing
