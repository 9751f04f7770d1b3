// intersection_lines (hlr/hidden_line/lines.hpp): where faces penetrate, in model space, exactly.
//
// Candidate pairs are the faces whose 3D bounding boxes overlap (overlapping_box_pairs). A pair
// can only cross when each face has corners strictly on both sides of the other's plane (exact
// orientation predicates on the input doubles), which rejects neighbours that merely share an edge
// or a corner and faces that only touch. Two triangles each cut an open chord from the line where their
// planes meet, with ends built from the input doubles (TriangleChords), and the chords overlap.
// For other faces, that line is intersected with the relative interior of each face in the face's
// own plane (projected along the normal's largest axis), and the two interval sets, measured with
// one parameter along the line, are intersected. Both the pair search and the pieces run on as
// many threads as are allowed, with the same result for any number.
#include "lines_impl.hpp"
#include "sources_impl.hpp"

#include <hlr/hidden_line/lines.hpp>
#include <hlr/kernel/filtered_sign.hpp>
#include <hlr/kernel/plane_side.hpp>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/box_intersection_d.h>

#include <tbb/enumerable_thread_specific.h>
#include <tbb/global_control.h>
#include <tbb/parallel_sort.h>

#include <array>
#include <cmath>
#include <iterator>
#include <map>
#include <numbers>
#include <stdexcept>
#include <tuple>

