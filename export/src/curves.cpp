// Circles and arcs in the chained lines of a drawing (hlr/export/curves.hpp).
//
// A chain is scanned from its start for runs of vertices on one circle, greedily: a run starts
// with four vertices that fit a circle, and grows one vertex at a time while the vertex lies
// within the tolerance of the run's circle (refitted over the whole run once a vertex misses the
// circle fitted so far, and kept only if every vertex still fits). The fit is Kåsa's algebraic
// circle, centred on the points' mean for conditioning, refined by Gauss–Newton on the geometric
// distances. A closed chain is first tried as one circle; otherwise it is scanned from its
// sharpest corner, so that no run has to wrap past the start.
//
// The steps of a run must go round the centre one way, evenly (Steps below), each of at most 46
// degrees: the polygons that tessellate holes have 8 segments or more, and a square, a hexagon,
// or a zigzag whose vertices happen to lie on a circle is no arc. A run whose vertices lie within the tolerance of
// a straight line is a line (its circle would be arbitrary). A run needs three segments: any three
// points lie on a circle, four are a test.
#include <hlr/export/curves.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

namespace hlr::exporter {
namespace {

constexpr double pi = 3.14159265358979323846;
constexpr double max_step = 46 * pi / 180;  // a circle of 8 segments steps 45 degrees
constexpr std::size_t min_fit_points = 4;   // over-determined: three points always fit

struct Circle {
  double cx = 0, cy = 0, r = 0;
};

double distance(const Point2& p, const Point2& q) { return std::hypot(p[0] - q[0], p[1] - q[1]); }

// Solves the 3x3 system a x = b (Cramer's rule; small and well scaled here). Nothing when singular.
std::optional<std::array<double, 3>> solve3(const double a[3][3], const double b[3]) {
  auto det = [](const double m[3][3]) {
    return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  };
  const double d = det(a);
  if (!(std::abs(d) > 0) || !std::isfinite(d)) return std::nullopt;
  std::array<double, 3> x{};
  for (int c = 0; c < 3; ++c) {
    double m[3][3];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) m[i][j] = j == c ? b[i] : a[i][j];
    x[c] = det(m) / d;
  }
  return x;
}

// The circle nearest to points p[0..n) (n >= 3), or nothing when they are (nearly) collinear.
std::optional<Circle> fit_circle(const Point2* p, std::size_t n) {
  double mx = 0, my = 0;
  for (std::size_t i = 0; i < n; ++i) mx += p[i][0], my += p[i][1];
  mx /= double(n), my /= double(n);
  double suu = 0, suv = 0, svv = 0, suuu = 0, svvv = 0, suvv = 0, svuu = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double u = p[i][0] - mx, v = p[i][1] - my;
    suu += u * u, suv += u * v, svv += v * v;
    suuu += u * u * u, svvv += v * v * v, suvv += u * v * v, svuu += v * u * u;
  }
  const double det = suu * svv - suv * suv;
  if (!(std::abs(det) > 1e-12 * (suu + svv) * (suu + svv))) return std::nullopt;
  const double uc = 0.5 * ((suuu + suvv) * svv - (svvv + svuu) * suv) / det;
  const double vc = 0.5 * ((svvv + svuu) * suu - (suuu + suvv) * suv) / det;
  Circle c{mx + uc, my + vc, std::sqrt(uc * uc + vc * vc + (suu + svv) / double(n))};
  if (!std::isfinite(c.r)) return std::nullopt;
  // Gauss–Newton on sum (|p - c| - r)^2: Kåsa's circle is biased on short arcs.
  for (int iteration = 0; iteration < 8; ++iteration) {
    double a[3][3] = {}, b[3] = {};
    for (std::size_t i = 0; i < n; ++i) {
      const double dx = p[i][0] - c.cx, dy = p[i][1] - c.cy, d = std::hypot(dx, dy);
      if (!(d > 0)) return c;
      const double j[3] = {-dx / d, -dy / d, -1}, residual = d - c.r;
      for (int k = 0; k < 3; ++k) {
        b[k] -= j[k] * residual;
        for (int l = 0; l < 3; ++l) a[k][l] += j[k] * j[l];
      }
    }
    const auto step = solve3(a, b);
    if (!step) break;
    c.cx += (*step)[0], c.cy += (*step)[1], c.r += (*step)[2];
    if (std::abs((*step)[0]) + std::abs((*step)[1]) + std::abs((*step)[2]) <= 1e-15 * (c.r + std::abs(c.cx) + std::abs(c.cy)))
      break;
  }
  if (!(c.r > 0) || !std::isfinite(c.cx + c.cy + c.r)) return std::nullopt;
  return c;
}

double angle_of(const Circle& c, const Point2& p) { return std::atan2(p[1] - c.cy, p[0] - c.cx); }

