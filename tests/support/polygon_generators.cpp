// Random polygon generators. Light on purpose: no CGAL here except through is_valid()
// (exact_polygon.cpp), so that this file compiles fast.
#include "polygon_generators.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <numbers>
#include <sstream>
#include <utility>

namespace hlr::testing {

std::size_t RawPolygon::vertex_count() const {
  std::size_t n = outer.size();
  for (const auto& h : holes) n += h.size();
  return n;
}

double uniform01(Rng& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }
double uniform(Rng& rng, double lo, double hi) { return lo + (hi - lo) * uniform01(rng); }
int uniform_int(Rng& rng, int lo, int hi) {
  if (hi <= lo) return lo;
  const std::uint64_t span = static_cast<std::uint64_t>(hi - lo) + 1;
  return lo + static_cast<int>(rng() % span);
}

namespace {

constexpr double kPi = std::numbers::pi;
constexpr int kMaxAttempts = 200;

// Point in contour, in double (the generators only use it to pick candidates; is_valid decides).
bool inside_contour(const RawContour& c, double x, double y) {
  bool in = false;
  for (std::size_t i = 0, j = c.size() - 1; i < c.size(); j = i++) {
    const double xi = c[i][0], yi = c[i][1], xj = c[j][0], yj = c[j][1];
    if ((yi > y) != (yj > y) && x < (xj - xi) * (y - yi) / (yj - yi) + xi) in = !in;
  }
  return in;
}

double distance_to_segment(double x, double y, const RawPoint& a, const RawPoint& b) {
  const double dx = b[0] - a[0], dy = b[1] - a[1];
  const double len2 = dx * dx + dy * dy;
  double t = len2 > 0 ? ((x - a[0]) * dx + (y - a[1]) * dy) / len2 : 0;
  t = std::clamp(t, 0.0, 1.0);
  const double px = a[0] + t * dx - x, py = a[1] + t * dy - y;
  return std::sqrt(px * px + py * py);
}

double distance_to_contour(double x, double y, const RawContour& c) {
  double d = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0, n = c.size(); i < n; ++i) d = std::min(d, distance_to_segment(x, y, c[i], c[(i + 1) % n]));
  return d;
}

RawPolygon star_once(Rng& rng, int vertices, double radius, double cx, double cy) {
  const int n = std::max(3, vertices);
  RawPolygon p;
  p.outer.reserve(n);
  // One vertex per angular slot, jittered inside it: consecutive gaps stay below pi for n >= 4,
  // so the polygon is star-shaped around the center and simple.
  const double phase = uniform01(rng) * 2 * kPi;
  for (int i = 0; i < n; ++i) {
    const double t = phase + (i + 0.1 + 0.8 * uniform01(rng)) * 2 * kPi / n;
    const double r = radius * (0.2 + 0.8 * uniform01(rng));
    p.outer.push_back({cx + r * std::cos(t), cy + r * std::sin(t)});
  }
  return p;
}

// Rotation by a multiple of 90 degrees is exact; other angles are rounded.
void rotate_in_place(RawPolygon& p, int quarter_turns, double angle, double cx, double cy) {
  auto apply = [&](RawPoint& q) {
    double x = q[0] - cx, y = q[1] - cy;
    switch (quarter_turns & 3) {
      case 1: std::tie(x, y) = std::pair(-y, x); break;
      case 2: std::tie(x, y) = std::pair(-x, -y); break;
      case 3: std::tie(x, y) = std::pair(y, -x); break;
      default: break;
    }
    if (angle != 0) {
      const double c = std::cos(angle), s = std::sin(angle);
      std::tie(x, y) = std::pair(c * x - s * y, s * x + c * y);
    }
    q = {cx + x, cy + y};
  };
  for (auto& q : p.outer) apply(q);
  for (auto& h : p.holes)
    for (auto& q : h) apply(q);
}

RawPolygon comb_once(Rng& rng, int vertices, double size, double cx, double cy) {
  const int teeth = std::max(1, (vertices - 4) / 4);
  // Columns: gap, tooth, gap, tooth, ..., gap, with random widths.
  const int columns = 2 * teeth + 1;
  std::vector<double> w(columns);
  double total = 0;
  for (auto& x : w) total += (x = 0.3 + uniform01(rng));
  const double x0 = cx - size / 2, y0 = cy - size / 2;
  std::vector<double> xs(columns + 1, x0);
  for (int k = 0; k < columns; ++k) xs[k + 1] = xs[k] + size * w[k] / total;
  xs[columns] = x0 + size;
  const double spine = y0 + size * uniform(rng, 0.1, 0.3);
  RawPolygon p;
  p.outer.push_back({x0, y0});
  p.outer.push_back({x0 + size, y0});
  p.outer.push_back({x0 + size, spine});
  for (int t = teeth - 1; t >= 0; --t) {
    const double left = xs[2 * t + 1], right = xs[2 * t + 2];
    const double top_r = y0 + size * uniform(rng, 0.45, 1.0);
    // Some teeth get slanted tips.
    const double top_l = uniform01(rng) < 0.3 ? y0 + size * uniform(rng, 0.45, 1.0) : top_r;
    p.outer.push_back({right, spine});
    p.outer.push_back({right, top_r});
    p.outer.push_back({left, top_l});
    p.outer.push_back({left, spine});
  }
  p.outer.push_back({x0, spine});
  const int quarter = uniform_int(rng, 0, 3);
  const double angle = uniform01(rng) < 0.3 ? uniform(rng, -kPi, kPi) : 0.0;
  rotate_in_place(p, quarter, angle, cx, cy);
  return p;
}

RawPolygon spiral_once(Rng& rng, int vertices, double size, double cx, double cy, double turns) {
  const int n = std::max(3, vertices / 2);  // samples per side
  const double pitch = 1.0;                 // radial growth per turn, before scaling
  const double w = pitch * uniform(rng, 0.3, 0.6);
  const double a = w / 2 + pitch * uniform(rng, 0.15, 0.5);
  const double total = turns * 2 * kPi;
  const double step = total / (n - 1);
  const double phase = uniform01(rng) * 2 * kPi;
  const double dir = uniform01(rng) < 0.5 ? 1.0 : -1.0;
  const double rmax = a + pitch * turns + w / 2;
  const double scale = size / 2 / rmax;
  auto at = [&](int i, double offset) {
    const double th = i * step;
    const double r = (a + pitch * th / (2 * kPi) + offset) * scale;
    return RawPoint{cx + r * std::cos(phase + dir * th), cy + r * std::sin(phase + dir * th)};
  };
  RawPolygon p;
  for (int i = 0; i < n; ++i) p.outer.push_back(at(i, w / 2));
  for (int i = n - 1; i >= 0; --i) p.outer.push_back(at(i, -w / 2));
  return p;
}

// ---- grid polygons ----

using Cells = std::vector<std::vector<char>>;  // [x][y]

// The boundary loops of a cell set, counter-clockwise around filled cells. Empty when the set
// pinches (two cells meeting at a corner only), which would make a contour non-simple.
std::vector<RawContour> trace_cells(const Cells& cells, int grid) {
  auto filled = [&](int x, int y) { return x >= 0 && y >= 0 && x < grid && y < grid && cells[x][y]; };
  std::map<std::pair<int, int>, std::pair<int, int>> next;  // directed boundary edge start -> end
  bool pinch = false;
  auto add = [&](int ax, int ay, int bx, int by) {
    if (!next.emplace(std::pair(ax, ay), std::pair(bx, by)).second) pinch = true;
  };
  for (int x = 0; x < grid; ++x)
    for (int y = 0; y < grid; ++y) {
      if (!cells[x][y]) continue;
      if (!filled(x, y - 1)) add(x, y, x + 1, y);
      if (!filled(x + 1, y)) add(x + 1, y, x + 1, y + 1);
      if (!filled(x, y + 1)) add(x + 1, y + 1, x, y + 1);
      if (!filled(x - 1, y)) add(x, y + 1, x, y);
    }
  if (pinch) return {};
  std::vector<RawContour> loops;
  while (!next.empty()) {
    auto start = next.begin()->first;
    RawContour loop;
    auto cur = start;
    do {
      loop.push_back({double(cur.first), double(cur.second)});
      auto it = next.find(cur);
      if (it == next.end()) return {};
      cur = it->second;
      next.erase(it);
    } while (cur != start);
    loops.push_back(std::move(loop));
  }
  return loops;
}

// Drops vertices where the contour runs straight on, each with probability `drop`.
RawContour drop_straight_vertices(Rng& rng, const RawContour& c, double drop) {
  RawContour out;
  const std::size_t n = c.size();
  for (std::size_t i = 0; i < n; ++i) {
    const RawPoint& p = c[(i + n - 1) % n];
    const RawPoint& q = c[i];
    const RawPoint& r = c[(i + 1) % n];
    const bool straight = (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]) == 0;
    if (straight && uniform01(rng) < drop) continue;
    out.push_back(q);
  }
  return out;
}

