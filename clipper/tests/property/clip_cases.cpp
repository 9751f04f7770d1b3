#include "clip_cases.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace hlr::testing {

const char* shape_name(Shape s) {
  switch (s) {
    case Shape::star: return "star";
    case Shape::comb: return "comb";
    case Shape::spiral: return "spiral";
    case Shape::holes: return "holes";
    case Shape::grid: return "grid";
    case Shape::grid_holes: return "grid_holes";
  }
  return "?";
}

const char* relation_name(Relation r) {
  switch (r) {
    case Relation::independent: return "independent";
    case Relation::identity: return "identity";
    case Relation::shifted: return "shifted";
    case Relation::in_clip_hole: return "in_clip_hole";
    case Relation::subject_contour: return "subject_contour";
    case Relation::box_cut: return "box_cut";
  }
  return "?";
}

bool is_grid(Shape s) { return s == Shape::grid || s == Shape::grid_holes; }

RawPolygon make_shape(Shape shape, Rng& rng, int vertices, int holes, int grid) {
  // Float shapes: centred in [2, 6]^2, 3 to 8 across, so that they overlap each other and the grid.
  const double cx = uniform(rng, 2, 6), cy = uniform(rng, 2, 6), size = uniform(rng, 3, 8);
  switch (shape) {
    case Shape::star: return random_star(rng, vertices, size / 2, cx, cy);
    case Shape::comb: return random_comb(rng, vertices, size, cx, cy);
    case Shape::spiral: return random_spiral(rng, vertices, size, cx, cy);
    case Shape::holes: {
      RawPolygon base;
      switch (uniform_int(rng, 0, 2)) {
        case 0: base = random_star(rng, vertices, size / 2, cx, cy); break;
        case 1: base = random_comb(rng, vertices, size, cx, cy); break;
        default: base = random_spiral(rng, vertices, size, cx, cy); break;
      }
      return with_random_holes(rng, std::move(base), std::max(1, holes), uniform_int(rng, 3, 8));
    }
    case Shape::grid: return random_grid_polygon(rng, grid, vertices, false);
    case Shape::grid_holes: return random_grid_polygon(rng, grid, vertices, true);
  }
  return {};
}

namespace {

// Identity up to numbering and orientation: the same point set.
RawPolygon renumbered(Rng& rng, const RawPolygon& p) {
  RawPolygon q = rotated_start(p, static_cast<std::size_t>(uniform_int(rng, 0, 1000)));
  if (uniform01(rng) < 0.5) q = reversed(q);
  return q;
}

RawBox expanded(const RawBox& b, double m) { return {b.xmin - m, b.ymin - m, b.xmax + m, b.ymax + m}; }

}  // namespace

