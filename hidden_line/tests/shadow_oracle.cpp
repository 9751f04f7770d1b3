// The shadow oracle (see shadow_oracle.hpp). Brute force over every face, exact, plain.
#include "shadow_oracle.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace hlr::hltest {
namespace {

using V3 = std::array<FT, 3>;
using hidden_line::Facing;
using hidden_line::ShadowPoint;
using hidden_line::ShadowPolygon;

V3 of(const ShadowPoint& p) { return {p.x, p.y, p.z}; }
V3 sub(const V3& a, const V3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
FT dot(const V3& a, const V3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

V3 newell(const std::vector<V3>& c) {
  V3 n{0, 0, 0};
  for (std::size_t i = 0; i < c.size(); ++i) {
    const V3& a = c[i];
    const V3& b = c[(i + 1) % c.size()];
    n[0] += (a[1] - b[1]) * (a[2] + b[2]);
    n[1] += (a[2] - b[2]) * (a[0] + b[0]);
    n[2] += (a[0] - b[0]) * (a[1] + b[1]);
  }
  return n;
}

int axis_of(const V3& n) {
  int a = 0;
  for (int k = 1; k < 3; ++k)
    if (CGAL::abs(n[k]) > CGAL::abs(n[a])) a = k;
  return a;
}

P2 project(const V3& p, int axis) { return P2(p[(axis + 1) % 3], p[(axis + 2) % 3]); }
std::vector<P2> project(const std::vector<V3>& c, int axis) {
  std::vector<P2> out;
  for (const V3& p : c) out.push_back(project(p, axis));
  return out;
}
// The point of the plane n·(q - o) = 0 above a projected point.
V3 lift(const P2& q, int axis, const V3& n, const V3& o) {
  V3 p;
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  p[u] = q.x();
  p[v] = q.y();
  p[axis] = o[axis] - (n[u] * (q.x() - o[u]) + n[v] * (q.y() - o[v])) / n[axis];
  return p;
}

std::vector<V3> corners(const std::vector<ShadowPoint>& c) {
  std::vector<V3> out;
  for (const auto& p : c) out.push_back(of(p));
  return out;
}

std::string name(const Mesh& m, std::uint32_t mesh, std::uint32_t face) {
  return "mesh " + std::to_string(mesh) + " face " + std::to_string(face);
}

}  // namespace

ShadowOracle::ShadowOracle(const std::vector<Mesh>& meshes) {
  for (const Mesh& mesh : meshes) {
    const std::vector<int> sides = closed_sides(mesh);
    auto& faces = meshes_.emplace_back();
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
      Face face;
      for (std::uint32_t v : mesh.faces[f]) {
        const auto& p = mesh.vertices[v];
        face.corners.push_back({FT(p[0]), FT(p[1]), FT(p[2])});
      }
      face.normal = newell(face.corners);
      face.side = sides[f] < 0 ? -1 : 1;
      face.axis = axis_of(face.normal);
      face.projected = project(face.corners, face.axis);
      face.box = {HUGE_VAL, HUGE_VAL, HUGE_VAL, -HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
      for (std::uint32_t v : mesh.faces[f])
        for (int k = 0; k < 3; ++k) {
          face.box[k] = std::min(face.box[k], mesh.vertices[v][k]);
          face.box[k + 3] = std::max(face.box[k + 3], mesh.vertices[v][k]);
        }
      faces.push_back(std::move(face));
    }
  }
}

int ShadowOracle::facing(FaceRef f, const V3& d) const {
  const Face& face = meshes_[f.mesh][f.face];
  return face.side * CGAL::sign(dot(face.normal, d));
}

RayProbe ShadowOracle::probe(const V3& p, const V3& d, bool segment) const {
  RayProbe out;
  std::optional<FT> best;
  // A filter in double only: the ray p - t d (t > 0) can reach a face only if its box, grown
  // generously, meets the ray's box over t in [0, T] where the ray leaves the scene's box... kept
  // simple: a face whose box lies entirely on the far side of p along some axis is skipped.
  const double pd[3] = {CGAL::to_double(p[0]), CGAL::to_double(p[1]), CGAL::to_double(p[2])};
  const double dd[3] = {CGAL::to_double(d[0]), CGAL::to_double(d[1]), CGAL::to_double(d[2])};
  for (std::uint32_t m = 0; m < meshes_.size(); ++m) {
    for (std::uint32_t f = 0; f < meshes_[m].size(); ++f) {
      const Face& face = meshes_[m][f];
      bool skip = false;
      for (int k = 0; k < 3 && !skip; ++k) {
        const double slack = 1e-9 * (std::abs(pd[k]) + std::abs(face.box[k]) + std::abs(face.box[k + 3]) + 1);
        // Along -d the coordinate k moves by -d[k] t: it only decreases when d[k] > 0.
        if (dd[k] > 0 && face.box[k] > pd[k] + slack) skip = true;
        if (dd[k] < 0 && face.box[k + 3] < pd[k] - slack) skip = true;
        if (dd[k] == 0 && (face.box[k] > pd[k] + slack || face.box[k + 3] < pd[k] - slack)) skip = true;
      }
      if (skip) continue;
      const FT nd = dot(face.normal, d);
      if (CGAL::is_zero(nd)) continue;  // parallel to the light: no shadow of positive area
      // n·(p - t d - c0) = 0
      const FT t = dot(face.normal, sub(p, face.corners[0])) / nd;
      if (!CGAL::is_positive(t) || (segment && t >= FT(1))) continue;
      const V3 q{p[0] - t * d[0], p[1] - t * d[1], p[2] - t * d[2]};
      if (locate(face.projected, project(q, face.axis)) < 0) continue;
      out.blocked = true;
      if (!best || t > *best) {
        best = t;
        out.nearest.clear();
      }
      if (t == *best) out.nearest.push_back({m, f});
    }
  }
  return out;
}

std::vector<std::string> check_shadows(const std::vector<Mesh>& meshes, const std::vector<hidden_line::Light>& lights,
                                       const hidden_line::ShadowResult& result, const ShadowCheckOptions& options) {
  std::vector<std::string> errors;
  auto fail = [&](const std::string& e) {
    if (errors.size() < options.max_errors) errors.push_back(e);
  };
  const ShadowOracle oracle(meshes);
  std::vector<V3> dirs;  // a directional light's direction, a point light's position
  for (const auto& l : lights) dirs.push_back({FT(l.vector[0]), FT(l.vector[1]), FT(l.vector[2])});
  auto point = [&](std::size_t k) { return lights[k].kind == hidden_line::Light::point; };
  // The direction the light travels to q.
  auto toward = [&](std::size_t k, const V3& q) { return point(k) ? sub(q, dirs[k]) : dirs[k]; };

  for (std::size_t si = 0; si < result.sources.size() && errors.size() < options.max_errors; ++si) {
    const auto& s = result.sources[si];
    const std::string where = "source " + std::to_string(si) + " (" + name(meshes[s.mesh], s.mesh, s.faces.front()) + ")";
    // The source's plane and area, from its faces as read.
    const auto& f0 = oracle.face({s.mesh, s.faces.front()});
    const V3 n0 = f0.normal;
    const V3 front{n0[0] * f0.side, n0[1] * f0.side, n0[2] * f0.side};
    const int axis = axis_of(n0);
    const V3 origin = f0.corners[0];
    FT source_area = 0;
    for (std::uint32_t f : s.faces) {
      const auto& face = oracle.face({s.mesh, f});
      if (CGAL::sign(dot(face.normal, n0)) <= 0) fail(where + ": face " + std::to_string(f) + " faces another way");
      source_area += CGAL::abs(twice_signed_area(project(face.corners, axis)));
    }
    // Twice the signed area seen from the front, after checking the plane.
    auto area_of = [&](const ShadowPolygon& p, const std::string& what) {
      FT sum = 0;
      auto contour = [&](const std::vector<ShadowPoint>& c, bool hole) {
        const auto cs = corners(c);
        for (const V3& q : cs)
          if (!CGAL::is_zero(dot(n0, sub(q, origin)))) {
            fail(where + ": a vertex of a " + what + " polygon is off the source's plane");
            break;
          }
        FT a = twice_signed_area(project(cs, axis));
        if (CGAL::is_negative(front[axis])) a = -a;
        if (hole ? !CGAL::is_negative(a) : !CGAL::is_positive(a))
          fail(where + ": a " + what + " polygon's " + (hole ? "hole" : "outer contour") + " is oriented wrongly");
        sum += a;
      };
      contour(p.outer, false);
      for (const auto& h : p.holes) contour(h, true);
      return sum;
    };
    auto sample = [&](const ShadowPolygon& p) -> std::optional<V3> {
      std::vector<std::vector<P2>> holes;
      for (const auto& h : p.holes) holes.push_back(project(corners(h), axis));
      auto q = interior_point(project(corners(p.outer), axis), holes);
      if (!q) return std::nullopt;
      return lift(*q, axis, n0, origin);
    };

    if (s.lights.size() != lights.size()) {
      fail(where + ": wrong number of lights");
      continue;
    }
    for (std::size_t k = 0; k < lights.size(); ++k) {
      const auto& sl = s.lights[k];
      const std::string at = where + " light " + std::to_string(k);
      const int side = oracle.facing({s.mesh, s.faces.front()}, toward(k, origin));
      const Facing expected = side < 0 ? Facing::toward : side == 0 ? Facing::edge_on : Facing::away;
      if (sl.facing != expected) {
        fail(at + ": facing " + hidden_line::facing_name(sl.facing) + ", expected " + hidden_line::facing_name(expected));
        continue;
      }
      FT covered = 0, lit = 0;
      std::size_t sampled = 0;
      for (const auto& p : sl.lit) {
        const FT a = area_of(p, "lit");
        lit += a;
        covered += a;
        if (options.max_polygons && sampled >= options.max_polygons) continue;
        ++sampled;
        if (expected != Facing::toward) fail(at + ": lit polygon on a source that does not face the light");
        auto q = sample(p);
        if (!q) fail(at + ": lit polygon without an interior point");
        else if (oracle.probe(*q, toward(k, *q), point(k)).blocked)
          fail(at + ": a point inside a lit polygon does not see the light");
      }
      if (lit != sl.lit_area2) fail(at + ": lit_area2 is not the lit polygons' area");
      sampled = 0;
      for (const auto& sh : sl.shadow) {
        covered += area_of(sh.polygon, "shadow");
        if (expected != Facing::toward) {
          if (!sh.by.empty()) fail(at + ": attached shadow with `by`");
          continue;
        }
        if (options.max_polygons && sampled >= options.max_polygons) continue;
        ++sampled;
        if (sh.by.empty()) fail(at + ": cast shadow without `by`");
        auto q = sample(sh.polygon);
        if (!q) {
          fail(at + ": shadow polygon without an interior point");
          continue;
        }
        const RayProbe probe = oracle.probe(*q, toward(k, *q), point(k));
        if (!probe.blocked) {
          fail(at + ": a point inside a shadow polygon sees the light");
          continue;
        }
        bool named = false;
        for (const auto& f : probe.nearest)
          named |= std::find(sh.by.begin(), sh.by.end(), std::array<std::uint32_t, 2>{f.mesh, f.face}) != sh.by.end();
        if (!named) fail(at + ": `by` does not name a face nearest to the light over the shadow");
      }
      if (covered != source_area) {
        std::ostringstream e;
        e << at << ": lit + shadow = " << CGAL::to_double(covered) / 2 << ", source " << CGAL::to_double(source_area) / 2
          << " (projected)";
        fail(e.str());
      }
      // Coverage at an interior point of every face.
      for (std::uint32_t f : s.faces) {
        const auto& face = oracle.face({s.mesh, f});
        auto q2 = interior_point(project(face.corners, axis), {});
        if (!q2) continue;
        int strictly = 0, closed = 0;
        auto test = [&](const ShadowPolygon& p) {
          const auto outer = project(corners(p.outer), axis);
          int in = locate(outer, *q2);
          for (const auto& h : p.holes) {
            const int hl = locate(project(corners(h), axis), *q2);
            if (hl == 1) in = -1;
            else if (hl == 0 && in == 1) in = 0;
          }
          strictly += in == 1;
          closed += in >= 0;
        };
        for (const auto& p : sl.lit) test(p);
        for (const auto& sh : sl.shadow) test(sh.polygon);
        if (strictly > 1 || closed < 1)
          fail(at + ": an interior point of face " + std::to_string(f) + " lies in " + std::to_string(strictly) +
               " polygons (" + std::to_string(closed) + " with their boundaries)");
      }
      // Per-face areas.
      if (k < result.face_lit_area2.size()) {
        FT sum = 0;
        for (std::uint32_t f : s.faces) {
          const FT& fl = result.face_lit_area2[k][s.mesh][f];
          sum += fl;
          if (CGAL::is_negative(fl) || fl > result.face_area2[s.mesh][f])
            fail(at + ": face " + std::to_string(f) + " lit more than its area, or less than none");
        }
        if (sum != sl.lit_area2) fail(at + ": the faces' lit areas do not add up to the source's");
      }
    }
  }
  return errors;
}

}  // namespace hlr::hltest