// Union of 1..4 random cell rectangles in [x0, x1] x [y0, y1], traced.
bool grid_cells_polygon(Rng& rng, int grid, int max_vertices, bool allow_holes, RawPolygon& out) {
  Cells cells(grid, std::vector<char>(grid, 0));
  const int rects = uniform_int(rng, 1, 4);
  for (int r = 0; r < rects; ++r) {
    const int x0 = uniform_int(rng, 0, grid - 1), y0 = uniform_int(rng, 0, grid - 1);
    const int x1 = uniform_int(rng, x0 + 1, grid), y1 = uniform_int(rng, y0 + 1, grid);
    for (int x = x0; x < x1; ++x)
      for (int y = y0; y < y1; ++y) cells[x][y] = 1;
  }
  std::vector<RawContour> loops = trace_cells(cells, grid);
  if (loops.empty()) return false;
  RawPolygon p;
  int outers = 0;
  const double drop = std::array{0.0, 0.5, 1.0}[uniform_int(rng, 0, 2)];
  for (auto& loop : loops) {
    RawContour c = drop_straight_vertices(rng, loop, drop);
    if (twice_signed_area(loop) > 0) {
      ++outers;
      p.outer = std::move(c);
    } else if (allow_holes) {
      p.holes.push_back(std::move(c));
    }
  }
  if (outers != 1 || static_cast<int>(p.outer.size()) > max_vertices) return false;
  out = std::move(p);
  return true;
}

