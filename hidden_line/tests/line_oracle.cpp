// The independent oracle of the hidden-line tests (see line_oracle.hpp). Brute force, exact,
// deliberately plain.
#include "line_oracle.hpp"

#include <CGAL/box_intersection_d.h>
#include <CGAL/intersections.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <set>
#include <sstream>
#include <tuple>

namespace hlr::hltest {

const char* kind_text(FeatureKind kind) {
  switch (kind) {
    case FeatureKind::silhouette: return "silhouette";
    case FeatureKind::crease: return "crease";
    case FeatureKind::boundary: return "boundary";
    case FeatureKind::intersection: return "intersection";
    case FeatureKind::group: return "group";
    case FeatureKind::smooth: return "smooth";
  }
  return "?";
}

// ---------------------------------------------------------------------------------------------
// The view basis.

ExactViewBasis::ExactViewBasis(const View& view) {
  const FT d[3] = {FT(view.direction[0]), FT(view.direction[1]), FT(view.direction[2])};
  const FT u[3] = {FT(view.up[0]), FT(view.up[1]), FT(view.up[2])};
  // X = d x up
  x_[0] = d[1] * u[2] - d[2] * u[1];
  x_[1] = d[2] * u[0] - d[0] * u[2];
  x_[2] = d[0] * u[1] - d[1] * u[0];
  // Y = X x d
  y_[0] = x_[1] * d[2] - x_[2] * d[1];
  y_[1] = x_[2] * d[0] - x_[0] * d[2];
  y_[2] = x_[0] * d[1] - x_[1] * d[0];
  for (int i = 0; i < 3; ++i) z_[i] = -d[i];
  if (view.eye) eye_ = P3((*view.eye)[0], (*view.eye)[1], (*view.eye)[2]);
}

VP ExactViewBasis::to_view(const P3& p) const {
  if (!eye_)
    return {x_[0] * p.x() + x_[1] * p.y() + x_[2] * p.z(), y_[0] * p.x() + y_[1] * p.y() + y_[2] * p.z(),
            z_[0] * p.x() + z_[1] * p.y() + z_[2] * p.z()};
  const EK::Vector_3 q = p - *eye_;
  const FT w = -(z_[0] * q.x() + z_[1] * q.y() + z_[2] * q.z());
  return {(x_[0] * q.x() + x_[1] * q.y() + x_[2] * q.z()) / w, (y_[0] * q.x() + y_[1] * q.y() + y_[2] * q.z()) / w,
          1 / w};
}

EK::Vector_3 ExactViewBasis::toward_viewer(const P3& p) const {
  if (eye_) return *eye_ - p;
  return {z_[0], z_[1], z_[2]};
}

VP ExactViewBasis::to_view(const std::array<double, 3>& p) const { return to_view(P3(p[0], p[1], p[2])); }

namespace {

CGAL::Bbox_2 interval_box(const P2& p) {
  const auto x = CGAL::to_interval(p.x());
  const auto y = CGAL::to_interval(p.y());
  return CGAL::Bbox_2(x.first, y.first, x.second, y.second);
}

P2 image(const VP& p) { return P2(p.x, p.y); }

std::string num(const FT& v) { return exact_rational_string(v); }
std::string triple(const FT& x, const FT& y, const FT& z) {
  std::string s = "(";
  s += num(x);
  s += ", ";
  s += num(y);
  s += ", ";
  s += num(z);
  s += ")";
  return s;
}
std::string vp_text(const VP& p) { return triple(p.x, p.y, p.z); }
std::string p3_text(const P3& p) { return triple(p.x(), p.y(), p.z()); }

// Newell's formula over all corners: twice the vector area of the polygon (exact for planar faces).
template <class Corner>
void newell(const std::vector<Corner>& c, FT& nx, FT& ny, FT& nz) {
  nx = 0;
  ny = 0;
  nz = 0;
  for (std::size_t i = 0, n = c.size(); i < n; ++i) {
    const Corner& p = c[i];
    const Corner& q = c[(i + 1) % n];
    nx += (p.y - q.y) * (p.z + q.z);
    ny += (p.z - q.z) * (p.x + q.x);
    nz += (p.x - q.x) * (p.y + q.y);
  }
}

struct ModelCorner {
  FT x, y, z;
};

std::vector<ModelCorner> model_corners(const Mesh& mesh, const std::vector<std::uint32_t>& face) {
  std::vector<ModelCorner> out;
  for (std::uint32_t v : face) out.push_back({FT(mesh.vertices[v][0]), FT(mesh.vertices[v][1]), FT(mesh.vertices[v][2])});
  return out;
}

// n1 . n2 < c |n1| |n2|, exactly, for a double c, by cases on the signs.
bool dihedral_above(const EK::Vector_3& n1, const EK::Vector_3& n2, double c) {
  const FT dot = n1 * n2;
  const FT c2P = FT(c) * FT(c) * n1.squared_length() * n2.squared_length();
  if (c > 0) {
    // right side positive
    if (CGAL::sign(dot) != CGAL::POSITIVE) return true;
    return dot * dot < c2P;
  }
  if (c == 0) return CGAL::sign(dot) == CGAL::NEGATIVE;
  // right side negative: need dot negative and |dot| > |c| |n1| |n2|
  if (CGAL::sign(dot) != CGAL::NEGATIVE) return false;
  return dot * dot > c2P;
}


// The smooth-edge rule of meshes (features.hpp), by brute force on Epeck: coplanar groups by a
// union-find over the edges, every corner tested against every line.
class OracleSurfaces {
 public:
  using Key = std::pair<std::uint32_t, std::uint32_t>;
  using Uses = std::vector<std::pair<std::uint32_t, bool>>;

  OracleSurfaces(const Mesh& mesh, const std::map<Key, Uses>& edges) : mesh_(mesh), root_(mesh.faces.size()) {
    for (std::uint32_t f = 0; f < root_.size(); ++f) root_[f] = f;
    for (const auto& [key, uses] : edges)
      if (uses.size() == 2 && uses[0].second != uses[1].second && coplanar(uses[0].first, uses[1].first)) {
        const std::uint32_t a = find(uses[0].first), b = find(uses[1].first);
        root_[std::max(a, b)] = std::min(a, b);
      }
  }

  std::uint32_t find(std::uint32_t f) const {
    while (root_[f] != f) f = root_[f];
    return f;
  }

