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
// circles over a stretch of vertices (a 48-gon seen in the iso view fits four arcs within 0.01 of
// its 6 mm radius), but its steps grow and shrink round them. So the angles of a run's vertices
// must grow evenly: they may lie off the straight line fitted to them (angle against vertex
// number) by no more than the tolerance, as arc length, as the vertices of an even tessellation
// may lie off it by the tolerance. Noise (coordinates written as floats) is far below that.
class Steps {
 public:
  void add(double step) { angles_.push_back(angles_.empty() ? step : angles_.back() + step); }
  bool even(double r, double tol) const {
    const std::size_t n = angles_.size() + 1;  // angles from the run's first vertex, which is at 0
    if (n < 3) return true;
    double sk = 0, sa = 0, skk = 0, ska = 0;
    for (std::size_t k = 0; k < n; ++k) {
      const double a = k == 0 ? 0 : angles_[k - 1];
      sk += double(k), sa += a, skk += double(k) * double(k), ska += double(k) * a;
    }
    const double slope = (double(n) * ska - sk * sa) / (double(n) * skk - sk * sk), offset = (sa - slope * sk) / double(n);
    for (std::size_t k = 0; k < n; ++k) {
      const double a = k == 0 ? 0 : angles_[k - 1];
      if (std::abs(a - offset - slope * double(k)) * r > tol) return false;
    }
    return true;
  }

 private:
  std::vector<double> angles_;
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

// Whether a closed chain that is no circle is nearly one: it goes round its own fitted circle
// once, one way, in steps of at most max_step, every vertex within 5 % of the radius (and the
// tolerance) of it. Such a chain is a circle with a vertex or a few off it by more than the
// resolution: that is the shape's, not the tessellation's, and the polygon is drawn as it is.
// (Its other vertices would make arcs, of circles bent to take the odd vertex in.) A slot, a
// rounded rectangle or a keyway is far from round and keeps its arcs.
bool nearly_round(const std::vector<Point2>& p, double tol) {
  const auto c = fit_circle(p.data(), p.size());
  if (!c) return false;
  double sweep = 0, sign = 0;
  for (std::size_t k = 0; k < p.size(); ++k) {
    if (std::abs(distance(p[k], {c->cx, c->cy}) - c->r) > 0.05 * c->r + tol) return false;
    const double step = step_between(angle_of(*c, p[k]), angle_of(*c, p[(k + 1) % p.size()]));
    if (step == 0 || std::abs(step) > max_step) return false;
    if (sign == 0) sign = step > 0 ? 1 : -1;
    if (step * sign < 0) return false;
    sweep += step;
  }
  return std::abs(std::abs(sweep) - 2 * pi) <= 1e-6;
}

bool same_circle(const Circle& a, const Circle& b, double tol) {
  return std::hypot(a.cx - b.cx, a.cy - b.cy) <= tol && std::abs(a.r - b.r) <= tol;
}

// Runs found one after another can take an odd vertex into a short run of its own, whose circle
// bends to reach it (any four points near a circle fit some circle over a short stretch). A run
// between two runs of one circle, on another circle, is such a run: dropped, its vertices drawn
// as lines. (A chain keeps the runs in its order; a closed chain's first and last are neighbours.)
//
// Runs of different circles that follow one another without a line or a corner between them are
// a smooth curve that is no circle: an ellipse (a circle seen at a slant) is as close to four
// arcs near its vertices as a tessellated circle is to one. Such a sequence of runs is dropped
// whole: a drawing keeps arcs that end at a line, a corner or the chain's end, or at another arc
// of their own circle. (An S-curve of two arcs is drawn as the polyline it is.)
std::vector<Run> without_bent_runs(std::vector<Run> runs, bool closed, double tol, const std::vector<Point2>& q) {
  const std::size_t n = runs.size();
  std::vector<bool> drop(n, false);
  if (n >= 3 || (closed && n == 3))
    for (std::size_t i = 0; i < n; ++i) {
      if (!closed && (i == 0 || i + 1 == n)) continue;
      const Run &before = runs[(i + n - 1) % n], &after = runs[(i + 1) % n];
      if (same_circle(before.circle, after.circle, tol) && !same_circle(runs[i].circle, before.circle, tol)) drop[i] = true;
    }
  // Whether run j starts where run i ends, smoothly (the chords on either side turn by no more
  // than the runs' steps).
  auto smooth_join = [&](std::size_t i, std::size_t j) {
    const std::size_t m = q.size() - 1;
    const bool joined = runs[i].last == runs[j].first || (closed && runs[i].last == m && runs[j].first == 0);
    if (!joined) return false;
    const Point2 &a = q[runs[i].last - 1], &b = q[runs[i].last], &c = q[runs[j].first + 1];
    const double turn = std::abs(step_between(std::atan2(b[1] - a[1], b[0] - a[0]), std::atan2(c[1] - b[1], c[0] - b[0])));
    return turn <= max_step;
  };
  std::vector<bool> smooth(n, false);  // smooth[i]: run i + 1 (mod n) follows run i smoothly on another circle
  for (std::size_t i = 0; i + 1 < n || (closed && n > 1 && i < n); ++i) {
    const std::size_t j = (i + 1) % n;
    if (drop[i] || drop[j]) continue;
    smooth[i] = smooth_join(i, j) && !same_circle(runs[i].circle, runs[j].circle, tol);
  }
  for (std::size_t i = 0; i < n; ++i)
    if (smooth[i]) drop[i] = drop[(i + 1) % n] = true;
  // Likewise a run that the polyline goes on from smoothly, turning on the same way at the first
  // vertex beyond it that is no run's (by a quarter of the run's step or more): the arc near an
  // ellipse's vertex, between the flatter stretches that fit no circle. A slot's or a rounded
  // rectangle's arc is followed by a straight line to the next arc; a hole's ends at a corner or
  // at the chain's end.
  const std::size_t m = q.size() - 1;
  std::vector<bool> in_run(q.size(), false);
  for (std::size_t i = 0; i < n; ++i)
    if (!drop[i])
      for (std::size_t k = runs[i].first; k <= runs[i].last; ++k) in_run[k] = true;
  if (closed) in_run[0] = in_run[m] = in_run[0] || in_run[m];
  auto at = [&](std::ptrdiff_t k) -> std::optional<std::size_t> {  // q's index k, cyclic if closed
    if (closed) return std::size_t(((k % std::ptrdiff_t(m)) + std::ptrdiff_t(m)) % std::ptrdiff_t(m));
    if (k < 0 || k > std::ptrdiff_t(m)) return std::nullopt;
    return std::size_t(k);
  };
  auto goes_on_turning = [&](const Run& r, std::ptrdiff_t v, std::ptrdiff_t towards) {
    const auto here = at(v), before = at(v - towards), after = at(v + towards);
    if (!here || !before || !after || in_run[*here]) return false;
    const Point2 &a = q[*before], &b = q[*here], &c = q[*after];
    const double turn = step_between(std::atan2(b[1] - a[1], b[0] - a[0]), std::atan2(c[1] - b[1], c[0] - b[0])) * double(towards);
    const double step = std::abs(r.sweep) / double(r.last - r.first);
    return turn * r.sweep > 0 && std::abs(turn) >= 0.25 * step && std::abs(turn) <= max_step;
  };
  for (std::size_t i = 0; i < n; ++i) {
    if (drop[i]) continue;
    const Run& r = runs[i];
    if (goes_on_turning(r, std::ptrdiff_t(r.last) + 1, 1) || goes_on_turning(r, std::ptrdiff_t(r.first) - 1, -1)) drop[i] = true;
  }
  std::vector<Run> kept;
  for (std::size_t i = 0; i < n; ++i)
    if (!drop[i]) kept.push_back(runs[i]);
  return kept;
}

DrawingPath straight_path(const DrawingPolyline& chain) {
  DrawingPath path;
  path.start = chain.points.front();
  path.closed = chain.closed;
  path.visible = chain.visible;
  path.thin = chain.thin;
  path.mesh = chain.mesh;
  for (std::size_t k = 1; k < chain.points.size(); ++k) path.steps.push_back({chain.points[k]});
  return path;
}

}  // namespace