// k distinct grid points in the box, joined in angular order around their centroid.
RawContour grid_star_contour(Rng& rng, int k, int x0, int y0, int x1, int y1) {
  std::vector<RawPoint> pts;
  const int capacity = (x1 - x0 + 1) * (y1 - y0 + 1);
  k = std::min(k, capacity);
  for (int tries = 0; static_cast<int>(pts.size()) < k && tries < 20 * k; ++tries) {
    RawPoint q{double(uniform_int(rng, x0, x1)), double(uniform_int(rng, y0, y1))};
    if (std::find(pts.begin(), pts.end(), q) == pts.end()) pts.push_back(q);
  }
  double mx = 0, my = 0;
  for (auto& q : pts) mx += q[0], my += q[1];
  mx /= pts.size();
  my /= pts.size();
  std::sort(pts.begin(), pts.end(), [&](const RawPoint& a, const RawPoint& b) {
    const double ta = std::atan2(a[1] - my, a[0] - mx), tb = std::atan2(b[1] - my, b[0] - mx);
    if (ta != tb) return ta < tb;
    return std::hypot(a[0] - mx, a[1] - my) < std::hypot(b[0] - mx, b[1] - my);
  });
  return pts;
}

RawContour grid_rectangle(Rng& rng, int x0, int y0, int x1, int y1) {
  const int ax = uniform_int(rng, x0, x1 - 1), ay = uniform_int(rng, y0, y1 - 1);
  const int bx = uniform_int(rng, ax + 1, x1), by = uniform_int(rng, ay + 1, y1);
  return box_contour({double(ax), double(ay), double(bx), double(by)});
}

}  // namespace

RawPolygon random_star(Rng& rng, int vertices, double radius, double cx, double cy) {
  RawPolygon p;
  for (int attempt = 0; attempt < kMaxAttempts; ++attempt) {
    p = star_once(rng, vertices, radius, cx, cy);
    if (is_valid(p)) return p;
  }
  return p;
}

RawPolygon random_comb(Rng& rng, int vertices, double size, double cx, double cy) {
  RawPolygon p;
  for (int attempt = 0; attempt < kMaxAttempts; ++attempt) {
    p = comb_once(rng, vertices, size, cx, cy);
    if (is_valid(p)) return p;
  }
  return p;
}

RawPolygon random_spiral(Rng& rng, int vertices, double size, double cx, double cy) {
  // Coarse sampling of many turns makes the chords cut through the neighbouring turn: fewer turns
  // until the polygon is simple.
  double turns = uniform(rng, 0.5, 2.5);
  RawPolygon p;
  for (int attempt = 0; attempt < kMaxAttempts; ++attempt) {
    p = spiral_once(rng, vertices, size, cx, cy, turns);
    if (is_valid(p)) return p;
    turns *= 0.8;
  }
  return p;
}