  // Every corner of g in the plane of f.
  bool coplanar(std::uint32_t f, std::uint32_t g) const {
    const auto& face = mesh_.faces[f];
    for (std::size_t k = 2; k < face.size(); ++k) {
      if (CGAL::collinear(point(face[0]), point(face[1]), point(face[k]))) continue;
      for (std::uint32_t v : mesh_.faces[g])
        if (!CGAL::coplanar(point(face[0]), point(face[1]), point(face[k]), point(v))) return false;
      return true;
    }
    return false;
  }

  void add_soft(const Key& edge, std::uint32_t f, std::uint32_t g) { soft_.push_back({edge, {find(f), find(g)}}); }

  bool smooth(const Key& edge, std::uint32_t f, std::uint32_t g) const {
    const std::uint32_t rf = find(f), rg = find(g);
    const bool sf = strip(rf, edge), sg = strip(rg, edge);
    return (sf && !sg && !lone_triangle(rg)) || (sg && !sf && !lone_triangle(rf));
  }

 private:
  P3 point(std::uint32_t v) const {
    const auto& p = mesh_.vertices[v];
    return P3(p[0], p[1], p[2]);
  }

  bool lone_triangle(std::uint32_t root) const {
    std::size_t faces = 0;
    for (std::uint32_t f = 0; f < root_.size(); ++f) faces += find(f) == root;
    return faces == 1 && mesh_.faces[root].size() == 3;
  }

  // Every corner of the group on the edge's line or on one parallel line that carries a soft edge
  // of the group.
  bool strip(std::uint32_t root, const Key& edge) const {
    const P3 a = point(edge.first), b = point(edge.second);
    std::set<std::uint32_t> off;
    for (std::uint32_t f = 0; f < root_.size(); ++f)
      if (find(f) == root)
        for (std::uint32_t v : mesh_.faces[f])
          if (!CGAL::collinear(a, b, point(v))) off.insert(v);
    if (off.empty()) return false;
    const P3 p = point(*off.begin());
    auto on_far_line = [&](std::uint32_t v) {
      return !CGAL::collinear(a, b, point(v)) && CGAL::cross_product(b - a, point(v) - p) == CGAL::NULL_VECTOR;
    };
    for (std::uint32_t v : off)
      if (!on_far_line(v)) return false;
    for (const auto& [e, roots] : soft_)
      if ((roots.first == root || roots.second == root) && on_far_line(e.first) && on_far_line(e.second)) return true;
    return false;
  }