namespace hlr::hidden_line {
namespace {

using EK = CGAL::Exact_predicates_exact_constructions_kernel;
using IK = CGAL::Exact_predicates_inexact_constructions_kernel;  // predicates on input doubles only
using FT = EK::FT;
using G = Geometry<ExactKernel>;

struct FaceRef {
  std::uint32_t mesh, face;
};

using Interval = std::pair<FT, FT>;

// An input vertex as a point of Kernel: IK for predicates on the input doubles, EK to construct.
template <class Kernel>
typename Kernel::Point_3 input_point(const Mesh& mesh, std::uint32_t v) {
  const auto& c = mesh.vertices[v];
  return typename Kernel::Point_3(c[0], c[1], c[2]);
}

// The open intervals of parameters t for which p + t d lies in the relative interior of the face,
// with intervals that meet at a point joined (the line runs on through a corner or along a
// internal boundary point of the face).
std::vector<Interval> interior_intervals(const Mesh& mesh, const std::vector<std::uint32_t>& face,
                                         const EK::Vector_3& normal, const EK::Point_3& p, const EK::Vector_3& d) {
  // Drop the axis of the normal's largest component: the projection is one-to-one on the plane.
  int drop = 0;
  for (int k = 1; k < 3; ++k)
    if (std::abs(G::rough_double(normal[k])) > std::abs(G::rough_double(normal[drop]))) drop = k;
  if (CGAL::is_zero(normal[drop]))
    for (int k = 0; k < 3; ++k)
      if (!CGAL::is_zero(normal[k])) drop = k;
  const int u = (drop + 1) % 3, v = (drop + 2) % 3;
  auto project = [&](const EK::Point_3& q) { return EK::Point_2(q[u], q[v]); };
  clip::Polygon<EK> polygon;
  for (std::uint32_t vi : face) polygon.outer.points.push_back(project(input_point<EK>(mesh, vi)));
  // The image of p + t d has parameter t along the image line.
  const detail::ImageLine<EK> line(project(p), project(p + d));
  auto edge = [](const clip::Contour<EK>& c, std::size_t i) {
    return std::pair<const EK::Point_2&, const EK::Point_2&>(c.points[i], c.points[(i + 1) % c.size()]);
  };
  detail::PlainParams<EK, decltype(edge)> params{line, edge};
  return detail::inside_intervals(line, polygon, params, false, false);
}

// Whether face g has corners strictly on both sides of the plane of face f. Corners g shares with f
// (same mesh, same vertex) lie in f's plane: they are skipped rather than sent to the exact
// fallback of the predicate, which is where neighbouring faces would spend their time.
bool straddles(const Mesh& mesh_g, const std::vector<std::uint32_t>& g, const std::vector<std::uint32_t>* f_corners,
               const IK::Point_3& a, const IK::Point_3& b, const IK::Point_3& c) {
  bool below = false, above = false;
  for (std::uint32_t v : g) {
    if (f_corners && std::find(f_corners->begin(), f_corners->end(), v) != f_corners->end()) continue;
    const auto o = CGAL::orientation(a, b, c, input_point<IK>(mesh_g, v));
    below |= o == CGAL::NEGATIVE;
    above |= o == CGAL::POSITIVE;
  }
  return below && above;
}

// What the pair test reads of a face, in one record: the pair search visits faces in the order of
// their boxes, far from the meshes' order, and a record is two cache lines where the meshes'
// arrays (faces, vertices, coplanar groups) are about a dozen.
struct FaceRecord {
  std::array<Vec3, 3> corner;  // a triangle's corners in order; another face's plane_vertices
  std::array<std::uint32_t, 3> vertex;
  std::uint32_t mesh, group;
  bool triangle;
};

// Whether triangle g has corners strictly on both sides of f_plane, the plane of triangle f, with
// the side of each corner in `side`; corners g shares with f (same mesh, same vertex) lie in that
// plane (side 0) and are not tested.
bool straddles(const PlaneSide& f_plane, const FaceRecord& g, const FaceRecord& f, std::array<int, 3>& side) {
  const bool same_mesh = f.mesh == g.mesh;
  bool below = false, above = false;
  for (int k = 0; k < 3; ++k) {
    const bool shared =
        same_mesh && (g.vertex[k] == f.vertex[0] || g.vertex[k] == f.vertex[1] || g.vertex[k] == f.vertex[2]);
    side[k] = shared ? 0 : f_plane(g.corner[k]);
    below |= side[k] < 0;
    above |= side[k] > 0;
  }
  return below && above;
}

// Two triangles (v, f1, f2) and (v, g1, g2) sharing the corner v, each with its other two corners
// strictly on both sides of the other's plane: their planes meet in a line through v, and each
// triangle covers one ray of it from v. They cross (share a stretch of positive length inside
// both) exactly when the rays agree, that is when q, the point where f1 f2 meets g's plane, lies
// strictly on g2's side of the line v g1 within g's plane. With u = g1 - v, n = u x (g2 - v),
// d(x) = (x - v).n and h(x) = (u x (x - v)).n, that is sign((d1 h(f2) - d2 h(f1)) / (d1 - d2)) > 0.
// Written for any number type: filtered_sign (kernel/) decides it on intervals first.
template <class NT>
auto shared_corner_sign(const Vec3& v, const Vec3& f1, const Vec3& f2, const Vec3& g1,
                                              const Vec3& g2) {
  using V = std::array<NT, 3>;
  // Explicit result types: gmpxx's expression templates must not outlive a lambda's temporaries.
  auto sub = [](const Vec3& a, const Vec3& b) -> V { return V{NT(a[0]) - NT(b[0]), NT(a[1]) - NT(b[1]), NT(a[2]) - NT(b[2])}; };
  auto cross = [](const V& a, const V& b) -> V {
    return V{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  };
  auto dot = [](const V& a, const V& b) -> NT { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
  const V u = sub(g1, v), n = cross(u, sub(g2, v));
  const V r1 = sub(f1, v), r2 = sub(f2, v);
  const NT d1 = dot(r1, n), d2 = dot(r2, n);
  const NT h1 = dot(cross(u, r1), n), h2 = dot(cross(u, r2), n);
  const NT num = d1 * h2 - d2 * h1, den = d1 - d2;
  return CGAL::sign(num) * CGAL::sign(den);
}

// The first axis along which the line where two planes meet is not constant (each plane through
// three input points, the planes not parallel): along that line, the lexicographic order of
// points is the order of this coordinate. The line's direction is n x m, n and m the normals.
int line_axis(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& p, const Vec3& q, const Vec3& r) {
  for (int k = 0; k < 2; ++k) {
    const CGAL::Sign s = filtered_sign([&](auto nt) {
      using NT = typename decltype(nt)::type;
      auto normal = [](const Vec3& a, const Vec3& b, const Vec3& c, int i) -> NT {
        const int j = (i + 1) % 3, l = (i + 2) % 3;
        return (NT(b[j]) - NT(a[j])) * (NT(c[l]) - NT(a[l])) - (NT(b[l]) - NT(a[l])) * (NT(c[j]) - NT(a[j]));
      };
      const int j = (k + 1) % 3, l = (k + 2) % 3;
      const NT d = normal(a, b, c, j) * normal(p, q, r, l) - normal(a, b, c, l) * normal(p, q, r, j);
      return CGAL::sign(d);
    });
    if (s != CGAL::ZERO) return k;
  }
  return 2;
}

// The order of two points of a line along `axis`, an axis the line is not constant along
// (line_axis): their lexicographic order. Points on such a line that share a coordinate of an
// axis it is constant along (all of them, in CAD models' axis-aligned planes) need no exact
// arithmetic to be told apart; copies of one lazy point are equal without any.
CGAL::Comparison_result compare_on_line(const EK::Point_3& p, const EK::Point_3& q, int axis) {
  if (p.id() == q.id()) return CGAL::EQUAL;
  return axis == 0 ? CGAL::compare_x(p, q) : axis == 1 ? CGAL::compare_y(p, q) : CGAL::compare_z(p, q);
}

bool crosses_at_shared_corner(const Vec3& v, const Vec3& f1, const Vec3& f2, const Vec3& g1, const Vec3& g2) {
  return filtered_sign([&](auto nt) {
           return shared_corner_sign<typename decltype(nt)::type>(v, f1, f2, g1, g2);
         }) == CGAL::POSITIVE;
}

}  // namespace

namespace {
// The angle between two planes with these normals, in degrees in [0, 90], in double (output only:
// the sheet leaves off lines where surfaces meet at a small angle).
double angle_between(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  const double cross = std::hypot(a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]);
  const double dot = std::abs(a[0] * b[0] + a[1] * b[1] + a[2] * b[2]);
  return std::atan2(cross, dot) * 180 / std::numbers::pi;
}
// (q - p) x (r - p) in double, for angle_between: no lazy plane for the many pairs of triangles.
std::array<double, 3> rough_normal(const Vec3& p, const Vec3& q, const Vec3& r) {
  const double u[3] = {q[0] - p[0], q[1] - p[1], q[2] - p[2]}, v[3] = {r[0] - p[0], r[1] - p[1], r[2] - p[2]};
  return {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
}

// Where the boundary of a triangle meets the plane of a face it straddles: two points, corners in
// the plane or crossings of edges with it, in lexicographic order (the order along the line the
// two planes meet in). Built from the input doubles, not from that line: a crossing of edge i j
// is c_i + t (c_j - c_i) with t = s_i / (s_i - s_j), s the signed volumes against the plane,
// exactly. Such a point is a lazy leaf (lazy_point, kernel/exact_output.hpp): its intervals now,
// its exact coordinates only for the few predicates that need them, never a chain of plane, line
// and interval constructions. A crossing shared by the triangles on both sides of an edge is
// built once per plane, so that the two are one point.
class TriangleChords {
 public:
  using I = CGAL::Interval_nt<false>;
  explicit TriangleChords(const std::vector<Mesh>& meshes) : meshes_(meshes) {}

  // An end of a chord: how it is built, and its coordinates as intervals, which order most ends
  // without building them (two triangles' chords give four ends, of which two are kept).
  struct End {
    ModelPointRecipe recipe;
    std::uint32_t mesh = 0, u = 0, w = 0;  // an edge crossing: the edge u w of mesh
    std::uint64_t plane_id = 0;
    std::array<I, 3> at;
  };

  // Triangle `face` of mesh `mesh` against the plane through a, b, c (three input points, not
  // collinear), known to have corners strictly on both sides of it; `plane_id` names the plane
  // (equal ids: one plane) for sharing crossings. The two ends in lexicographic order.
  std::array<End, 2> chord(std::uint32_t mesh, std::uint32_t face, const Vec3& a, const Vec3& b, const Vec3& c,
                           std::uint64_t plane_id, int axis) {
    const Mesh& m = meshes_[mesh];
    const auto& t = m.faces[face];
    const PlaneSide plane(a, b, c);
    int side[3];
    for (int k = 0; k < 3; ++k) side[k] = plane(m.vertices[t[k]]);
    std::array<End, 2> out;
    int n = 0;
    {
      CGAL::Protect_FPU_rounding<true> protect;  // for the intervals, after the exact sides
      const std::array<I, 3> normal = interval_normal(a, b, c);
      std::array<I, 3> volume;  // of the corners against the plane
      for (int k = 0; k < 3; ++k) volume[k] = interval_volume(a, normal, m.vertices[t[k]]);
      for (int k = 0; k < 3 && n < 2; ++k) {
        const int l = (k + 1) % 3;
        if (side[k] == 0) out[n++] = end_at_vertex(mesh, t[k]);
        else if (side[k] * side[l] < 0) out[n++] = end_at_crossing(mesh, t[k], t[l], volume[k], volume[l], a, b, c, plane_id);
      }
    }
    if (n != 2) throw std::logic_error("a triangle straddling a plane did not meet it in two points");
    if (compare(out[1], out[0], axis) == CGAL::SMALLER) std::swap(out[0], out[1]);
    return out;
  }

  // The lexicographic order of two ends on one line, whose coordinate `axis` is not constant
  // (line_axis): the order of that coordinate, on the intervals where they decide, else exactly.
  CGAL::Comparison_result compare(const End& x, const End& y, int axis) {
    const I &p = x.at[axis], &q = y.at[axis];
    if (p.sup() < q.inf()) return CGAL::SMALLER;
    if (p.inf() > q.sup()) return CGAL::LARGER;
    if (p.is_point() && q.is_point()) return CGAL::EQUAL;  // equal doubles
    return compare_on_line(point(x), point(y), axis);
  }

  // The end as an exact point (a lazy one for a crossing), one per chunk for each input vertex
  // and each crossing of an edge with a plane: ends that are one point are one lazy point.
  EK::Point_3 point(const End& e) {
    const ModelPointRecipe& r = e.recipe;
    const bool vertex = r.kind == ModelPointRecipe::Kind::input_point;
    // A vertex's key has u = w and plane 0, which no crossing's has (its edge has two ends).
    auto [it, added] = ends_.try_emplace({edge_key(e.u, e.w), vertex ? 0 : e.plane_id, e.mesh});
    if (added)
      it->second = vertex ? EK::Point_3(r.u[0], r.u[1], r.u[2]) : lazy_point(r, e.at);
    return it->second;
  }

 private:
  End end_at_vertex(std::uint32_t mesh, std::uint32_t u) const {
    const Vec3& p = meshes_[mesh].vertices[u];
    return {{ModelPointRecipe::Kind::input_point, p}, mesh, u, u, 0, {I(p[0]), I(p[1]), I(p[2])}};
  }
  // u + t (w - u) with t = s_u / (s_u - s_w), s the volumes against the plane (under upward
  // rounding).
  End end_at_crossing(std::uint32_t mesh, std::uint32_t u, std::uint32_t w, const I& su, const I& sw,
                      const Vec3& a, const Vec3& b, const Vec3& c, std::uint64_t plane_id) const {
    const Vec3 &pu = meshes_[mesh].vertices[u], &pw = meshes_[mesh].vertices[w];
    const I den = su - sw;
    std::array<I, 3> at;
    for (int j = 0; j < 3; ++j) at[j] = (su * I(pw[j]) - sw * I(pu[j])) / den;
    return {{ModelPointRecipe::Kind::edge_crossing, pu, pw, a, b, c}, mesh, u, w, plane_id, at};
  }

  // On intervals (under upward rounding): the plane's normal (b - a) x (c - a), made once per
  // plane, and the volume (p - a) . normal of a point against it.
  static std::array<I, 3> interval_normal(const Vec3& a, const Vec3& b, const Vec3& c) {
    const I ux = I(b[0]) - a[0], uy = I(b[1]) - a[1], uz = I(b[2]) - a[2];
    const I vx = I(c[0]) - a[0], vy = I(c[1]) - a[1], vz = I(c[2]) - a[2];
    return {uy * vz - uz * vy, uz * vx - ux * vz, ux * vy - uy * vx};
  }
  static I interval_volume(const Vec3& a, const std::array<I, 3>& normal, const Vec3& p) {
    return (I(p[0]) - a[0]) * normal[0] + (I(p[1]) - a[1]) * normal[1] + (I(p[2]) - a[2]) * normal[2];
  }

  const std::vector<Mesh>& meshes_;
  std::map<std::tuple<std::uint64_t, std::uint64_t, std::uint32_t>, EK::Point_3> ends_;  // point(): (edge, plane, mesh)
};

}  // namespace

std::vector<IntersectionSegment> intersection_lines(const std::vector<Mesh>& meshes, StopToken stop) {
  std::vector<detail::MeshTopology> topo;
  for (const Mesh& m : meshes) topo.push_back(detail::analyse_mesh(m));

  using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 3, std::size_t>;
  std::vector<FaceRef> faces;
  std::size_t face_count = 0;
  for (const Mesh& m : meshes) face_count += m.faces.size();
  faces.reserve(face_count);
  for (std::uint32_t mi = 0; mi < meshes.size(); ++mi)
    for (std::uint32_t f = 0; f < meshes[mi].faces.size(); ++f) faces.push_back({mi, f});
  std::vector<Box> boxes(faces.size());
  parallel_chunks(faces.size(), 4096, [&](const auto& range) {
    for (std::size_t i = range.begin(); i != range.end(); ++i) {
      const Mesh& m = meshes[faces[i].mesh];
      const auto& corners = m.faces[faces[i].face];
      double lo[3], hi[3];
      for (int k = 0; k < 3; ++k) lo[k] = hi[k] = m.vertices[corners[0]][k];
      for (std::uint32_t v : corners)
        for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], m.vertices[v][k]), hi[k] = std::max(hi[k], m.vertices[v][k]);
      boxes[i] = Box(CGAL::Bbox_3(lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]), i);
    }
  });