bool has_thin_lines(const DrawingCurves& curves) {
  auto thin = [](const auto& item) { return item.thin; };
  return std::any_of(curves.paths.begin(), curves.paths.end(), thin) ||
         std::any_of(curves.circles.begin(), curves.circles.end(), thin) ||
         std::any_of(curves.ellipses.begin(), curves.ellipses.end(), thin);
}

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
        out.circles.push_back({{c->cx, c->cy}, c->r, chain.visible, chain.mesh, chain.thin});
        continue;
      }
      if (nearly_round(chain.points, tolerance)) {
        out.paths.push_back(straight_path(chain));
        continue;
      }
    }
    // The points to scan: a closed chain from its sharpest corner round to that corner again, and
    // then, if the first run ends before the chain does, from that run's end: where a circle
    // stops is a better start than a corner (a slot's lines meet its arcs without a corner).
    std::vector<Point2> q;
    std::vector<Run> runs;
    if (chain.closed) {
      const std::size_t n = chain.points.size();
      auto scan_from = [&](std::size_t s) {
        q.clear();
        for (std::size_t k = 0; k <= n; ++k) q.push_back(chain.points[(s + k) % n]);
        runs = ChainScanner(q, false, tolerance).runs();
      };
      const std::size_t s = sharpest_corner(chain.points);
      scan_from(s);
      if (!runs.empty() && runs[0].last < n) scan_from((s + runs[0].last) % n);
    } else {
      q = chain.points;
      runs = ChainScanner(q, true, tolerance).runs();
    }
    runs = without_bent_runs(std::move(runs), chain.closed, tolerance, q);
    if (runs.empty()) {
      out.paths.push_back(straight_path(chain));
      continue;
    }
    DrawingPath path;
    path.closed = chain.closed;
    path.visible = chain.visible;
    path.thin = chain.thin;
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

Point2 ellipse_point(const DrawingEllipse& e, double t) {
  const double c = std::cos(t), s = e.ratio * std::sin(t);
  return {e.centre[0] + c * e.major[0] - s * e.major[1], e.centre[1] + c * e.major[1] + s * e.major[0]};
}

}  // namespace hlr::exporter
