// intersection_lines on two triangles of one mesh that share a corner (the shortcut taken for
// them: one exact predicate instead of constructions), on two triangles of two meshes, and on two
// flat quads of two triangles each (whose pieces are joined along the line where the planes
// meet), against CGAL's exact triangle-triangle intersection on Epeck: a pair of triangles must
// give an intersection line exactly when CGAL's intersection is a segment of positive length
// whose middle lies inside both triangles.
#include <hlr/hidden_line/lines.hpp>

#include <CGAL/intersections.h>
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

namespace hlr::hltest {
namespace {

using EK = CGAL::Exact_predicates_exact_constructions_kernel;

bool in_relative_interior(const EK::Triangle_3& t, const EK::Point_3& p) {
  if (!t.has_on(p)) return false;
  for (int i = 0; i < 3; ++i)
    if (CGAL::collinear(t[i], t[(i + 1) % 3], p)) return false;
  return true;
}

bool crossing_by_cgal(const EK::Triangle_3& a, const EK::Triangle_3& b) {
  const auto meet = CGAL::intersection(a, b);
  if (!meet) return false;
  const EK::Segment_3* s = boost::get<EK::Segment_3>(&*meet);
  if (!s) return false;
  const EK::Point_3 mid = CGAL::midpoint(s->source(), s->target());
  return in_relative_interior(a, mid) && in_relative_interior(b, mid);
}

RC_GTEST_PROP(Intersections, TrianglesSharingACornerCrossAsCgalSays, ()) {
  // Small grid coordinates force coplanar, collinear and touching cases.
  auto coordinate = [] { return double(*rc::gen::inRange(-3, 4)); };
  Mesh mesh;
  mesh.file = "pair";
  for (int v = 0; v < 5; ++v) mesh.vertices.push_back({coordinate(), coordinate(), coordinate()});
  auto point = [&](int v) { return EK::Point_3(mesh.vertices[v][0], mesh.vertices[v][1], mesh.vertices[v][2]); };
  RC_PRE(!CGAL::collinear(point(0), point(1), point(2)) && !CGAL::collinear(point(0), point(3), point(4)));
  mesh.faces = {{0, 1, 2}, {0, 3, 4}};
  const bool found = !hidden_line::intersection_lines({mesh}).empty();
  const bool expected = crossing_by_cgal(EK::Triangle_3(point(0), point(1), point(2)), EK::Triangle_3(point(0), point(3), point(4)));
  RC_TAG(expected ? "crossing" : "not crossing");
  RC_ASSERT(found == expected);
}

RC_GTEST_PROP(Intersections, TwoTrianglesGiveCgalsSegmentExactly, ()) {
  // Two triangles of two meshes on a small grid (coplanar, touching and corner-on-plane cases are
  // common): a line exactly when CGAL's exact intersection is a segment through both interiors,
  // and then with CGAL's ends, exactly (the ends are built from the input doubles, not from the
  // line where the planes meet).
  auto coordinate = [] { return double(*rc::gen::inRange(-3, 4)); };
  Mesh a, b;
  a.file = "a";
  b.file = "b";
  for (Mesh* m : {&a, &b}) {
    for (int v = 0; v < 3; ++v) m->vertices.push_back({coordinate(), coordinate(), coordinate()});
    m->faces = {{0, 1, 2}};
  }
  auto triangle = [](const Mesh& m) {
    auto p = [&](int v) { return EK::Point_3(m.vertices[v][0], m.vertices[v][1], m.vertices[v][2]); };
    return EK::Triangle_3(p(0), p(1), p(2));
  };
  const EK::Triangle_3 ta = triangle(a), tb = triangle(b);
  RC_PRE(!ta.is_degenerate() && !tb.is_degenerate());
  const auto lines = hidden_line::intersection_lines({a, b});
  const bool expected = crossing_by_cgal(ta, tb);
  RC_TAG(expected ? "crossing" : "not crossing");
  RC_ASSERT(lines.size() == (expected ? 1u : 0u));
  if (!expected) return;
  const auto meet = CGAL::intersection(ta, tb);
  const EK::Segment_3& s = *boost::get<EK::Segment_3>(&*meet);
  const auto& l = lines.front();
  RC_ASSERT((l.a == s.source() && l.b == s.target()) || (l.a == s.target() && l.b == s.source()));
}

RC_GTEST_PROP(Intersections, TwoQuadsGiveCgalsSegmentsJoined, ()) {
  // Two parallelograms on a small grid, each two triangles of one plane: their pieces lie on one
  // line, most often along an axis (a coordinate constant along it), and are joined where they
  // meet or overlap. Expected: CGAL's segments of the crossing triangle pairs, joined likewise.
  auto coordinate = [] { return double(*rc::gen::inRange(-3, 4)); };
  auto quad = [&](const char* name) {
    Mesh m;
    m.file = name;
    // Centred near the origin, so that most pairs of quads cross.
    const std::array<double, 3> p{coordinate() / 2, coordinate() / 2, coordinate() / 2},
        u{coordinate(), coordinate(), coordinate()}, v{coordinate(), coordinate(), coordinate()};
    for (const auto& [s, t] : {std::pair{-1, -1}, {1, -1}, {1, 1}, {-1, 1}})
      m.vertices.push_back({p[0] + s * u[0] + t * v[0], p[1] + s * u[1] + t * v[1], p[2] + s * u[2] + t * v[2]});
    m.faces = {{0, 1, 2}, {0, 2, 3}};
    return m;
  };
  const Mesh a = quad("a"), b = quad("b");
  auto triangle = [](const Mesh& m, int f) {
    auto p = [&](int k) {
      const auto& c = m.vertices[m.faces[f][k]];
      return EK::Point_3(c[0], c[1], c[2]);
    };
    return EK::Triangle_3(p(0), p(1), p(2));
  };
  RC_PRE(!triangle(a, 0).is_degenerate() && !triangle(b, 0).is_degenerate());
  std::vector<EK::Segment_3> expected;  // each from its lexicographically smaller end
  for (int fa = 0; fa < 2; ++fa)
    for (int fb = 0; fb < 2; ++fb)
      if (crossing_by_cgal(triangle(a, fa), triangle(b, fb))) {
        const auto meet = CGAL::intersection(triangle(a, fa), triangle(b, fb));
        EK::Segment_3 s = *boost::get<EK::Segment_3>(&*meet);
        if (CGAL::compare_xyz(s.target(), s.source()) == CGAL::SMALLER) s = s.opposite();
        expected.push_back(s);
      }
  std::sort(expected.begin(), expected.end(),
            [](const auto& x, const auto& y) { return CGAL::compare_xyz(x.source(), y.source()) == CGAL::SMALLER; });
  std::vector<EK::Segment_3> joined;
  for (const auto& s : expected) {
    if (!joined.empty() && CGAL::compare_xyz(s.source(), joined.back().target()) != CGAL::LARGER) {
      if (CGAL::compare_xyz(s.target(), joined.back().target()) == CGAL::LARGER)
        joined.back() = EK::Segment_3(joined.back().source(), s.target());
    } else {
      joined.push_back(s);
    }
  }
  const auto lines = hidden_line::intersection_lines({a, b});
  RC_TAG(joined.size() == 0 ? "none" : expected.size() > joined.size() ? "joined" : "apart");
  RC_ASSERT(lines.size() == joined.size());
  for (const auto& s : joined)
    RC_ASSERT(std::any_of(lines.begin(), lines.end(), [&](const auto& l) {
      return (l.a == s.source() && l.b == s.target()) || (l.a == s.target() && l.b == s.source());
    }));
}

}  // namespace
}  // namespace hlr::hltest