  const Mesh& mesh_;
  std::vector<std::uint32_t> root_;
  std::vector<std::pair<Key, Key>> soft_;  // (edge, its two groups)
};

}  // namespace

// ---------------------------------------------------------------------------------------------
// Feature edges.

std::vector<OracleFeature> oracle_features(const std::vector<Mesh>& meshes, const View& view, double crease_degrees,
                                           SmoothEdges smooth_edges) {
  const FeatureKind smooth_kind = smooth_edges == SmoothEdges::thin ? FeatureKind::smooth : FeatureKind::crease;
  const double cos_threshold = std::cos(crease_degrees * std::numbers::pi / 180.0);
  const ExactViewBasis basis(view);
  std::vector<OracleFeature> out;
  for (std::uint32_t m = 0; m < meshes.size(); ++m) {
    const Mesh& mesh = meshes[m];
    std::vector<EK::Vector_3> normal;
    normal.reserve(mesh.faces.size());
    for (const auto& face : mesh.faces) {
      FT nx, ny, nz;
      newell(model_corners(mesh, face), nx, ny, nz);
      normal.emplace_back(nx, ny, nz);
    }
    // (low, high) -> uses (face, runs low -> high), faces in ascending order; edges all of whose
    // uses are internal to one non-planar face's fan (DESIGN.md: the crease rule only).
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::pair<std::uint32_t, bool>>> edges;
    std::map<std::pair<std::uint32_t, std::uint32_t>, bool> fan;
    std::map<std::pair<std::uint32_t, std::uint32_t>, unsigned> source;  // B-rep edge bits, or'ed
    const std::vector<int> sides = closed_sides(mesh);
    for (std::uint32_t f = 0; f < mesh.faces.size(); ++f) {
      const auto& face = mesh.faces[f];
      for (std::size_t i = 0; i < face.size(); ++i) {
        const std::uint32_t p = face[i], q = face[(i + 1) % face.size()];
        edges[{std::min(p, q), std::max(p, q)}].push_back({f, p < q});
        const bool internal = !mesh.fan_edges.empty() && i < 8 && (mesh.fan_edges[f] >> i & 1u);
        auto [it, first] = fan.try_emplace({std::min(p, q), std::max(p, q)}, internal);
        if (!first) it->second = it->second && internal;
        if (!mesh.source_edges.empty() && i < 4 && (mesh.source_edges[f] >> i & 1u))
          source[{std::min(p, q), std::max(p, q)}] |= 1u | ((mesh.source_edges[f] >> (i + 4) & 1u) << 1);
      }
    }
    // Soft edges (features.hpp) first: the smooth rule needs the strips' far edges.
    std::optional<OracleSurfaces> surfaces;
    auto soft = [&](const auto& key, const auto& uses) {
      if (uses.size() != 2 || fan.at(key)) return false;
      const auto [f, f_up] = uses[0];
      const auto [g, g_up] = uses[1];
      const EK::Vector_3 ng = f_up == g_up ? -normal[g] : normal[g];
      return surfaces->find(f) != surfaces->find(g) && !dihedral_above(normal[f], ng, cos_threshold) && !surfaces->coplanar(f, g);
    };
    if (smooth_edges != SmoothEdges::off && mesh.source_edges.empty()) {
      surfaces.emplace(mesh, edges);
      for (const auto& [key, uses] : edges)
        if (soft(key, uses)) surfaces->add_soft(key, uses[0].first, uses[1].first);
    }
    for (const auto& [key, uses] : edges) {
      OracleFeature e;
      e.mesh = m;
      e.v0 = key.first;
      e.v1 = key.second;
      for (const auto& u : uses) e.faces.push_back(u.first);
      if (uses.size() == 1) {
        e.kind = FeatureKind::boundary;
      } else if (uses.size() > 2) {
        e.kind = FeatureKind::crease;
      } else {
        const auto [f, f_up] = uses[0];
        const auto [g, g_up] = uses[1];
        // Alike: faces sharing an edge agree in orientation when they run it in opposite directions.
        const EK::Vector_3 nf = normal[f];
        const EK::Vector_3 ng = f_up == g_up ? -normal[g] : normal[g];
        // The front side is the outside for a closed solid; elsewhere the two sides are alike, so a
        // silhouette is where the (alike-oriented) faces' facings differ at all.
        const int side = sides[f];
        const auto& corner = mesh.vertices[mesh.faces[f][0]];
        const EK::Vector_3 toward = basis.toward_viewer(P3(corner[0], corner[1], corner[2]));
        const auto& g_corner = mesh.vertices[mesh.faces[g][0]];
        const EK::Vector_3 g_toward = basis.toward_viewer(P3(g_corner[0], g_corner[1], g_corner[2]));
        const int f_sign = CGAL::sign(nf * toward), g_sign = CGAL::sign(ng * g_toward);
        const bool turns = side != 0 ? (f_sign * side > 0) != (g_sign * side > 0) : f_sign != g_sign;
        const bool crease_only = fan.at(key);
        if (turns && !crease_only) {
          e.kind = FeatureKind::silhouette;
        } else if (!mesh.source_edges.empty()) {
          // B-rep edges, whatever the angle; tangent ones only with smooth edges (features.hpp).
          const auto s = source.find(key);
          const unsigned bits = s == source.end() ? 0u : s->second;
          if (!(bits & 1u) || ((bits & 2u) && smooth_edges == SmoothEdges::off)) continue;
          e.kind = bits & 2u ? smooth_kind : FeatureKind::crease;
        } else if (dihedral_above(nf, ng, cos_threshold)) {
          e.kind = FeatureKind::crease;
        } else if (!mesh.face_group.empty() && mesh.face_group[f] != mesh.face_group[g]) {
          e.kind = FeatureKind::group;
        } else if (surfaces && soft(key, uses) && surfaces->smooth(key, f, g)) {
          e.kind = smooth_kind;
        } else {
          continue;
        }
      }
      out.push_back(std::move(e));
    }
  }
  return out;
}

// ---------------------------------------------------------------------------------------------
// Penetrations.

namespace {

struct Tri {
  EK::Triangle_3 t;
  FaceRef face;
  std::array<std::uint32_t, 3> v;
};

bool in_relative_interior(const EK::Triangle_3& t, const P3& p) {
  // p lies on t (it is on the intersection): it is in the relative interior iff on no edge line.
  for (int i = 0; i < 3; ++i)
    if (CGAL::collinear(t.vertex(i), t.vertex((i + 1) % 3), p)) return false;
  return true;
}

// Ear clipping of a planar polygon face, exactly, in the coordinate plane that drops the largest
// component of its normal: the triangles (as vertex indices) of a simple polygon, straight-angle
// corners dropped; nothing when no ear is found (the face is not simple).
std::optional<std::vector<std::array<std::uint32_t, 3>>> ear_clip(const Mesh& mesh, const std::vector<std::uint32_t>& face,
                                                                  const FT& nx, const FT& ny, const FT& nz) {
  const FT n[3] = {nx, ny, nz};
  int drop = 0;
  for (int k = 1; k < 3; ++k)
    if (CGAL::abs(n[k]) > CGAL::abs(n[drop])) drop = k;
  const int u = (drop + 1) % 3, v = (drop + 2) % 3;
  // Counter-clockwise in (u, v) when n[drop] > 0; flip v otherwise.
  const bool flip = CGAL::sign(n[drop]) == CGAL::NEGATIVE;
  auto project = [&](std::uint32_t i) {
    const auto& c = mesh.vertices[i];
    return P2(c[u], flip ? -c[v] : c[v]);
  };
  std::vector<std::uint32_t> ring = face;
  std::vector<std::array<std::uint32_t, 3>> out;
  while (ring.size() > 3) {
    bool clipped = false;
    for (std::size_t i = 0; i < ring.size() && !clipped; ++i) {
      const std::size_t ip = (i + ring.size() - 1) % ring.size(), in = (i + 1) % ring.size();
      const P2 a = project(ring[ip]), b = project(ring[i]), c = project(ring[in]);
      const CGAL::Orientation o = CGAL::orientation(a, b, c);
      if (o == CGAL::COLLINEAR) {
        if (!CGAL::collinear_are_strictly_ordered_along_line(a, b, c)) return std::nullopt;  // a spike
        ring.erase(ring.begin() + static_cast<std::ptrdiff_t>(i));  // a straight angle
        clipped = true;
        continue;
      }
      if (o != CGAL::LEFT_TURN) continue;  // reflex
      bool empty = true;
      for (std::size_t k = 0; k < ring.size() && empty; ++k) {
        if (k == ip || k == i || k == in) continue;
        const P2 r = project(ring[k]);
        empty = CGAL::orientation(a, b, r) == CGAL::RIGHT_TURN || CGAL::orientation(b, c, r) == CGAL::RIGHT_TURN ||
                CGAL::orientation(c, a, r) == CGAL::RIGHT_TURN;
      }
      if (!empty) continue;
      out.push_back({ring[ip], ring[i], ring[in]});
      ring.erase(ring.begin() + static_cast<std::ptrdiff_t>(i));
      clipped = true;
    }
    if (!clipped) return std::nullopt;
  }
  const P2 a = project(ring[0]), b = project(ring[1]), c = project(ring[2]);
  if (CGAL::orientation(a, b, c) == CGAL::LEFT_TURN) out.push_back({ring[0], ring[1], ring[2]});
  else if (CGAL::orientation(a, b, c) == CGAL::RIGHT_TURN) return std::nullopt;
  return out;
}

}  // namespace

PenetrationSearch find_penetrations(const std::vector<Mesh>& meshes) {
  PenetrationSearch out;
  std::vector<Tri> tris;
  for (std::uint32_t m = 0; m < meshes.size(); ++m) {
    const Mesh& mesh = meshes[m];
    auto point = [&](std::uint32_t v) {
      const auto& p = mesh.vertices[v];
      return P3(p[0], p[1], p[2]);
    };
    for (std::uint32_t f = 0; f < mesh.faces.size(); ++f) {
      const auto& face = mesh.faces[f];
      if (face.size() == 3) {
        tris.push_back({EK::Triangle_3(point(face[0]), point(face[1]), point(face[2])), {m, f}, {face[0], face[1], face[2]}});
        continue;
      }
      FT nx, ny, nz;
      newell(model_corners(mesh, face), nx, ny, nz);
      const auto ears = ear_clip(mesh, face, nx, ny, nz);
      if (!ears) {
        ++out.faces_skipped;
        continue;
      }
      for (const auto& e : *ears)
        tris.push_back({EK::Triangle_3(point(e[0]), point(e[1]), point(e[2])), {m, f}, e});
    }
  }
  out.triangles = tris.size();

  using Box = CGAL::Box_intersection_d::Box_with_handle_d<double, 3, const Tri*>;
  std::vector<Box> boxes;
  boxes.reserve(tris.size());
  for (const Tri& t : tris) boxes.emplace_back(t.t.bbox(), &t);
  auto visit = [&](const Box& x, const Box& y) {
    const Tri& s = *x.handle();
    const Tri& t = *y.handle();
    if (s.face.mesh == t.face.mesh) {
      if (s.face.face == t.face.face) return;  // two triangles of one face: coplanar
      int shared = 0;
      for (std::uint32_t a : s.v)
        for (std::uint32_t b : t.v) shared += a == b;
      // Sharing an edge: if not coplanar, the planes meet in the edge's line, so the
      // intersection lies on that edge of both; if coplanar, the intersection has no interior
      // point of both either. Nothing to find.
      if (shared >= 2) return;
    }
    // The midpoint of s and t's intersection can be in the relative interior of s only if s has
    // corners strictly on both sides of t's plane: otherwise the signed distance to that plane,
    // zero at the midpoint, would have an interior minimum on s and vanish on all of it (s and t
    // coplanar, where a segment-shaped intersection lies on the boundary of one of them). And the
    // same with s and t exchanged. Exact orientation predicates on the input doubles.
    auto straddles = [](const EK::Triangle_3& a, const EK::Triangle_3& b) {
      bool below = false, above = false;
      for (int i = 0; i < 3; ++i) {
        const CGAL::Orientation o = CGAL::orientation(b.vertex(0), b.vertex(1), b.vertex(2), a.vertex(i));
        below = below || o == CGAL::NEGATIVE;
        above = above || o == CGAL::POSITIVE;
      }
      return below && above;
    };
    if (!straddles(s.t, t.t) || !straddles(t.t, s.t)) return;
    ++out.pairs_tested;
    if (!CGAL::do_intersect(s.t, t.t)) return;
    const auto result = CGAL::intersection(s.t, t.t);
    if (!result) return;
    const EK::Segment_3* seg = boost::get<EK::Segment_3>(&*result);
    if (!seg || seg->source() == seg->target()) return;
    const P3 mid = CGAL::midpoint(seg->source(), seg->target());
    if (!in_relative_interior(s.t, mid) || !in_relative_interior(t.t, mid)) return;
    out.found.push_back({mid, s.face, t.face});
  };
  CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), visit);
  std::sort(out.found.begin(), out.found.end(), [](const Penetration& a, const Penetration& b) {
    return std::tie(a.f, a.g) < std::tie(b.f, b.g);
  });
  return out;
}