// The step from angle a to angle b, in (-pi, pi].
double step_between(double a, double b) {
  double d = b - a;
  while (d > pi) d -= 2 * pi;
  while (d <= -pi) d += 2 * pi;
  return d;
}

Point2 onto(const Circle& c, const Point2& p) {
  const double a = angle_of(c, p);
  return {c.cx + c.r * std::cos(a), c.cy + c.r * std::sin(a)};
}

// The steps of a run round its centre. Tessellations divide a circle evenly (cos and sin of
// 2 pi k / n); the projection of a tessellated circle seen at a slant, an ellipse, lies as close to
// a circle over a few vertices, but its steps grow and shrink round it: over four vertices of a
// 32-gon seen in the iso view they differ by a fifth. Steps are even when they differ by at most
// 0.5 %, or by an arc length of a tenth of the tolerance (noise: coordinates written as floats).
struct Steps {
  double lo = HUGE_VAL, hi = 0;
  void add(double step) { lo = std::min(lo, std::abs(step)), hi = std::max(hi, std::abs(step)); }
  bool even(double r, double tol) const { return hi - lo <= std::max(0.005 * hi, 0.1 * tol / r); }
};

// A run of q[first..last] on one circle; `sweep` is signed (positive counter-clockwise).
struct Run {
  std::size_t first = 0, last = 0;
  Circle circle;
  double sweep = 0;
};

class ChainScanner {
 public:
  // q holds the chain's points; a closed chain, rotated, repeats its first point at the end.
  ChainScanner(const std::vector<Point2>& q, bool open, double tolerance) : q_(q), open_(open), tol_(tolerance) {}

  std::vector<Run> runs() {
    std::vector<Run> out;
    const std::size_t m = q_.size() - 1;
    std::size_t i = 0;
    while (i < m) {
      if (auto run = run_from(i)) {
        i = run->last;
        out.push_back(*run);
      } else {
        ++i;
      }
    }
    return out;
  }

 private:
  // The fit covers q[b..e]; an open chain's first and last points are never fitted (they may
  // lie on a chord), only checked against the fit.
  std::size_t last_fit() const { return open_ ? q_.size() - 2 : q_.size() - 1; }

  // Whether q[b..e] all lie on `c` and go round it one way in steps of at most max_step, and
  // the signed sweep; nothing otherwise.
  std::optional<double> fits(const Circle& c, std::size_t b, std::size_t e) const {
    double sweep = 0, sign = 0;
    double previous = angle_of(c, q_[b]);
    Steps steps;
    for (std::size_t k = b; k <= e; ++k) {
      if (std::abs(distance(q_[k], {c.cx, c.cy}) - c.r) > tol_) return std::nullopt;
      if (k == b) continue;
      const double a = angle_of(c, q_[k]);
      const double step = step_between(previous, a);
      previous = a;
      if (step == 0 || std::abs(step) > max_step) return std::nullopt;
      if (sign == 0) sign = step > 0 ? 1 : -1;
      if (step * sign < 0) return std::nullopt;
      sweep += step;
      steps.add(step);
    }
    if (std::abs(sweep) >= 2 * pi) return std::nullopt;  // more than once round: not one arc
    if (!steps.even(c.r, tol_)) return std::nullopt;
    return sweep;
  }

  bool straight(std::size_t b, std::size_t e) const {
    const Point2 &a = q_[b], &z = q_[e];
    const double length = distance(a, z);
    if (!(length > 0)) return false;
    for (std::size_t k = b + 1; k < e; ++k) {
      const double off = std::abs((z[0] - a[0]) * (q_[k][1] - a[1]) - (z[1] - a[1]) * (q_[k][0] - a[0])) / length;
      if (off > tol_) return false;
    }
    return true;
  }

  // Whether an open chain's end q[end], next to q[inner] on the run, belongs to it: on the circle,
  // or on the chord that leaves q[inner] with the run's largest step, one step on at most.
  bool end_fits(const Circle& c, std::size_t end, std::size_t inner, double sweep, double widest) const {
    const double phi = step_between(angle_of(c, q_[inner]), angle_of(c, q_[end])) * (end > inner ? 1 : -1);
    if (!(phi * sweep > 0) || std::abs(phi) > widest * (1 + 1e-9)) return false;
    const double d = distance(q_[end], {c.cx, c.cy});
    if (std::abs(d - c.r) <= tol_) return true;
    const double chord = c.r * std::cos(widest / 2) / std::cos(std::abs(phi) - widest / 2);
    return std::abs(d - chord) <= tol_;
  }

  double widest_step(const Circle& c, std::size_t b, std::size_t e) const {
    double widest = 0;
    for (std::size_t k = b; k < e; ++k)
      widest = std::max(widest, std::abs(step_between(angle_of(c, q_[k]), angle_of(c, q_[k + 1]))));
    return widest;
  }