  std::vector<FaceRecord> records(faces.size());
  parallel_chunks(faces.size(), 4096, [&](const auto& range) {
    for (std::size_t i = range.begin(); i != range.end(); ++i) {
      const FaceRef r = faces[i];
      const Mesh& m = meshes[r.mesh];
      const auto& corners = m.faces[r.face];
      FaceRecord& rec = records[i];
      rec.triangle = corners.size() == 3;
      rec.vertex = rec.triangle ? std::array{corners[0], corners[1], corners[2]} : topo[r.mesh].plane_vertices[r.face];
      for (int k = 0; k < 3; ++k) rec.corner[k] = m.vertices[rec.vertex[k]];
      rec.mesh = r.mesh;
      rec.group = topo[r.mesh].coplanar_group[r.face];
    }
  });
  auto ipoint = [&](const FaceRecord& r, int k) { return IK::Point_3(r.corner[k][0], r.corner[k][1], r.corner[k][2]); };
  // Faces with more corners than three: all their corners against the other's plane.
  auto polygons_cross = [&](const FaceRef& f, const FaceRef& g, const FaceRecord& rf, const FaceRecord& rg) {
    const auto& fc = meshes[f.mesh].faces[f.face];
    const auto& gc = meshes[g.mesh].faces[g.face];
    const bool same_mesh = f.mesh == g.mesh;
    return straddles(meshes[g.mesh], gc, same_mesh ? &fc : nullptr, ipoint(rf, 0), ipoint(rf, 1), ipoint(rf, 2)) &&
           straddles(meshes[f.mesh], fc, same_mesh ? &gc : nullptr, ipoint(rg, 0), ipoint(rg, 1), ipoint(rg, 2));
  };
  auto crosses = [&](std::size_t i, std::size_t j) {
    const FaceRecord &f = records[i], &g = records[j];
    const bool same_mesh = f.mesh == g.mesh;
    // Faces of one coplanar group never cross, and their corners would all be exact zeros.
    if (same_mesh && f.group == g.group) return false;
    if (!f.triangle || !g.triangle) return polygons_cross(faces[i], faces[j], f, g);
    const auto &fc = f.vertex, &gc = g.vertex;
    // Triangles with an edge in common meet in that edge only, whatever their planes: a quarter of
    // the candidate pairs on a mesh.
    if (same_mesh &&
        (fc[0] == gc[0] || fc[0] == gc[1] || fc[0] == gc[2]) + (fc[1] == gc[0] || fc[1] == gc[1] || fc[1] == gc[2]) +
                (fc[2] == gc[0] || fc[2] == gc[1] || fc[2] == gc[2]) >= 2)
      return false;
    std::array<int, 3> f_side, g_side;  // f's corners against g's plane, g's against f's
    if (!straddles(PlaneSide(f.corner[0], f.corner[1], f.corner[2]), g, f, g_side) ||
        !straddles(PlaneSide(g.corner[0], g.corner[1], g.corner[2]), f, g, f_side))
      return false;
    // The exact overlap test (predicates on the input points only) spares the constructions for
    // the many curved-surface neighbours that straddle each other's planes but do not meet.
    if (same_mesh) {
      // Neighbours around a corner straddle each other's planes all over curved surfaces; they
      // cross only if the two rays of their intersection line from the shared corner agree.
      for (int p = 0; p < 3; ++p)
        for (int q = 0; q < 3; ++q)
          if (fc[p] == gc[q])
            return crosses_at_shared_corner(f.corner[p], f.corner[(p + 1) % 3], f.corner[(p + 2) % 3],
                                            g.corner[(q + 1) % 3], g.corner[(q + 2) % 3]);
    }
    auto off_plane = [](const std::array<int, 3>& side) { return side[0] != 0 && side[1] != 0 && side[2] != 0; };
    if (off_plane(f_side) && off_plane(g_side)) return triangles_meet(f.corner, f_side, g.corner, g_side);
    return CGAL::do_intersect(IK::Triangle_3(ipoint(f, 0), ipoint(f, 1), ipoint(f, 2)),
                              IK::Triangle_3(ipoint(g, 0), ipoint(g, 1), ipoint(g, 2)));
  };
  // The candidate pairs that cross, sorted: the callback runs on several threads when more than
  // one is allowed, so each collects its own and the sort makes the order one.
  struct Found {
    std::vector<std::pair<std::size_t, std::size_t>> pairs;
    std::size_t polls = 0;
  };
  // A thread's own Found is looked up per pair: a key of its own makes that a native TLS read.
  tbb::enumerable_thread_specific<Found, tbb::cache_aligned_allocator<Found>, tbb::ets_key_per_instance> found;
  const bool parallel = tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism) > 1;
  Found* const alone = parallel ? nullptr : &found.local();  // spares a thread-local lookup per pair
  auto test_boxes = [&](const Box& x, const Box& y) {
    Found& mine = alone ? *alone : found.local();
    stop.check_every(mine.polls, 4096);
    const std::size_t i = std::min(x.info(), y.info()), j = std::max(x.info(), y.info());
    if (crosses(i, j)) mine.pairs.emplace_back(i, j);
  };
  // The sweep runs along the axis that the faces' boxes are shortest along, on average, in parts
  // of the scene's extent: a box long along the sweep meets every box of its column over its
  // length (bench/box_pairs/box_pairs_bench.cpp times the three).
  int axis = 0;
  {
    double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL}, length[3] = {0, 0, 0};
    for (const Box& b : boxes)
      for (int k = 0; k < 3; ++k) {
        lo[k] = std::min(lo[k], b.min_coord(k)), hi[k] = std::max(hi[k], b.max_coord(k));
        length[k] += b.max_coord(k) - b.min_coord(k);
      }
    double best = HUGE_VAL;
    for (int k = 0; k < 3; ++k)
      if (const double share = length[k] / (hi[k] - lo[k]); share < best) best = share, axis = k;
  }
  detail::overlapping_box_pairs(boxes, axis, test_boxes);
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  for (const Found& f : found) pairs.insert(pairs.end(), f.pairs.begin(), f.pairs.end());
  tbb::parallel_sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());

  // Pieces of one pair of coplanar groups lie on one line; they are joined below.
  using GroupPair = std::tuple<std::uint32_t, std::uint32_t, std::uint32_t, std::uint32_t>;
  struct Piece {
    EK::Point_3 a, b;  // a < b lexicographically
    std::uint32_t face_a, face_b;
    double meeting_degrees;
  };
  auto plane_corner = [&](const FaceRef& r, int k) -> const Vec3& {
    return meshes[r.mesh].vertices[topo[r.mesh].plane_vertices[r.face][k]];
  };
  auto rough_normal_of = [&](const FaceRef& r) {
    return rough_normal(plane_corner(r, 0), plane_corner(r, 1), plane_corner(r, 2));
  };
  auto plane_of = [&](const FaceRef& r) {
    auto point = [&](int k) {
      const Vec3& c = plane_corner(r, k);
      return EK::Point_3(c[0], c[1], c[2]);
    };
    return EK::Plane_3(point(0), point(1), point(2));
  };
  // line_axis of the line where the planes of two faces meet.
  auto axis_of = [&](const FaceRef& f, const FaceRef& g) {
    return line_axis(plane_corner(f, 0), plane_corner(f, 1), plane_corner(f, 2), plane_corner(g, 0), plane_corner(g, 1),
                     plane_corner(g, 2));
  };
  // The pairs in fixed chunks, each with its own crossings (pairs are sorted, so the triangles
  // around one edge mostly fall in one chunk), gathered in chunk order: the same pieces in the
  // same order, built the same way, for any number of threads.
  constexpr std::size_t kPairsPerChunk = 2048;
  const std::size_t chunk_count = (pairs.size() + kPairsPerChunk - 1) / kPairsPerChunk;
  std::vector<std::vector<std::pair<GroupPair, Piece>>> chunk_pieces(chunk_count);
  parallel_chunks(chunk_count, 1, [&](const auto& range) {
    for (std::size_t chunk = range.begin(); chunk != range.end(); ++chunk) {
      TriangleChords chords(meshes);
      std::size_t polls = 0;
      auto& out = chunk_pieces[chunk];
      const std::size_t end = std::min(pairs.size(), (chunk + 1) * kPairsPerChunk);
      for (std::size_t k = chunk * kPairsPerChunk; k < end; ++k) {
        stop.check_every(polls, 256);
        FaceRef f = faces[pairs[k].first], g = faces[pairs[k].second];
        // One key per pair of groups, whichever face came first.
        if (std::pair(g.mesh, topo[g.mesh].coplanar_group[g.face]) < std::pair(f.mesh, topo[f.mesh].coplanar_group[f.face]))
          std::swap(f, g);
        const GroupPair key{f.mesh, topo[f.mesh].coplanar_group[f.face], g.mesh, topo[g.mesh].coplanar_group[g.face]};
        const double meeting_degrees = angle_between(rough_normal_of(f), rough_normal_of(g));
        if (meshes[f.mesh].faces[f.face].size() == 3 && meshes[g.mesh].faces[g.face].size() == 3) {
          // Two triangles: the open chords each cuts from the line of the two planes, overlapped.
          const int axis = axis_of(f, g);
          auto chord = [&](const FaceRef& t, const FaceRef& other) {
            const std::uint64_t plane_id = (std::uint64_t(other.mesh) << 32) | topo[other.mesh].coplanar_group[other.face];
            return chords.chord(t.mesh, t.face, plane_corner(other, 0), plane_corner(other, 1), plane_corner(other, 2),
                                plane_id, axis);
          };
          const auto in_f = chord(f, g), in_g = chord(g, f);
          const auto& lo = chords.compare(in_f[0], in_g[0], axis) == CGAL::LARGER ? in_f[0] : in_g[0];
          const auto& hi = chords.compare(in_f[1], in_g[1], axis) == CGAL::SMALLER ? in_f[1] : in_g[1];
          if (chords.compare(lo, hi, axis) == CGAL::SMALLER)
            out.push_back({key, {chords.point(lo), chords.point(hi), f.face, g.face, meeting_degrees}});
          continue;
        }
        const EK::Plane_3 pf = plane_of(f), pg = plane_of(g);
        const auto meet = CGAL::intersection(pf, pg);
        if (!meet) continue;
        const EK::Line_3* line = boost::get<EK::Line_3>(&*meet);  // CGAL 5: boost::variant
        if (!line) continue;
        const EK::Point_3 p = line->point();
        const EK::Vector_3 d = line->to_vector();
        const auto in_f = interior_intervals(meshes[f.mesh], meshes[f.mesh].faces[f.face], pf.orthogonal_vector(), p, d);
        const auto in_g = interior_intervals(meshes[g.mesh], meshes[g.mesh].faces[g.face], pg.orthogonal_vector(), p, d);
        for (const Interval& x : in_f)
          for (const Interval& y : in_g) {
            const FT lo = CGAL::max(x.first, y.first), hi = CGAL::min(x.second, y.second);
            if (!(lo < hi)) continue;
            EK::Point_3 a = p + lo * d, b = p + hi * d;
            if (CGAL::compare_xyz(b, a) == CGAL::SMALLER) std::swap(a, b);
            out.push_back({key, {a, b, f.face, g.face, meeting_degrees}});
          }
      }
    }
  });
  // The pieces of each pair of groups, in chunk order: references sorted by key, then by their
  // place in chunk order (a stable sort, on every thread).
  struct Keyed {
    GroupPair key;
    std::uint32_t place;
    const Piece* piece;
  };
  std::vector<Keyed> by_group;
  std::size_t pieces = 0;
  for (const auto& chunk : chunk_pieces) pieces += chunk.size();
  by_group.reserve(pieces);
  for (const auto& chunk : chunk_pieces)
    for (const auto& [key, piece] : chunk) by_group.push_back({key, std::uint32_t(by_group.size()), &piece});
  tbb::parallel_sort(by_group.begin(), by_group.end(),
                     [](const Keyed& x, const Keyed& y) { return std::tie(x.key, x.place) < std::tie(y.key, y.place); });
  std::vector<std::size_t> run_starts;  // where each pair of groups begins in by_group, and its end
  for (std::size_t k = 0; k < by_group.size(); ++k)
    if (k == 0 || by_group[k].key != by_group[k - 1].key) run_starts.push_back(k);
  run_starts.push_back(by_group.size());

  // Join the pieces of each group pair where they meet or overlap (points along one line are
  // ordered lexicographically). Pairs of groups are joined side by side in fixed chunks, gathered
  // in key order.
  constexpr std::size_t kRunsPerChunk = 1024;
  const std::size_t runs = run_starts.size() - 1;
  std::vector<std::vector<IntersectionSegment>> joined((runs + kRunsPerChunk - 1) / kRunsPerChunk);
  parallel_chunks(joined.size(), 1, [&](const auto& range) {
    std::vector<const Piece*> list;
    for (std::size_t chunk = range.begin(); chunk != range.end(); ++chunk) {
      stop.check();
      for (std::size_t r = chunk * kRunsPerChunk; r < std::min(runs, (chunk + 1) * kRunsPerChunk); ++r) {
        const GroupPair& key = by_group[run_starts[r]].key;
        list.clear();
        for (std::size_t k = run_starts[r]; k < run_starts[r + 1]; ++k) list.push_back(by_group[k].piece);
        // All on the line where the two groups' planes meet.
        const int axis = axis_of({std::get<0>(key), list.front()->face_a}, {std::get<2>(key), list.front()->face_b});
        auto compare = [axis](const EK::Point_3& p, const EK::Point_3& q) { return compare_on_line(p, q, axis); };
        std::sort(list.begin(), list.end(), [&](const Piece* x, const Piece* y) { return compare(x->a, y->a) == CGAL::SMALLER; });
        for (std::size_t k = 0; k < list.size();) {
          const Piece& first = *list[k];
          IntersectionSegment s{first.a,          first.b,          std::get<0>(key),      std::get<2>(key),
                                {first.face_a}, {first.face_b}, first.meeting_degrees};
          for (++k; k < list.size() && compare(list[k]->a, s.b) != CGAL::LARGER; ++k) {
            if (compare(list[k]->b, s.b) == CGAL::LARGER) s.b = list[k]->b;
            s.faces_a.push_back(list[k]->face_a);
            s.faces_b.push_back(list[k]->face_b);
          }
          for (auto* fs : {&s.faces_a, &s.faces_b}) {
            std::sort(fs->begin(), fs->end());
            fs->erase(std::unique(fs->begin(), fs->end()), fs->end());
          }
          joined[chunk].push_back(std::move(s));
        }
      }
    }
  });
  std::vector<IntersectionSegment> out;
  std::size_t total = 0;
  for (const auto& j : joined) total += j.size();
  out.reserve(total);
  for (auto& j : joined) std::move(j.begin(), j.end(), std::back_inserter(out));
  // The kept ends made again, one per point, while every point the chunks made is still held (by
  // chunk_pieces, freed on return): joining dropped about 200,000 of the 700,000 made at 1M faces,
  // and their reps (200 bytes each) would otherwise stay free among the kept ones' pages for the
  // rest of the run (39 MB at 1M faces). The search's other arrays are freed first, so that the
  // new reps take their pages.
  std::vector<Box>().swap(boxes);
  std::vector<FaceRef>().swap(faces);
  std::vector<FaceRecord>().swap(records);
  std::vector<std::pair<std::size_t, std::size_t>>().swap(pairs);
  std::vector<Keyed>().swap(by_group);
  std::vector<std::vector<IntersectionSegment>>().swap(joined);
  auto ends = detail::ends_by_point(out);
  auto end_point = [&](std::uint32_t end) -> EK::Point_3& { return end % 2 == 0 ? out[end / 2].a : out[end / 2].b; };
  detail::for_each_run_of_one_key(ends, 4096, stop, [&](auto run) {
    const EK::Point_3 point = remade(end_point(run.front().second));
    for (const auto& [id, end] : run) end_point(end) = point;
  });
  return out;
}

}  // namespace hlr::hidden_line