// ---------------------------------------------------------------------------------------------
// Visibility.

LineOracle::LineOracle(const std::vector<Mesh>& meshes, const View& view)
    : meshes_(&meshes), view_(view), surfaces_(meshes, view), basis_(view), near_(meshes, view) {
  std::size_t total = 0;
  for (const Mesh& mesh : meshes) {
    first_.push_back(total);
    total += mesh.faces.size();
  }
  faces_.reserve(total);
  bool first = true;
  for (std::uint32_t m = 0; m < meshes.size(); ++m) {
    const Mesh& mesh = meshes[m];
    std::vector<VP> vp(mesh.vertices.size());  // of the vertices in front of the near plane
    std::vector<bool> front(mesh.vertices.size());
    auto model = [&](std::uint32_t v) { return P3(mesh.vertices[v][0], mesh.vertices[v][1], mesh.vertices[v][2]); };
    for (std::uint32_t v = 0; v < mesh.vertices.size(); ++v)
      if ((front[v] = near_.in_front(model(v)))) vp[v] = basis_.to_view(mesh.vertices[v]);
    for (std::uint32_t f = 0; f < mesh.faces.size(); ++f) {
      FaceData fd;
      fd.ref = {m, f};
      const auto& face = mesh.faces[f];
      if (std::all_of(face.begin(), face.end(), [&](std::uint32_t v) { return front[v]; })) {
        for (std::uint32_t v : face) fd.corners.push_back(vp[v]);
      } else {  // its part in front of the near plane; none: a face of no corners, which covers nothing
        std::vector<P3> polygon;
        for (std::uint32_t v : face) polygon.push_back(model(v));
        for (const P3& p : near_.clip(polygon)) fd.corners.push_back(basis_.to_view(p));
        if (fd.corners.empty()) {
          faces_.push_back(std::move(fd));
          continue;
        }
      }
      newell(fd.corners, fd.nx, fd.ny, fd.nz);
      const VP& c0 = fd.corners[0];
      fd.d = fd.nx * c0.x + fd.ny * c0.y + fd.nz * c0.z;
      if (fd.corners.size() > 3) {  // a triangle is planar
        for (const VP& c : fd.corners)
          if (fd.nx * c.x + fd.ny * c.y + fd.nz * c.z != fd.d) {
            ++non_planar_;
            break;
          }
      }
      const CGAL::Bbox_2& box = surfaces_.face(fd.ref).box;
      extent_ = first ? box : extent_ + box;
      first = false;
      faces_.push_back(std::move(fd));
    }
    vertices_.push_back(std::move(vp));
  }
  const double w = std::max(extent_.xmax() - extent_.xmin(), 1e-300);
  const double h = std::max(extent_.ymax() - extent_.ymin(), 1e-300);
  const double cells = std::max<double>(1, static_cast<double>(faces_.size()) / 2.0);
  nx_ = std::clamp(static_cast<int>(std::sqrt(cells * w / h)), 1, 1024);
  ny_ = std::clamp(static_cast<int>(cells / nx_), 1, 1024);
  cells_.assign(static_cast<std::size_t>(nx_) * ny_, {});
  auto index = [](double v, double lo, double hi, int n) {
    if (!(hi > lo)) return 0;
    return std::clamp(static_cast<int>(std::floor((v - lo) / (hi - lo) * n)), 0, n - 1);
  };
  for (std::uint32_t id = 0; id < faces_.size(); ++id) {
    if (faces_[id].corners.empty()) continue;  // behind the near plane: never a candidate
    const CGAL::Bbox_2& b = surfaces_.face(faces_[id].ref).box;
    const int x0 = index(b.xmin(), extent_.xmin(), extent_.xmax(), nx_);
    const int x1 = index(b.xmax(), extent_.xmin(), extent_.xmax(), nx_);
    const int y0 = index(b.ymin(), extent_.ymin(), extent_.ymax(), ny_);
    const int y1 = index(b.ymax(), extent_.ymin(), extent_.ymax(), ny_);
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) cells_[static_cast<std::size_t>(y) * nx_ + x].push_back(id);
  }
}