RawPolygon with_random_holes(Rng& rng, RawPolygon polygon, int holes, int hole_vertices) {
  if (polygon.outer.size() < 3 || holes <= 0) return polygon;
  const RawBox box = bounding_box(polygon);
  int placed = 0;
  for (int attempt = 0; attempt < 30 * holes && placed < holes; ++attempt) {
    const double x = uniform(rng, box.xmin, box.xmax), y = uniform(rng, box.ymin, box.ymax);
    if (!inside_contour(polygon.outer, x, y)) continue;
    bool in_hole = false;
    for (const auto& h : polygon.holes) in_hole = in_hole || inside_contour(h, x, y);
    if (in_hole) continue;
    double d = distance_to_contour(x, y, polygon.outer);
    for (const auto& h : polygon.holes) d = std::min(d, distance_to_contour(x, y, h));
    if (!(d > 0)) continue;
    // Every vertex of a star lies within its radius, so the whole hole lies in the disc, which
    // reaches no other boundary.
    RawPolygon hole = star_once(rng, hole_vertices, d * uniform(rng, 0.3, 0.9), x, y);
    polygon.holes.push_back(std::move(hole.outer));
    if (last_hole_defect(polygon).empty()) ++placed;
    else polygon.holes.pop_back();
  }
  return polygon;
}

RawPolygon random_grid_polygon(Rng& rng, int grid, int max_vertices, bool allow_holes) {
  grid = std::max(grid, 2);
  max_vertices = std::max(max_vertices, 3);
  // Half of the polygons use only even coordinates (a coarser lattice): coincidences with
  // another polygon on the same grid become more frequent still.
  const int step = grid >= 4 && uniform01(rng) < 0.5 ? 2 : 1;
  const int coarse = grid / step;
  RawPolygon p;
  bool ok = false;
  for (int attempt = 0; attempt < kMaxAttempts && !ok; ++attempt) {
    // Kinds: 0-4 orthogonal cell unions, 5-7 stars over the whole grid, 8-9 stars in a sub-box.
    const int draw = uniform_int(rng, 0, 9);
    const int kind = draw < 5 ? 0 : draw < 8 ? 1 : 2;
    if (kind == 0) {
      ok = grid_cells_polygon(rng, coarse, max_vertices, allow_holes, p);
    } else if (kind == 1) {
      p = RawPolygon{grid_star_contour(rng, uniform_int(rng, 3, max_vertices), 0, 0, coarse, coarse), {}};
      ok = true;
    } else {
      // A small star in a random sub-box: leaves room for the other polygon around it.
      const int x0 = uniform_int(rng, 0, coarse - 2), y0 = uniform_int(rng, 0, coarse - 2);
      const int x1 = uniform_int(rng, x0 + 2, coarse), y1 = uniform_int(rng, y0 + 2, coarse);
      p = RawPolygon{grid_star_contour(rng, uniform_int(rng, 3, max_vertices), x0, y0, x1, y1), {}};
      ok = true;
    }
    ok = ok && p.outer.size() >= 3 && is_valid(p);
    if (ok && step != 1) p = scaled(p, step);
  }
  if (!ok) {
    p = RawPolygon{grid_rectangle(rng, 0, 0, grid, grid), {}};
  }
  if (allow_holes && uniform01(rng) < 0.75) {
    // Holes on the same grid, inside the outer contour; they may touch it and each other at points.
    const RawBox b = bounding_box(p);
    const int bx0 = int(b.xmin), by0 = int(b.ymin), bx1 = int(b.xmax), by1 = int(b.ymax);
    const int want = uniform_int(rng, 1, 2);
    int placed = 0;
    for (int attempt = 0; attempt < 30 && placed < want && bx1 - bx0 >= 2 && by1 - by0 >= 2; ++attempt) {
      RawContour hole;
      if (uniform01(rng) < 0.5) {
        hole = grid_rectangle(rng, bx0, by0, bx1, by1);
      } else {
        const int x0 = uniform_int(rng, bx0, bx1 - 1), y0 = uniform_int(rng, by0, by1 - 1);
        const int x1 = uniform_int(rng, x0 + 1, bx1), y1 = uniform_int(rng, y0 + 1, by1);
        hole = grid_star_contour(rng, uniform_int(rng, 3, 6), x0, y0, x1, y1);
      }
      if (hole.size() < 3) continue;
      p.holes.push_back(std::move(hole));
      if (last_hole_defect(p).empty()) ++placed;
      else p.holes.pop_back();
    }
  }
  return p;
}

bool is_valid(const RawPolygon& polygon) { return validity_defect(polygon).empty(); }

RawPolygon translated(const RawPolygon& p, double dx, double dy) {
  RawPolygon q = p;
  for (auto& v : q.outer) v = {v[0] + dx, v[1] + dy};
  for (auto& h : q.holes)
    for (auto& v : h) v = {v[0] + dx, v[1] + dy};
  return q;
}