  std::optional<Run> run_from(std::size_t i) const {
    const std::size_t b = open_ && i == 0 ? 1 : i;
    std::size_t e = b + min_fit_points - 1;
    if (e > last_fit()) return std::nullopt;
    auto circle = fit_circle(&q_[b], e - b + 1);
    if (!circle) return std::nullopt;
    auto sweep = fits(*circle, b, e);
    if (!sweep || straight(b, e)) return std::nullopt;
    while (e + 1 <= last_fit()) {
      if (auto grown = fits(*circle, b, e + 1)) {
        sweep = grown, ++e;
        continue;
      }
      const auto refit = fit_circle(&q_[b], e - b + 2);
      const auto again = refit ? fits(*refit, b, e + 1) : std::nullopt;
      if (!again) break;
      circle = refit, sweep = again, ++e;
    }
    Run run{b, e, *circle, *sweep};
    if (open_) {
      const double widest = widest_step(run.circle, b, e);
      auto extend = [&](std::size_t end, std::size_t inner) {
        // The sweep the end adds, in the run's direction (from the lower index to the higher).
        const std::size_t from = std::min(end, inner), to = std::max(end, inner);
        const double phi = step_between(angle_of(run.circle, q_[from]), angle_of(run.circle, q_[to]));
        if (!end_fits(run.circle, end, inner, run.sweep, widest) || std::abs(run.sweep + phi) >= 2 * pi) return false;
        run.sweep += phi;
        return true;
      };
      if (b == 1 && i == 0 && extend(0, 1)) run.first = 0;
      if (e + 1 == q_.size() - 1 && extend(e + 1, e)) run.last = e + 1;
    }
    return run;
  }

  const std::vector<Point2>& q_;
  bool open_;
  double tol_;
};

// The vertex of a closed chain where it turns most: where a scan for runs can start.
std::size_t sharpest_corner(const std::vector<Point2>& p) {
  const std::size_t n = p.size();
  std::size_t best = 0;
  double best_turn = -1;
  for (std::size_t k = 0; k < n; ++k) {
    const Point2 &a = p[(k + n - 1) % n], &b = p[k], &c = p[(k + 1) % n];
    const double turn = std::abs(step_between(std::atan2(b[1] - a[1], b[0] - a[0]), std::atan2(c[1] - b[1], c[0] - b[0])));
    if (turn > best_turn) best_turn = turn, best = k;
  }
  return best;
}

// A closed chain that goes round one circle once, as that circle.
std::optional<Circle> whole_circle(const std::vector<Point2>& p, double tol) {
  if (p.size() < 8) return std::nullopt;  // steps of at most 46 degrees
  const auto c = fit_circle(p.data(), p.size());
  if (!c) return std::nullopt;
  double sweep = 0, sign = 0;
  Steps steps;
  for (std::size_t k = 0; k < p.size(); ++k) {
    if (std::abs(distance(p[k], {c->cx, c->cy}) - c->r) > tol) return std::nullopt;
    const double step = step_between(angle_of(*c, p[k]), angle_of(*c, p[(k + 1) % p.size()]));
    if (step == 0 || std::abs(step) > max_step) return std::nullopt;
    if (sign == 0) sign = step > 0 ? 1 : -1;
    if (step * sign < 0) return std::nullopt;
    sweep += step;
    steps.add(step);
  }
  if (std::abs(std::abs(sweep) - 2 * pi) > 1e-6 || !steps.even(c->r, tol)) return std::nullopt;
  return c;
}

// Whether the runs of a closed chain all lie on one circle and leave out no more of it than two
// of their steps: a circle with a vertex off it, which is drawn as the polygon it is (a vertex
// off by more than the resolution is the shape's, not the tessellation's).
bool nearly_round(const std::vector<Run>& runs, double tol) {
  double sweep = 0, widest = 0;
  for (const Run& r : runs) {
    const Circle& c = runs.front().circle;
    if (std::hypot(r.circle.cx - c.cx, r.circle.cy - c.cy) > tol || std::abs(r.circle.r - c.r) > tol) return false;
    sweep += std::abs(r.sweep);
    widest = std::max(widest, std::abs(r.sweep) / double(r.last - r.first));
  }
  return sweep >= 2 * pi - 2 * widest * (1 + 1e-6);
}

DrawingPath straight_path(const DrawingPolyline& chain) {
  DrawingPath path;
  path.start = chain.points.front();
  path.closed = chain.closed;
  path.visible = chain.visible;
  path.mesh = chain.mesh;
  for (std::size_t k = 1; k < chain.points.size(); ++k) path.steps.push_back({chain.points[k]});
  return path;
}

}  // namespace