std::optional<std::pair<VP, VP>> LineOracle::edge_ends(std::uint32_t mesh, std::uint32_t v0, std::uint32_t v1) const {
  const auto& v = (*meshes_)[mesh].vertices;
  const P3 a(v[v0][0], v[v0][1], v[v0][2]), b(v[v1][0], v[v1][1], v[v1][2]);
  const auto part = near_.clip(a, b);
  if (!part) return std::nullopt;
  return std::pair{basis_.to_view(part->first), basis_.to_view(part->second)};
}

std::vector<std::uint32_t> LineOracle::candidates(const CGAL::Bbox_2& box) const {
  std::vector<std::uint32_t> out;
  if (faces_.empty() || !CGAL::do_overlap(box, extent_)) return out;
  auto index = [](double v, double lo, double hi, int n) {
    if (!(hi > lo)) return 0;
    return std::clamp(static_cast<int>(std::floor((v - lo) / (hi - lo) * n)), 0, n - 1);
  };
  const int x0 = index(box.xmin(), extent_.xmin(), extent_.xmax(), nx_);
  const int x1 = index(box.xmax(), extent_.xmin(), extent_.xmax(), nx_);
  const int y0 = index(box.ymin(), extent_.ymin(), extent_.ymax(), ny_);
  const int y1 = index(box.ymax(), extent_.ymin(), extent_.ymax(), ny_);
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) {
      const auto& cell = cells_[static_cast<std::size_t>(y) * nx_ + x];
      for (std::uint32_t id : cell)
        if (CGAL::do_overlap(surfaces_.face(faces_[id].ref).box, box)) out.push_back(id);
    }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

std::optional<FaceRef> LineOracle::hiding_face(const VP& p) const {
  const P2 q = image(p);
  // Faces that are not edge-on: the surface oracle's probe.
  const SceneOracle::Probe probe = surfaces_.probe(q);
  if (probe.max_z && *probe.max_z > p.z) {
    for (const FaceRef& f : probe.faces)
      if (surfaces_.face(f).plane.at(q) > p.z) return f;
  }
  // Faces seen edge-on: the largest depth of their boundary edges over q.
  for (std::uint32_t id : candidates(interval_box(q))) {
    const FaceData& face = faces_[id];
    if (surfaces_.face(face.ref).facing != 0) continue;
    const std::size_t n = face.corners.size();
    for (std::size_t i = 0; i < n; ++i) {
      const VP& u = face.corners[i];
      const VP& v = face.corners[(i + 1) % n];
      const P2 u2 = image(u), v2 = image(v);
      if (u2 == v2) {
        if (q == u2 && (u.z > p.z || v.z > p.z)) return face.ref;
        continue;
      }
      if (!CGAL::collinear(u2, v2, q) || !CGAL::collinear_are_ordered_along_line(u2, q, v2)) continue;
      const FT lambda = u.x != v.x ? (p.x - u.x) / (v.x - u.x) : (p.y - u.y) / (v.y - u.y);
      if (u.z + lambda * (v.z - u.z) > p.z) return face.ref;
    }
  }
  return std::nullopt;
}

namespace {

// The positive part of the linear function through (s, gs) and (e, ge) over (s, e), s < e.
std::optional<Interval> positive_part(const FT& s, const FT& e, const FT& gs, const FT& ge) {
  const CGAL::Sign ss = CGAL::sign(gs), se = CGAL::sign(ge);
  if (ss != CGAL::POSITIVE && se != CGAL::POSITIVE) return std::nullopt;
  if (ss == CGAL::POSITIVE && se == CGAL::POSITIVE) return Interval{s, e};
  const FT root = s + (e - s) * gs / (gs - ge);
  if (ss == CGAL::POSITIVE) return Interval{s, root};
  return Interval{root, e};
}

}  // namespace

void LineOracle::face_intervals(const FaceData& face, const VP& a, const VP& b, std::vector<Interval>& out) const {
  const SceneOracle::Face& sf = surfaces_.face(face.ref);
  const P2 a2 = image(a), b2 = image(b);
  // Where the face is strictly nearer: g(t) = depth of the plane - depth of the line, linear in t,
  // (d - n.p) / nz at p = a + t (b - a), decided without dividing first.
  const FT ha = face.d - (face.nx * a.x + face.ny * a.y + face.nz * a.z);
  const FT hb = face.d - (face.nx * b.x + face.ny * b.y + face.nz * b.z);
  const CGAL::Sign sz = CGAL::sign(face.nz);
  if (CGAL::sign(ha) != sz && CGAL::sign(hb) != sz) return;  // nowhere strictly nearer
  const auto nearer = positive_part(FT(0), FT(1), ha / face.nz, hb / face.nz);
  if (!nearer) return;
  const std::vector<P2>& pts = sf.points;
  const std::size_t n = pts.size();
  std::vector<int> side(n);
  bool left = false, right = false;
  for (std::size_t k = 0; k < n; ++k) {
    side[k] = static_cast<int>(CGAL::orientation(a2, b2, pts[k]));
    left = left || side[k] > 0;
    right = right || side[k] < 0;
  }
  if (!(left && right) && std::find(side.begin(), side.end(), 0) == side.end()) return;  // apart
  const FT wx = b.x - a.x, wy = b.y - a.y;
  const bool by_x = CGAL::abs(wx) >= CGAL::abs(wy);
  // Every parameter where the segment's image meets the face's projected boundary.
  std::vector<FT> cuts{nearer->lo, nearer->hi};
  for (std::size_t k = 0; k < n; ++k) {
    const P2& u = pts[k];
    const P2& v = pts[(k + 1) % n];
    const int su = side[k], sv = side[(k + 1) % n];
    std::optional<FT> t;
    if (su == 0) {
      t = by_x ? (u.x() - a.x) / wx : (u.y() - a.y) / wy;
    } else if (su * sv < 0) {
      const FT ex = v.x() - u.x(), ey = v.y() - u.y();
      t = ((u.x() - a.x) * ey - (u.y() - a.y) * ex) / (wx * ey - wy * ex);
    }
    if (t && nearer->lo < *t && *t < nearer->hi) cuts.push_back(*t);
  }
  std::sort(cuts.begin(), cuts.end());
  cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
  for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
    const FT mid = (cuts[k] + cuts[k + 1]) / 2;
    const P2 q(a.x + mid * wx, a.y + mid * wy);
    if (locate(pts, q) >= 0) out.push_back({cuts[k], cuts[k + 1]});
  }
}

