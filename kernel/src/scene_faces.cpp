// Welding and face preparation on import (scene_faces.hpp), exact on the input doubles: Epick's
// exact predicates decide collinearity and coplanarity in 3D, and simplicity and the triangulation
// in a plane the face projects to without loss (coordinate axes dropped, nothing constructed).
#include "scene_faces.hpp"

#include "scene_readers.hpp"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2_algorithms.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include <algorithm>
#include <set>
#include <utility>

namespace hlr::scene_detail {

std::vector<std::uint32_t> weld_vertices(const std::vector<std::array<double, 3>>& vertices) {
  // Sorted by coordinates and then by index, equal coordinates are a run that starts with the
  // first of them: a sort on every thread rather than a hash table filled on one (1M vertices:
  // 0.18 s in a table).
  struct Keyed {
    std::array<double, 3> at;
    std::uint32_t v;
  };
  const std::size_t n = vertices.size();
  std::vector<Keyed> keyed(n);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 16384), [&](const auto& range) {
    for (std::size_t v = range.begin(); v != range.end(); ++v) keyed[v] = {coordinate_key(vertices[v]), std::uint32_t(v)};
  });
  tbb::parallel_sort(keyed.begin(), keyed.end(), [](const Keyed& a, const Keyed& b) { return a.at < b.at || (a.at == b.at && a.v < b.v); });
  std::vector<std::uint32_t> canonical(n);
  for (std::size_t i = 0, first = 0; i < n; ++i) {
    if (keyed[i].at != keyed[first].at) first = i;
    canonical[keyed[i].v] = keyed[first].v;
  }
  return canonical;
}

namespace {

using EK = CGAL::Exact_predicates_exact_constructions_kernel;
using IK = CGAL::Exact_predicates_inexact_constructions_kernel;
using Loop = std::vector<std::uint32_t>;

[[noreturn]] void self_intersecting(std::size_t file_face, const char* what) {
  fail("face " + std::to_string(file_face) + ": " + what + " (a planar face must be a simple polygon)");
}

// The corner of `loop` that spans a plane with its first two, or loop.size() when all are on one line.
std::size_t plane_corner(const std::vector<InputPoint3>& p, const Loop& loop) {
  for (std::size_t k = 2; k < loop.size(); ++k)
    if (!CGAL::collinear(p[loop[0]], p[loop[1]], p[loop[k]])) return k;
  return loop.size();
}

// Projection onto the coordinate plane that drops the axis the plane's normal is longest along:
// a bijection of the plane, so simplicity and orientation (up to one sign) are kept.
struct PlaneProjection {
  int u = 0, v = 1;
  PlaneProjection(const std::vector<InputPoint3>& p, const Loop& loop, std::size_t k) {
    auto exact = [&](std::uint32_t v) { return EK::Point_3(p[v].x(), p[v].y(), p[v].z()); };
    const EK::Vector_3 n = CGAL::cross_product(exact(loop[1]) - exact(loop[0]), exact(loop[k]) - exact(loop[0]));
    const EK::FT ax = CGAL::abs(n.x()), ay = CGAL::abs(n.y()), az = CGAL::abs(n.z());
    const int drop = az >= ax && az >= ay ? 2 : (ay >= ax ? 1 : 0);
    u = drop == 0 ? 1 : 0;
    v = drop == 2 ? 1 : 2;
  }
  IK::Point_2 operator()(const InputPoint3& q) const {
    return {q.cartesian(u), q.cartesian(v)};
  }
};

// The loops of a face: runs of repeated corners are one corner; a corner visited again closes the
// loop since its first visit (a keyhole face becomes its outer loop and its hole).
std::vector<Loop> split_loops(const std::vector<std::uint32_t>& face, bool& split) {
  Loop f;
  for (std::uint32_t v : face)
    if (f.empty() || f.back() != v) f.push_back(v);
  while (f.size() > 1 && f.back() == f.front()) f.pop_back();
  std::vector<Loop> loops;
  Loop stack;
  split = false;
  for (std::uint32_t v : f) {
    auto it = std::find(stack.begin(), stack.end(), v);
    if (it == stack.end()) {
      stack.push_back(v);
      continue;
    }
    split = true;
    loops.emplace_back(it, stack.end());
    stack.erase(it + 1, stack.end());
  }
  loops.push_back(std::move(stack));
  return loops;
}

void append(PreparedFaces& out, Loop face, std::uint8_t fan_edges = 0) {
  out.faces.push_back(std::move(face));
  out.fan_edges.push_back(fan_edges);
}

// One simple loop of distinct corners, not all on one line.
void prepare_loop(const std::vector<InputPoint3>& p, Loop loop, std::size_t file_face, PreparedFaces& out) {
  const std::size_t k = plane_corner(p, loop);
  bool planar = true;
  for (std::size_t i = 3; i < loop.size() && planar; ++i)
    planar = CGAL::coplanar(p[loop[0]], p[loop[1]], p[loop[k]], p[loop[i]]);
  if (planar) {
    if (loop.size() > 3) {
      const PlaneProjection project(p, loop, k);
      std::vector<IK::Point_2> q;
      for (std::uint32_t v : loop) q.push_back(project(p[v]));
      if (!CGAL::is_simple_2(q.begin(), q.end(), IK())) self_intersecting(file_face, "the polygon crosses itself");
    }
    append(out, std::move(loop));
    return;
  }
  // The fan from the first corner; triangles on one line are left out.
  ++out.fanned;
  const std::size_t n = loop.size();
  for (std::size_t i = 1; i + 1 < n; ++i) {
    if (CGAL::collinear(p[loop[0]], p[loop[i]], p[loop[i + 1]])) continue;
    const std::uint8_t internal = (i >= 2 ? 1u : 0u) | (i + 2 < n ? 4u : 0u);  // edges 0 -> i, i + 1 -> 0
    append(out, {loop[0], loop[i], loop[i + 1]}, internal);
  }
}

// Loops of one face in one plane: the region inside an odd number of them, as triangles run the
// way the loop that bounds them runs (so that edges shared with neighbouring faces keep their
// direction).
void triangulate_region(const std::vector<InputPoint3>& p, const std::vector<Loop>& loops, std::size_t k,
                        std::size_t file_face, PreparedFaces& out) {
  struct FaceInfo {
    int level = -1;  // nesting depth: how many loops enclose the face
    int sign = 0;    // inside faces: +1 when the triangle's counter-clockwise order is the loops' way
  };
  using Vb = CGAL::Triangulation_vertex_base_with_info_2<std::uint32_t, IK>;
  using Fb = CGAL::Constrained_triangulation_face_base_2<IK, CGAL::Triangulation_face_base_with_info_2<FaceInfo, IK>>;
  using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
  using CDT = CGAL::Constrained_Delaunay_triangulation_2<IK, Tds, CGAL::No_constraint_intersection_tag>;

  const PlaneProjection project(p, loops.front(), k);
  CDT cdt;
  std::set<std::pair<std::uint32_t, std::uint32_t>> directed;  // the loops' edges, as they run
  try {
    for (const Loop& loop : loops) {
      std::vector<CDT::Vertex_handle> vh;
      for (std::uint32_t v : loop) {
        vh.push_back(cdt.insert(project(p[v])));
        vh.back()->info() = v;
      }
      for (std::size_t i = 0; i < loop.size(); ++i) {
        cdt.insert_constraint(vh[i], vh[(i + 1) % loop.size()]);
        directed.insert({loop[i], loop[(i + 1) % loop.size()]});
      }
    }
  } catch (const CDT::Intersection_of_constraints_exception&) {
    self_intersecting(file_face, "its loops cross each other");
  }

  // Nesting levels by flooding from outside; each flood is one domain, oriented by a loop edge on
  // its border.
  std::vector<std::pair<CDT::Face_handle, int>> seeds{{cdt.infinite_face(), 0}};
  while (!seeds.empty()) {
    auto [start, level] = seeds.back();
    seeds.pop_back();
    if (start->info().level != -1) continue;
    std::vector<CDT::Face_handle> domain, queue{start};
    int sign = 0;
    while (!queue.empty()) {
      CDT::Face_handle f = queue.back();
      queue.pop_back();
      if (f->info().level != -1) continue;
      f->info().level = level;
      domain.push_back(f);
      for (int i = 0; i < 3; ++i) {
        CDT::Face_handle n = f->neighbor(i);
        if (!cdt.is_constrained({f, i})) {
          queue.push_back(n);
          continue;
        }
        seeds.push_back({n, level + 1});
        if (sign == 0 && !cdt.is_infinite(f)) {
          const std::uint32_t a = f->vertex(CDT::ccw(i))->info(), b = f->vertex(CDT::cw(i))->info();
          sign = directed.count({a, b}) ? 1 : (directed.count({b, a}) ? -1 : 0);
        }
      }
    }
    for (CDT::Face_handle f : domain) f->info().sign = sign;
  }
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (f->info().level % 2 == 0) continue;
    const std::uint32_t a = f->vertex(0)->info(), b = f->vertex(1)->info(), c = f->vertex(2)->info();
    append(out, f->info().sign < 0 ? Loop{a, c, b} : Loop{a, b, c});
  }
}

}  // namespace