RawPolygon scaled(const RawPolygon& p, double f, double cx, double cy) {
  RawPolygon q = p;
  auto s = [&](RawPoint& v) { v = {cx + (v[0] - cx) * f, cy + (v[1] - cy) * f}; };
  for (auto& v : q.outer) s(v);
  for (auto& h : q.holes)
    for (auto& v : h) s(v);
  return q;
}

RawPolygon rotated(const RawPolygon& p, double angle, double cx, double cy) {
  RawPolygon q = p;
  rotate_in_place(q, 0, angle, cx, cy);
  return q;
}

RawPolygon reversed(const RawPolygon& p) {
  RawPolygon q = p;
  std::reverse(q.outer.begin(), q.outer.end());
  for (auto& h : q.holes) std::reverse(h.begin(), h.end());
  return q;
}

RawPolygon rotated_start(const RawPolygon& p, std::size_t shift) {
  RawPolygon q = p;
  auto rot = [&](RawContour& c) {
    if (!c.empty()) std::rotate(c.begin(), c.begin() + (shift % c.size()), c.end());
  };
  rot(q.outer);
  for (auto& h : q.holes) rot(h);
  return q;
}

RawBox bounding_box(const RawPolygon& p) {
  RawBox b{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
           -std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
  for (const auto& v : p.outer) {
    b.xmin = std::min(b.xmin, v[0]);
    b.ymin = std::min(b.ymin, v[1]);
    b.xmax = std::max(b.xmax, v[0]);
    b.ymax = std::max(b.ymax, v[1]);
  }
  return b;
}

RawContour box_contour(const RawBox& b) {
  return {{b.xmin, b.ymin}, {b.xmax, b.ymin}, {b.xmax, b.ymax}, {b.xmin, b.ymax}};
}

double max_abs_coordinate(const RawPolygon& p) {
  double m = 0;
  for (const auto& v : p.outer) m = std::max({m, std::abs(v[0]), std::abs(v[1])});
  return m;
}

double perimeter(const RawPolygon& p) {
  auto len = [](const RawContour& c) {
    double s = 0;
    for (std::size_t i = 0, n = c.size(); i < n; ++i)
      s += std::hypot(c[(i + 1) % n][0] - c[i][0], c[(i + 1) % n][1] - c[i][1]);
    return s;
  };
  double s = len(p.outer);
  for (const auto& h : p.holes) s += len(h);
  return s;
}

namespace {
std::string number(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}
std::string cpp_number(double v) {
  char buf[64];
  if (v == std::floor(v) && std::abs(v) < 1e15) std::snprintf(buf, sizeof buf, "%.1f", v);
  else std::snprintf(buf, sizeof buf, "%a", v);
  return buf;
}
template <class F>
std::string contour_text(const RawContour& c, F&& num) {
  std::string s = "[";
  for (std::size_t i = 0; i < c.size(); ++i) {
    if (i) s += ", ";
    s += '[';
    s += num(c[i][0]);
    s += ", ";
    s += num(c[i][1]);
    s += ']';
  }
  return s + "]";
}
}  // namespace

std::string to_json(const std::vector<RawPolygon>& polygons) {
  std::string s = "{\"format\": \"hlr-polygons/1\", \"polygons\": [";
  for (std::size_t k = 0; k < polygons.size(); ++k) {
    if (k) s += ", ";
    s += "{\"outer\": " + contour_text(polygons[k].outer, number) + ", \"holes\": [";
    for (std::size_t h = 0; h < polygons[k].holes.size(); ++h) {
      if (h) s += ", ";
      s += contour_text(polygons[k].holes[h], number);
    }
    s += "]}";
  }
  return s + "]}";
}

std::string to_cpp(const RawPolygon& p) {
  auto cont = [](const RawContour& c) {
    std::string s = "{";
    for (std::size_t i = 0; i < c.size(); ++i) {
      if (i) s += ", ";
      s += '{';
      s += cpp_number(c[i][0]);
      s += ", ";
      s += cpp_number(c[i][1]);
      s += '}';
    }
    return s + "}";
  };
  std::string s = "{";
  s += cont(p.outer);
  s += ", {";
  for (std::size_t h = 0; h < p.holes.size(); ++h) {
    if (h) s += ", ";
    s += cont(p.holes[h]);
  }
  s += "}}";
  return s;
}

double twice_signed_area(const RawContour& c) {
  double a = 0;
  for (std::size_t i = 0, n = c.size(); i < n; ++i) {
    const RawPoint& p = c[i];
    const RawPoint& q = c[(i + 1) % n];
    a += p[0] * q[1] - q[0] * p[1];
  }
  return a;
}

}  // namespace hlr::testing