void LineOracle::edge_on_intervals(const FaceData& face, const VP& a, const VP& b, std::vector<Interval>& out) const {
  const P2 a2 = image(a), b2 = image(b);
  const FT wx = b.x - a.x, wy = b.y - a.y, wz = b.z - a.z;
  const bool by_x = CGAL::abs(wx) >= CGAL::abs(wy);
  const std::size_t n = face.corners.size();
  for (std::size_t i = 0; i < n; ++i) {
    const VP& u = face.corners[i];
    const VP& v = face.corners[(i + 1) % n];
    const P2 u2 = image(u), v2 = image(v);
    if (u2 == v2) continue;  // seen end-on: at most one point of the segment
    if (CGAL::orientation(a2, b2, u2) != CGAL::COLLINEAR || CGAL::orientation(a2, b2, v2) != CGAL::COLLINEAR)
      continue;  // crossing: at most one point
    const FT tu = by_x ? (u.x - a.x) / wx : (u.y - a.y) / wy;
    const FT tv = by_x ? (v.x - a.x) / wx : (v.y - a.y) / wy;
    const FT lo = CGAL::max(FT(0), CGAL::min(tu, tv)), hi = CGAL::min(FT(1), CGAL::max(tu, tv));
    if (!(lo < hi)) continue;
    // The edge's depth minus the segment's depth, linear in t, through (tu, gu) and (tv, gv).
    const FT gu = u.z - (a.z + tu * wz), gv = v.z - (a.z + tv * wz);
    auto g = [&](const FT& t) { return gu + (t - tu) * (gv - gu) / (tv - tu); };
    if (auto part = positive_part(lo, hi, g(lo), g(hi))) out.push_back(*part);
  }
}

std::vector<Interval> LineOracle::hidden_intervals(const VP& a, const VP& b) const {
  const P2 a2 = image(a), b2 = image(b);
  if (a2 == b2) return {};
  std::vector<Interval> raw;
  for (std::uint32_t id : candidates(interval_box(a2) + interval_box(b2))) {
    const FaceData& face = faces_[id];
    if (surfaces_.face(face.ref).facing != 0) face_intervals(face, a, b, raw);
    else edge_on_intervals(face, a, b, raw);
  }
  std::sort(raw.begin(), raw.end(), [](const Interval& x, const Interval& y) { return x.lo < y.lo; });
  std::vector<Interval> merged;
  for (const Interval& i : raw) {
    if (!merged.empty() && i.lo <= merged.back().hi) {
      if (i.hi > merged.back().hi) merged.back().hi = i.hi;
    } else {
      merged.push_back(i);
    }
  }
  return merged;
}

std::vector<FaceRef> LineOracle::faces_through(const VP& p) const {
  std::vector<FaceRef> out;
  const P2 q = image(p);
  for (std::uint32_t id : candidates(interval_box(q))) {
    const FaceData& face = faces_[id];
    const SceneOracle::Face& sf = surfaces_.face(face.ref);
    if (sf.facing != 0) {
      if (locate(sf.points, q) >= 0 && sf.plane.at(q) == p.z) out.push_back(face.ref);
      continue;
    }
    // Edge-on: in the plane (nz = 0), then inside the face drawn in the plane's (y, z) or (x, z).
    if (face.nx * p.x + face.ny * p.y != face.d) continue;
    const bool drop_x = CGAL::abs(face.nx) >= CGAL::abs(face.ny);
    std::vector<P2> poly;
    for (const VP& c : face.corners) poly.push_back(drop_x ? P2(c.y, c.z) : P2(c.x, c.z));
    if (locate(poly, drop_x ? P2(p.y, p.z) : P2(p.x, p.z)) >= 0) out.push_back(face.ref);
  }
  return out;
}

bool LineOracle::coplanar(FaceRef f, FaceRef g) const {
  const FaceData& a = data(f);
  const FaceData& b = data(g);
  const EK::Vector_3 na(a.nx, a.ny, a.nz), nb(b.nx, b.ny, b.nz);
  if (CGAL::cross_product(na, nb) != CGAL::NULL_VECTOR) return false;
  const VP& c = b.corners[0];
  return a.nx * c.x + a.ny * c.y + a.nz * c.z == a.d;
}

// ---------------------------------------------------------------------------------------------
// Checks.

std::string LineReport::summary() const {
  std::ostringstream out;
  out << lines << " lines, " << pieces << " pieces, " << samples << " sample points, " << intersection_points
      << " intersection points, " << penetrations << " penetrations checked";
  append_outcome(out, notes, failures, messages);
  return out.str();
}

namespace {

using Line = hidden_line::FeatureLine<ExactKernel>;

VP point_at(const Line& line, const FT& t) {
  return {line.a.x + t * (line.b.x - line.a.x), line.a.y + t * (line.b.y - line.a.y),
          line.a.z + t * (line.b.z - line.a.z)};
}

bool same(const VP& p, const VP& q) { return p.x == q.x && p.y == q.y && p.z == q.z; }

class LineChecker {
 public:
  LineChecker(const LineOracle& oracle, const hidden_line::LineSet<ExactKernel>& set, const LineCheckOptions& options,
              const PenetrationSearch* penetrations, LineReport& report)
      : oracle_(oracle), set_(set), options_(options), penetrations_(penetrations), report_(report) {}

  void run() {
    report_.lines = set_.lines.size();
    stats();
    for (std::size_t i = 0; i < set_.lines.size(); ++i) coverage(i);
    features();
    for (std::size_t i = 0; i < set_.lines.size(); ++i) visibility(i);
    intersections();
  }

 private:
  void fail(const std::string& kind, const std::string& message) {
    ++report_.failures[kind];
    if (report_.messages.size() < options_.max_messages) report_.messages.push_back(kind + ": " + message);
  }
  void note(const std::string& kind) { ++report_.notes[kind]; }

  std::string line_text(std::size_t i) const {
    const Line& l = set_.lines[i];
    std::string s = "line " + std::to_string(i) + " (" + kind_text(l.kind) + ", mesh " + std::to_string(l.mesh);
    if (l.kind != FeatureKind::intersection) s += ", edge " + std::to_string(l.v0) + "-" + std::to_string(l.v1);
    return s + ", a = " + vp_text(l.a) + ", b = " + vp_text(l.b) + ")";
  }
  std::string piece_text(std::size_t i, std::size_t k) const {
    const auto& p = set_.lines[i].pieces[k];
    return line_text(i) + " piece " + std::to_string(k) + " [" + num(p.t0) + ", " + num(p.t1) + "] " +
           (p.visible ? "visible" : "hidden");
  }
  std::string verdict(const VP& p) const {
    const auto f = oracle_.hiding_face(p);
    if (!f) return "the oracle says visible";
    return "the oracle says hidden by mesh " + std::to_string(f->mesh) + " face " + std::to_string(f->face);
  }

