// attach_source_curves (hlr/export/lines.hpp) and draw_source_curves (source_curves.hpp): a CAD
// model's circles, carried from the B-rep (Mesh::source_curves) to the sheet.
#include "source_curves.hpp"

#include <hlr/kernel/mesh_edges.hpp>  // edge_key
#include <hlr/kernel/view_predicates.hpp>

#include <cmath>
#include <map>
#include <numbers>
#include <unordered_map>

namespace hlr::exporter {
namespace {

double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// Face-on: normal x direction = 0, each component a determinant of the input doubles, decided
// exactly by the kernel's view predicate (det[n, e_k, d] is component k of d x n).
bool parallel(const Vec3& normal, const Vec3& direction) {
  const Vec3 origin{0, 0, 0};
  for (int k = 0; k < 3; ++k) {
    Vec3 axis{0, 0, 0};
    axis[k] = 1;
    if (!collinear_in_view(origin, normal, axis, direction)) return false;
  }
  return true;
}

// Edge-on: normal . direction = 0, in rationals of the doubles.
bool orthogonal(const Vec3& normal, const Vec3& direction) {
  using Q = CGAL::Exact_rational;
  return CGAL::sign(Q(normal[0]) * Q(direction[0]) + Q(normal[1]) * Q(direction[1]) + Q(normal[2]) * Q(direction[2])) ==
         CGAL::ZERO;
}

ViewCurve view_curve(const SourceCurve& c, const ViewInfo& view, std::uint32_t mesh) {
  const auto& m = view.world_to_view;
  auto image = [&](const Vec3& p, double w) -> Point2 {  // w: 1 for a point, 0 for a vector
    return {m[0][0] * p[0] + m[0][1] * p[1] + m[0][2] * p[2] + w * m[0][3],
            m[1][0] * p[0] + m[1][1] * p[1] + m[1][2] * p[2] + w * m[1][3]};
  };
  ViewCurve v;
  v.mesh = mesh;
  v.centre = image(c.centre, 1);
  v.radius = c.radius;
  v.face_on = parallel(c.normal, view.direction);
  v.edge_on = !v.face_on && orthogonal(c.normal, view.direction);
  v.major = {c.radius, 0};
  if (!v.face_on && !v.edge_on) {
    // The diameter along n x d lies in the view plane: it is the major axis, seen at full length;
    // the one across it is foreshortened by |cos| of the angle between n and d.
    const Vec3& n = c.normal;
    const Vec3& d = view.direction;
    const Vec3 w{n[1] * d[2] - n[2] * d[1], n[2] * d[0] - n[0] * d[2], n[0] * d[1] - n[1] * d[0]};
    const double length = std::sqrt(dot(w, w));
    const Point2 axis = image(w, 0);
    v.major = {c.radius * axis[0] / length, c.radius * axis[1] / length};
    v.ratio = std::abs(dot(n, d)) / std::sqrt(dot(n, n) * dot(d, d));
  }
  return v;
}

// ezdxf (and AutoCAD) take ELLIPSE ratios from 1e-6: flatter ones are drawn as their polylines.
bool drawn_as_curve(const ViewCurve& c) { return c.face_on || (!c.edge_on && c.ratio >= 1e-6 && c.ratio <= 1); }

Point2 minus(const Point2& a, const Point2& b) { return {a[0] - b[0], a[1] - b[1]}; }
double cross(const Point2& a, const Point2& b) { return a[0] * b[1] - a[1] * b[0]; }

// The run's points as a path of lines (a run whose ends cannot be put on its curve).
DrawingPath straight_path(const DrawingPolyline& chain) {
  DrawingPath path;
  path.start = chain.points.front();
  for (std::size_t k = 1; k < chain.points.size(); ++k) path.steps.push_back({chain.points[k]});
  path.closed = chain.closed;
  path.visible = chain.visible;
  path.thin = chain.thin;
  path.mesh = chain.mesh;
  return path;
}

void add_run(const ViewCurve& c, const DrawingPolyline& chain, DrawingCurves& out) {
  const std::vector<Point2>& p = chain.points;
  // Which way the run goes round the centre.
  double turn = 0;
  for (std::size_t k = 0; k + 1 < p.size(); ++k) turn += cross(minus(p[k], c.centre), minus(p[k + 1], c.centre));
  if (chain.closed) turn += cross(minus(p.back(), c.centre), minus(p.front(), c.centre));
  const bool ccw = turn > 0;
  if (c.face_on) {
    if (chain.closed) {
      out.circles.push_back({c.centre, c.radius, chain.visible, chain.mesh, chain.thin});
      return;
    }
    auto on_circle = [&](const Point2& q, Point2& at) {
      const Point2 r = minus(q, c.centre);
      const double length = std::hypot(r[0], r[1]);
      if (!(length > 0) || !std::isfinite(length)) return false;
      at = {c.centre[0] + c.radius * r[0] / length, c.centre[1] + c.radius * r[1] / length};
      return true;
    };
    DrawingPath path;
    PathStep step;
    if (!on_circle(p.front(), path.start) || !on_circle(p.back(), step.to)) {
      out.paths.push_back(straight_path(chain));
      return;
    }
    step.arc = true, step.centre = c.centre, step.radius = c.radius, step.ccw = ccw;
    path.steps.push_back(step);
    path.visible = chain.visible;
    path.thin = chain.thin;
    path.mesh = chain.mesh;
    out.paths.push_back(std::move(path));
    ++out.arcs;
    return;
  }
  DrawingEllipse e{c.centre, c.major, c.ratio, 0, 2 * std::numbers::pi, chain.closed, chain.visible, chain.mesh, chain.thin};
  if (!chain.closed) {
    // The parameter of a point's direction from the centre: its coordinates along the major and
    // the minor axis, the minor one stretched to the major's length.
    const Point2 minor{-c.major[1], c.major[0]};
    auto parameter = [&](const Point2& q) {
      const Point2 r = minus(q, c.centre);
      return std::atan2((r[0] * minor[0] + r[1] * minor[1]) / c.ratio, r[0] * c.major[0] + r[1] * c.major[1]);
    };
    e.t0 = parameter(ccw ? p.front() : p.back());
    e.t1 = parameter(ccw ? p.back() : p.front());
    while (e.t1 <= e.t0) e.t1 += 2 * std::numbers::pi;
  }
  out.ellipses.push_back(e);
}

}  // namespace

void attach_source_curves(LineDrawing& drawing, const std::vector<Mesh>& meshes) {
  drawing.source_curves.clear();
  for (DrawingSegment& s : drawing.segments) s.curve = -1;
  // A circle seen in perspective is an ellipse whose centre is not the centre's image: left as
  // the polyline (and curves.hpp's recovery).
  if (drawing.view.eye) return;
  std::vector<std::unordered_map<std::uint64_t, std::int32_t>> curve_of_edge(meshes.size());
  for (std::uint32_t m = 0; m < meshes.size(); ++m)
    for (const SourceCurve& c : meshes[m].source_curves) {
      const auto index = std::int32_t(drawing.source_curves.size());
      drawing.source_curves.push_back(view_curve(c, drawing.view, m));
      for (std::size_t k = 0; k + 1 < c.vertices.size(); ++k)
        curve_of_edge[m][edge_key(c.vertices[k], c.vertices[k + 1])] = index;
    }
  if (drawing.source_curves.empty()) return;
  // A segment's line is a mesh edge when its pieces name one.
  std::unordered_map<std::uint32_t, std::int32_t> curve_of_line;
  for (const DrawingPiece& piece : drawing.pieces) {
    if (!piece.has_edge || piece.mesh >= meshes.size()) continue;
    const auto& edges = curve_of_edge[piece.mesh];
    const auto it = edges.find(edge_key(piece.edge[0], piece.edge[1]));
    if (it != edges.end()) curve_of_line.emplace(piece.line, it->second);
  }
  for (DrawingSegment& s : drawing.segments) {
    const auto it = curve_of_line.find(s.line);
    if (it != curve_of_line.end() && drawing.source_curves[std::size_t(it->second)].mesh == s.mesh) s.curve = it->second;
  }
}

namespace detail {

std::vector<DrawingSegment> draw_source_curves(const LineDrawing& drawing, const std::vector<DrawingSegment>& segments,
                                               DrawingCurves& curves) {
  std::vector<DrawingSegment> rest;
  std::map<std::pair<std::int32_t, int>, std::vector<DrawingSegment>> runs;  // (curve, precedence_rank)
  for (const DrawingSegment& s : segments) {
    if (s.curve >= 0 && drawn_as_curve(drawing.source_curves[std::size_t(s.curve)]))
      runs[{s.curve, precedence_rank(s)}].push_back(s);
    else rest.push_back(s);
  }
  for (const auto& [key, run] : runs)
    for (const DrawingPolyline& chain : chain_segments(run)) add_run(drawing.source_curves[std::size_t(key.first)], chain, curves);
  return rest;
}

}  // namespace detail
}  // namespace hlr::exporter