ClipCase make_case(const CaseSpec& spec) {
  Rng rng(spec.seed);
  ClipCase c;
  c.subject = make_shape(spec.subject, rng, spec.subject_vertices, spec.holes, spec.grid);
  const bool grid = is_grid(spec.subject);
  switch (spec.relation) {
    case Relation::independent:
      c.clip = make_shape(spec.clip, rng, spec.clip_vertices, spec.holes, spec.grid);
      break;
    case Relation::identity:
      c.clip = renumbered(rng, c.subject);
      break;
    case Relation::shifted: {
      double dx, dy;
      if (grid) {
        dx = uniform_int(rng, -3, 3);
        dy = uniform_int(rng, -3, 3);
      } else if (uniform01(rng) < 0.5) {
        // Dyadic steps: the shifted copy keeps exactly parallel edges and exact collinearities.
        dx = uniform_int(rng, -8, 8) * 0.25;
        dy = uniform_int(rng, -8, 8) * 0.25;
      } else {
        dx = uniform(rng, -3, 3);
        dy = uniform(rng, -3, 3);
      }
      if (uniform01(rng) < 0.3) (uniform01(rng) < 0.5 ? dx : dy) = 0;
      c.clip = renumbered(rng, translated(c.subject, dx, dy));
      break;
    }
    case Relation::in_clip_hole: {
      const RawBox b = bounding_box(c.subject);
      const double m = grid ? 1.0 : std::max(b.xmax - b.xmin, b.ymax - b.ymin) * 0.25;
      c.clip.outer = box_contour(expanded(b, 2 * m));
      switch (uniform_int(rng, 0, 2)) {
        case 0: c.clip.holes.push_back(c.subject.outer); break;        // hole == subject's outer contour
        case 1: c.clip.holes.push_back(box_contour(b)); break;         // hole == subject's box: touching
        default: c.clip.holes.push_back(box_contour(expanded(b, m))); break;  // strictly apart
      }
      c.clip = renumbered(rng, c.clip);
      break;
    }
    case Relation::subject_contour: {
      const std::size_t k = static_cast<std::size_t>(uniform_int(rng, 0, static_cast<int>(c.subject.holes.size())));
      c.clip.outer = k == 0 ? c.subject.outer : c.subject.holes[k - 1];
      c.clip = renumbered(rng, c.clip);
      break;
    }
    case Relation::box_cut: {
      const RawBox b = bounding_box(c.subject);
      if (uniform01(rng) < 0.3) {
        c.clip.outer = box_contour(b);
      } else {
        // A box with each side at a random place: on grids, on grid lines; otherwise at a vertex
        // coordinate of the subject half of the time, so that its sides run along subject edges.
        auto coord = [&](int axis, double lo, double hi) {
          if (grid) return static_cast<double>(uniform_int(rng, static_cast<int>(lo), static_cast<int>(hi)));
          if (uniform01(rng) < 0.5) {
            const auto& v = c.subject.outer[static_cast<std::size_t>(uniform_int(rng, 0, static_cast<int>(c.subject.outer.size()) - 1))];
            return v[axis];
          }
          return uniform(rng, lo, hi);
        };
        double x0 = coord(0, b.xmin - 1, b.xmax + 1), x1 = coord(0, b.xmin - 1, b.xmax + 1);
        double y0 = coord(1, b.ymin - 1, b.ymax + 1), y1 = coord(1, b.ymin - 1, b.ymax + 1);
        if (x0 > x1) std::swap(x0, x1);
        if (y0 > y1) std::swap(y0, y1);
        if (x0 == x1) x1 = x0 + 1;
        if (y0 == y1) y1 = y0 + 1;
        c.clip.outer = box_contour({x0, y0, x1, y1});
      }
      c.clip = renumbered(rng, c.clip);
      break;
    }
  }
  return c;
}

std::string describe(const CaseSpec& s) {
  return std::string("subject=") + shape_name(s.subject) + " clip=" + shape_name(s.clip) + " relation=" +
         relation_name(s.relation) + " seed=" + std::to_string(s.seed) + " subject_vertices=" +
         std::to_string(s.subject_vertices) + " clip_vertices=" + std::to_string(s.clip_vertices) +
         " holes=" + std::to_string(s.holes) + " grid=" + std::to_string(s.grid);
}

// ---- the stability families ----

namespace {

Shape float_shape(Rng& rng) {
  return std::array{Shape::star, Shape::comb, Shape::spiral, Shape::holes}[uniform_int(rng, 0, 3)];
}
Shape grid_shape(Rng& rng) { return uniform01(rng) < 0.5 ? Shape::grid : Shape::grid_holes; }
Shape any_shape(Rng& rng) { return kAllShapes[uniform_int(rng, 0, 5)]; }

CaseSpec random_spec(Rng& rng, Shape subject, Shape clip, Relation relation) {
  CaseSpec s;
  s.subject = subject;
  s.clip = clip;
  s.relation = relation;
  s.seed = rng();
  auto verts = [&](Shape sh) { return is_grid(sh) ? uniform_int(rng, 3, 12) : uniform_int(rng, 8, 24); };
  s.subject_vertices = verts(subject);
  s.clip_vertices = verts(clip);
  s.holes = uniform_int(rng, 1, 3);
  s.grid = 8;
  return s;
}

// Moves every vertex by a tiny random amount (relative to `scale`).
RawPolygon jittered(Rng& rng, const RawPolygon& p, double amount) {
  RawPolygon q = p;
  auto j = [&](RawPoint& v) {
    v[0] += amount * uniform(rng, -1, 1);
    v[1] += amount * uniform(rng, -1, 1);
  };
  for (auto& v : q.outer) j(v);
  for (auto& h : q.holes)
    for (auto& v : h) j(v);
  return q;
}

}  // namespace