  void stats() {
    const auto& s = set_.stats;
    std::size_t by_kind[kFeatureKinds] = {}, point = 0, vis = 0, hid = 0;
    for (const Line& l : set_.lines) {
      const auto k = static_cast<std::size_t>(l.kind);
      if (k < kFeatureKinds) ++by_kind[k];
      if (image(l.a) == image(l.b)) ++point;
      for (const auto& p : l.pieces) ++(p.visible ? vis : hid);
    }
    auto expect = [&](const char* what, std::size_t have, std::size_t want) {
      if (have != want) fail("stats", std::string(what) + " says " + std::to_string(have) + ", the lines have " + std::to_string(want));
    };
    expect("lines", s.lines, set_.lines.size());
    for (std::size_t k = 0; k < kFeatureKinds; ++k)
      expect(kind_text(static_cast<FeatureKind>(k)), s.by_kind[k], by_kind[k]);
    expect("point_in_view", s.point_in_view, point);
    expect("visible_pieces", s.visible_pieces, vis);
    expect("hidden_pieces", s.hidden_pieces, hid);
  }

  void coverage(std::size_t i) {
    const Line& l = set_.lines[i];
    report_.pieces += l.pieces.size();
    if (image(l.a) == image(l.b)) {
      if (!l.pieces.empty()) fail("(a) pieces on a line seen end-on", line_text(i));
      return;
    }
    if (l.pieces.empty()) {
      fail("(a) no pieces", line_text(i));
      return;
    }
    if (l.pieces.front().t0 != 0) fail("(a) first piece does not start at 0", piece_text(i, 0));
    if (l.pieces.back().t1 != 1) fail("(a) last piece does not end at 1", piece_text(i, l.pieces.size() - 1));
    for (std::size_t k = 0; k < l.pieces.size(); ++k) {
      const auto& p = l.pieces[k];
      if (!(p.t0 < p.t1)) fail("(a) empty or reversed piece", piece_text(i, k));
      if (k == 0) continue;
      const auto& prev = l.pieces[k - 1];
      if (prev.t1 != p.t0) fail("(a) gap or overlap", piece_text(i, k - 1) + " then " + piece_text(i, k));
      if (prev.visible == p.visible) fail("(a) consecutive pieces alike", piece_text(i, k - 1) + " then " + piece_text(i, k));
    }
  }

  void features() {
    const auto want = oracle_features(oracle_.meshes(), oracle_.view(), options_.crease_degrees, options_.smooth_edges);
    std::map<std::tuple<std::uint32_t, std::uint32_t, std::uint32_t>, FeatureKind> expected;
    for (const auto& e : want) expected[{e.mesh, e.v0, e.v1}] = e.kind;
    std::map<std::tuple<std::uint32_t, std::uint32_t, std::uint32_t>, std::size_t> have;
    const auto& meshes = oracle_.meshes();
    for (std::size_t i = 0; i < set_.lines.size(); ++i) {
      const Line& l = set_.lines[i];
      if (l.kind == FeatureKind::intersection) continue;
      if (l.mesh >= meshes.size() || l.v0 >= meshes[l.mesh].vertices.size() || l.v1 >= meshes[l.mesh].vertices.size()) {
        fail("(c) index out of range", line_text(i));
        continue;
      }
      const auto key = std::make_tuple(l.mesh, std::min(l.v0, l.v1), std::max(l.v0, l.v1));
      if (!have.emplace(key, i).second) {
        fail("(c) duplicate edge", line_text(i) + " repeats " + line_text(have[key]));
        continue;
      }
      // The ends are the exact view coordinates of the edge's vertices (of its part in front of
      // the near plane).
      const auto ends = oracle_.edge_ends(l.mesh, l.v0, l.v1);
      if (!ends) {
        fail("(c) edge behind the eye", line_text(i) + " lies behind the near plane");
        continue;
      }
      const VP &p = ends->first, &q = ends->second;
      if (!((same(l.a, p) && same(l.b, q)) || (same(l.a, q) && same(l.b, p))))
        fail("(c) endpoints", line_text(i) + ": vertex " + std::to_string(l.v0) + " is at " + vp_text(p) + ", vertex " +
                                  std::to_string(l.v1) + " at " + vp_text(q));
      const auto it = expected.find(key);
      if (it == expected.end()) {
        fail("(c) extra edge", line_text(i) + " is no feature edge");
      } else if (it->second != l.kind) {
        fail("(c) kind", line_text(i) + ": the oracle says " + kind_text(it->second));
      }
    }
    for (const auto& e : want) {
      if (have.count({e.mesh, e.v0, e.v1}) || !oracle_.edge_ends(e.mesh, e.v0, e.v1)) continue;
      std::string faces;
      for (std::uint32_t f : e.faces) {
        faces += ' ';
        faces += std::to_string(f);
      }
      fail("(c) missing edge", std::string(kind_text(e.kind)) + " edge " + std::to_string(e.v0) + "-" +
                                   std::to_string(e.v1) + " of mesh " + std::to_string(e.mesh) + " (faces" + faces + ")");
    }
  }