std::size_t prepare_face(const std::vector<InputPoint3>& points, const std::vector<std::uint32_t>& face,
                         std::size_t file_face, PreparedFaces& out) {
  const std::size_t before = out.faces.size();
  // Most faces are triangles of three distinct corners: one loop, planar, simple, kept as it is
  // unless on one line (what split_loops and prepare_loop would find, without their copies).
  if (face.size() == 3 && face[0] != face[1] && face[1] != face[2] && face[2] != face[0]) {
    if (CGAL::collinear(points[face[0]], points[face[1]], points[face[2]])) return 0;
    append(out, face);
    return 1;
  }
  bool split = false;
  std::vector<Loop> loops = split_loops(face, split);
  std::erase_if(loops, [&](const Loop& l) { return l.size() < 3 || plane_corner(points, l) == l.size(); });
  if (loops.empty()) return 0;
  if (split) ++out.split;
  if (loops.size() == 1) {
    prepare_loop(points, std::move(loops.front()), file_face, out);
    return out.faces.size() - before;
  }
  const Loop& first = loops.front();
  const std::size_t k = plane_corner(points, first);
  bool coplanar = true;
  for (const Loop& loop : loops)
    for (std::uint32_t v : loop)
      coplanar = coplanar && CGAL::coplanar(points[first[0]], points[first[1]], points[first[k]], points[v]);
  if (coplanar) {
    triangulate_region(points, loops, k, file_face, out);
  } else {
    for (Loop& loop : loops) prepare_loop(points, std::move(loop), file_face, out);
  }
  return out.faces.size() - before;
}

}  // namespace hlr::scene_detail