std::vector<Family> stability_families() {
  // Every draw from rng is its own statement: the order of evaluation of function arguments is
  // unspecified, and a seed must name the same case with every compiler.
  auto pick_relation = [](Rng& rng, double independent) {
    if (uniform01(rng) < independent) return Relation::independent;
    return kAllRelations[uniform_int(rng, 1, 5)];
  };
  auto spec = [](Rng& rng, Shape (*subject)(Rng&), Shape (*clip)(Rng&), Relation relation) {
    const Shape s = subject(rng);
    const Shape c = clip(rng);
    return random_spec(rng, s, c, relation);
  };
  auto star = [](Rng&) { return Shape::star; };
  return {
      {"random-float", "stars, combs, spirals, polygons with holes at random double coordinates, independent",
       [=](Rng& rng) { return make_case(spec(rng, float_shape, float_shape, Relation::independent)); }},
      {"grid", "integer grid 8x8, with and without holes, all relations (identity, shifts, boxes, holes)",
       [=](Rng& rng) {
         const Relation r = pick_relation(rng, 0.6);
         return make_case(spec(rng, grid_shape, grid_shape, r));
       }},
      {"decimal-grid", "the grid family scaled by 0.1: coordinates k/10, not representable in binary",
       [=](Rng& rng) {
         const Relation r = pick_relation(rng, 0.6);
         const ClipCase c = make_case(spec(rng, grid_shape, grid_shape, r));
         auto tenth = [](RawPolygon p) {
           auto f = [](RawPoint& v) { v = {v[0] / 10, v[1] / 10}; };
           for (auto& v : p.outer) f(v);
           for (auto& h : p.holes)
             for (auto& v : h) f(v);
           return p;
         };
         return ClipCase{tenth(c.subject), tenth(c.clip)};
       }},
      {"rotated-tiny", "clip = subject rotated by 1e-12 to 1e-6 rad about a subject vertex or its centre",
       [=](Rng& rng) {
         const RawPolygon subject = make_case(spec(rng, any_shape, star, Relation::independent)).subject;
         const double magnitude = std::pow(10.0, uniform(rng, -12, -6));
         const double angle = uniform01(rng) < 0.5 ? magnitude : -magnitude;
         const RawBox b = bounding_box(subject);
         RawPoint c{(b.xmin + b.xmax) / 2, (b.ymin + b.ymax) / 2};
         if (uniform01(rng) < 0.5) c = subject.outer[uniform_int(rng, 0, static_cast<int>(subject.outer.size()) - 1)];
         return ClipCase{subject, rotated(subject, angle, c[0], c[1])};
       }},
      {"shifted-tiny", "clip = subject shifted by 1e-12 (relative) along x, y or both",
       [=](Rng& rng) {
         const RawPolygon subject = make_case(spec(rng, any_shape, star, Relation::independent)).subject;
         const double e = 1e-12 * std::max(1.0, max_abs_coordinate(subject));
         const int axis = uniform_int(rng, 0, 2);
         const double sx = uniform01(rng) < 0.5 ? e : -e;
         const double sy = uniform01(rng) < 0.5 ? e : -e;
         return ClipCase{subject, translated(subject, axis != 1 ? sx : 0, axis != 0 ? sy : 0)};
       }},
      {"near-collinear", "grid polygons whose clip vertices are moved by 1e-14 to 1e-9: edges nearly collinear",
       [=](Rng& rng) {
         const Relation r = pick_relation(rng, 0.5);
         ClipCase c = make_case(spec(rng, grid_shape, grid_shape, r));
         const double amount = std::pow(10.0, uniform(rng, -14, -9));
         c.clip = jittered(rng, c.clip, amount);
         return c;
       }},
      {"large-offset", "random-float and grid cases moved to 1e7 (features of size 1 to 8 far from the origin)",
       [=](Rng& rng) {
         ClipCase c;
         if (uniform01(rng) < 0.5) {
           const Relation r = pick_relation(rng, 0.6);
           c = make_case(spec(rng, grid_shape, grid_shape, r));
         } else {
           c = make_case(spec(rng, float_shape, float_shape, Relation::independent));
         }
         const double ox = 1e7 + uniform(rng, 0, 1);
         const double oy = 1e7 + uniform(rng, 0, 1);
         return ClipCase{translated(c.subject, ox, oy), translated(c.clip, ox, oy)};
       }},
      {"identity", "clip = subject (renumbered or reversed), random-float shapes",
       [=](Rng& rng) { return make_case(spec(rng, float_shape, star, Relation::identity)); }},
  };
}

}  // namespace hlr::testing