  void visibility(std::size_t i) {
    const Line& l = set_.lines[i];
    if (image(l.a) == image(l.b) || l.pieces.empty()) return;
    const std::vector<Interval> hidden = oracle_.hidden_intervals(l.a, l.b);
    for (std::size_t k = 0; k < l.pieces.size(); ++k) {
      const auto& piece = l.pieces[k];
      if (!(piece.t0 < piece.t1) || piece.t0 < 0 || piece.t1 > 1) continue;  // reported under (a)
      // Over the whole piece, against the interval oracle.
      std::optional<Interval> wrong;  // a stretch of the piece where the oracle disagrees
      if (piece.visible) {
        for (const Interval& h : hidden)
          if (h.lo < piece.t1 && h.hi > piece.t0) {
            wrong = Interval{CGAL::max(h.lo, piece.t0), CGAL::min(h.hi, piece.t1)};
            break;
          }
      } else {
        FT from = piece.t0;  // covered up to here
        for (const Interval& h : hidden) {
          if (h.hi <= from) continue;
          if (h.lo > from) break;
          from = h.hi;
          if (from >= piece.t1) break;
        }
        if (from < piece.t1) {
          FT to = piece.t1;
          for (const Interval& h : hidden)
            if (h.lo > from && h.lo < to) to = h.lo;
          wrong = Interval{from, to};
        }
      }
      if (wrong) {
        const FT t = (wrong->lo + wrong->hi) / 2;
        const VP p = point_at(l, t);
        fail("(b) visibility", piece_text(i, k) + ": over t in (" + num(wrong->lo) + ", " + num(wrong->hi) +
                                   "), e.g. at t = " + num(t) + ", point " + vp_text(p) + ", " + verdict(p));
      }
      // At three exact interior points, against the point oracle.
      for (int quarter = 1; quarter <= 3; ++quarter) {
        const FT t = piece.t0 + (piece.t1 - piece.t0) * quarter / 4;
        const VP p = point_at(l, t);
        ++report_.samples;
        const bool hid = oracle_.hidden(p);
        if (hid == !piece.visible) continue;
        if (!wrong) {
          // The intervals say the piece is right, so the sample must be an isolated point: the
          // point oracle must agree with the piece just beside it (a cross-check of the oracles).
          const FT eps = (piece.t1 - piece.t0) / (1 << 24);
          bool beside_agrees = true;
          for (const FT& s : {t - eps, t + eps}) beside_agrees = beside_agrees && oracle_.hidden(point_at(l, s)) == !piece.visible;
          if (beside_agrees) {
            note(hid ? "(b) isolated hidden point in a visible piece" : "(b) isolated visible point in a hidden piece");
          } else {
            fail("(b) point and interval oracles disagree",
                 piece_text(i, k) + ": at t = " + num(t) + " and beside it, point " + vp_text(p) + ", " + verdict(p));
          }
        } else if (report_.messages.size() < options_.max_messages) {
          report_.messages.push_back("(b) visibility: sample at t = " + num(t) + ", point " + vp_text(p) + " of " +
                                     piece_text(i, k) + ": " + verdict(p));
        }
      }
    }
  }

  void intersections() {
    std::vector<std::size_t> lines;
    for (std::size_t i = 0; i < set_.lines.size(); ++i)
      if (set_.lines[i].kind == FeatureKind::intersection) lines.push_back(i);
    if (!options_.intersections) {
      if (!lines.empty()) fail("(d) intersection lines when none were asked for", line_text(lines.front()));
      return;
    }
    // Soundness: points of intersection lines lie on two faces in different planes.
    for (std::size_t i : lines) {
      const Line& l = set_.lines[i];
      std::vector<FT> ts{FT(0), FT(1), FT(1) / 2};
      for (const auto& p : l.pieces)
        for (int quarter = 1; quarter <= 3; ++quarter) ts.push_back(p.t0 + (p.t1 - p.t0) * quarter / 4);
      for (const FT& t : ts) {
        const VP p = point_at(l, t);
        ++report_.intersection_points;
        const auto faces = oracle_.faces_through(p);
        bool two = false;
        for (std::size_t x = 0; x < faces.size() && !two; ++x)
          for (std::size_t y = x + 1; y < faces.size() && !two; ++y) two = !oracle_.coplanar(faces[x], faces[y]);
        if (!two) {
          std::string on;
          for (const auto& f : faces) {
            on += ' ';
            on += std::to_string(f.mesh);
            on += ':';
            on += std::to_string(f.face);
          }
          fail("(d) intersection point not on two faces in different planes",
               line_text(i) + " at t = " + num(t) + ", point " + vp_text(p) + ", on faces (mesh:face)" +
                   (on.empty() ? " none" : on));
        }
      }
    }
    if (!options_.completeness) return;
    PenetrationSearch computed;
    if (!penetrations_) {
      computed = find_penetrations(oracle_.meshes());
      penetrations_ = &computed;
    }
    if (penetrations_->faces_skipped) report_.notes["(d) faces not searched for penetrations (not simple)"] += penetrations_->faces_skipped;
    // Completeness: every penetration midpoint lies on an intersection line.
    struct Box3 {
      std::pair<double, double> r[3];
    };
    std::vector<Box3> boxes;
    for (std::size_t i : lines) {
      const Line& l = set_.lines[i];
      Box3 b;
      const FT* ca[3] = {&l.a.x, &l.a.y, &l.a.z};
      const FT* cb[3] = {&l.b.x, &l.b.y, &l.b.z};
      for (int k = 0; k < 3; ++k) {
        const auto ia = CGAL::to_interval(*ca[k]), ib = CGAL::to_interval(*cb[k]);
        b.r[k] = {std::min(ia.first, ib.first), std::max(ia.second, ib.second)};
      }
      boxes.push_back(b);
    }
    for (const Penetration& pen : penetrations_->found) {
      if (!oracle_.near().in_front(pen.midpoint)) continue;  // clipped away with its faces
      ++report_.penetrations;
      const VP m = oracle_.basis().to_view(pen.midpoint);
      const P3 mp(m.x, m.y, m.z);
      std::pair<double, double> im[3] = {CGAL::to_interval(m.x), CGAL::to_interval(m.y), CGAL::to_interval(m.z)};
      bool found = false;
      for (std::size_t k = 0; k < lines.size() && !found; ++k) {
        const Box3& b = boxes[k];
        bool overlap = true;
        for (int c = 0; c < 3; ++c) overlap = overlap && im[c].first <= b.r[c].second && im[c].second >= b.r[c].first;
        if (!overlap) continue;
        const Line& l = set_.lines[lines[k]];
        const P3 a(l.a.x, l.a.y, l.a.z), bb(l.b.x, l.b.y, l.b.z);
        found = CGAL::collinear(a, mp, bb) && CGAL::collinear_are_ordered_along_line(a, mp, bb);
      }
      if (!found)
        fail("(d) penetration not on any intersection line",
             "mesh " + std::to_string(pen.f.mesh) + " face " + std::to_string(pen.f.face) + " and mesh " +
                 std::to_string(pen.g.mesh) + " face " + std::to_string(pen.g.face) + " cross at model point " +
                 p3_text(pen.midpoint) + ", view point " + vp_text(m));
    }
  }

  const LineOracle& oracle_;
  const hidden_line::LineSet<ExactKernel>& set_;
  const LineCheckOptions& options_;
  const PenetrationSearch* penetrations_;
  LineReport& report_;
};

}  // namespace

LineReport check_lines(const LineOracle& oracle, const hidden_line::LineSet<ExactKernel>& set,
                       const LineCheckOptions& options, const PenetrationSearch* penetrations) {
  LineReport report;
  LineChecker(oracle, set, options, penetrations, report).run();
  if (oracle.non_planar_faces()) report.notes["oracle: non-planar input faces (normals from Newell)"] += oracle.non_planar_faces();
  return report;
}

}  // namespace hlr::hltest