DrawingCurves recover_curves(const std::vector<DrawingPolyline>& chains, double tolerance) {
  DrawingCurves out;
  for (const auto& chain : chains) {
    if (chain.points.empty()) continue;
    if (!(tolerance > 0) || chain.points.size() < min_fit_points) {
      out.paths.push_back(straight_path(chain));
      continue;
    }
    if (chain.closed) {
      if (const auto c = whole_circle(chain.points, tolerance)) {
        out.circles.push_back({{c->cx, c->cy}, c->r, chain.visible, chain.mesh});
        continue;
      }
    }
    // The points to scan: a closed chain from its sharpest corner round to that corner again.
    std::vector<Point2> q;
    if (chain.closed) {
      const std::size_t n = chain.points.size(), s = sharpest_corner(chain.points);
      for (std::size_t k = 0; k <= n; ++k) q.push_back(chain.points[(s + k) % n]);
    } else {
      q = chain.points;
    }
    const std::vector<Run> runs = ChainScanner(q, !chain.closed, tolerance).runs();
    if (runs.empty() || (chain.closed && nearly_round(runs, tolerance))) {
      out.paths.push_back(straight_path(chain));
      continue;
    }
    DrawingPath path;
    path.closed = chain.closed;
    path.visible = chain.visible;
    path.mesh = chain.mesh;
    const std::size_t last = chain.closed ? q.size() - 2 : q.size() - 1;  // a closed path's Z goes back to q[0]
    std::size_t k = 0, r = 0;
    path.start = runs[0].first == 0 ? onto(runs[0].circle, q[0]) : q[0];
    while (k < q.size() - 1) {
      if (r < runs.size() && runs[r].first == k) {
        const Run& run = runs[r++];
        const PathStep arc{onto(run.circle, q[run.last]), true, {run.circle.cx, run.circle.cy}, run.circle.r, run.sweep > 0};
        path.steps.push_back(arc);
        ++out.arcs;
        k = run.last;
        continue;
      }
      ++k;
      if (k <= last) path.steps.push_back({q[k]});
    }
    out.paths.push_back(std::move(path));
  }
  return out;
}

std::vector<FaceOnCircle> face_on_circles(const DrawingCurves& curves, double tolerance) {
  // Each circle: the whole ones, and the arcs of one centre and radius that go round once.
  struct Found {
    Point2 centre;
    double radius;
  };
  std::vector<Found> found;
  for (const auto& c : curves.circles) found.push_back({c.centre, c.radius});
  struct ArcSet {
    Point2 centre;
    double radius, sweep;
  };
  std::vector<ArcSet> sets;
  for (const auto& path : curves.paths) {
    Point2 from = path.start;
    for (const auto& step : path.steps) {
      if (step.arc) {
        const double a0 = std::atan2(from[1] - step.centre[1], from[0] - step.centre[0]);
        const double a1 = std::atan2(step.to[1] - step.centre[1], step.to[0] - step.centre[0]);
        double sweep = a1 - a0;
        if (step.ccw) {
          while (sweep <= 0) sweep += 2 * pi;
        } else {
          while (sweep >= 0) sweep -= 2 * pi;
        }
        auto same = std::find_if(sets.begin(), sets.end(), [&](const ArcSet& s) {
          return distance(s.centre, step.centre) <= tolerance && std::abs(s.radius - step.radius) <= tolerance;
        });
        if (same == sets.end()) sets.push_back({step.centre, step.radius, std::abs(sweep)});
        else same->sweep += std::abs(sweep);
      }
      from = step.to;
    }
  }
  for (const auto& s : sets)
    if (s.sweep >= 2 * pi * (1 - 1e-3)) found.push_back({s.centre, s.radius});

  std::vector<FaceOnCircle> out;
  for (const auto& f : found) {
    auto same = std::find_if(out.begin(), out.end(), [&](const FaceOnCircle& o) { return distance(o.centre, f.centre) <= tolerance; });
    if (same == out.end()) {
      out.push_back({f.centre, {f.radius}});
    } else {
      const bool known = std::any_of(same->radii.begin(), same->radii.end(), [&](double r) { return std::abs(r - f.radius) <= tolerance; });
      if (!known) same->radii.push_back(f.radius);
    }
  }
  for (auto& o : out) std::sort(o.radii.begin(), o.radii.end());
  return out;
}

std::vector<CentreLine> centre_marks(const DrawingCurves& curves, double tolerance, double overshoot) {
  std::vector<CentreLine> out;
  for (const auto& c : face_on_circles(curves, tolerance)) {
    const double reach = c.radii.back() + overshoot;
    const double x = c.centre[0], y = c.centre[1];
    out.push_back({{x - reach, y}, {x + reach, y}});
    out.push_back({{x, y - reach}, {x, y + reach}});
  }
  return out;
}

}  // namespace hlr::exporter
