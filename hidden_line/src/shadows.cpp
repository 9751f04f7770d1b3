// cast_shadows (shadows.hpp): the light views, their area sorts, and the fragments taken back to
// model space, on the exact kernel. The only translation unit that instantiates shadow code.
//
// Stages per light:
//   1. light view: ViewFrame looking along the light direction (a point light: the perspective
//      view from it, point_light_view); build_sources (back faces of closed components removed,
//      as they lie behind their own front faces; edge-on faces dropped, as they cast no shadow of
//      positive area; coplanar faces consolidated);
//   2. area_sort with the hidden polygons kept;
//   3. map back: each fragment of a source facing the light is lifted onto the source's plane
//      (the rational map in shadows.hpp); visible fragments and coplanar ties are lit, the other
//      hidden fragments are cast shadow, tagged with the faces of the visible fragments over them;
//      per-face lit areas come from clipping the lit fragments by each face of a consolidated
//      source in the light view, where faces and fragments share their support lines.
// A point light among the geometry runs stages 1-3 once per pyramid of its cube (cube_views), the
// sources of each view cut to its square first; lit pieces, shadows and per-face areas add up
// over the views (each piece lies in one pyramid).
// Sources facing away or seen edge-on are in attached shadow: their model-space polygons, built
// once for all lights (model_sources), are the shadow.
// shadows_in_view takes the result into another view as surface detail (hlr draw --sun).
#include <hlr/hidden_line/shadows.hpp>

#include "box_index.hpp"
#include "sources_impl.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <memory>
#include <stdexcept>
#include <unordered_map>

namespace hlr::hidden_line {
namespace {

using K = ExactKernel;
using G = Geometry<K>;
using FT = ShadowFT;
using P2 = G::Point;
using Clock = std::chrono::steady_clock;

using Vec3FT = std::array<FT, 3>;

// Newell's normal of a face, exact: twice its area times the unit normal of its winding.
Vec3FT newell_normal(const Mesh& mesh, const std::vector<std::uint32_t>& face) {
  FT nx = 0, ny = 0, nz = 0;
  for (std::size_t i = 0; i < face.size(); ++i) {
    const auto& p = mesh.vertices[face[i]];
    const auto& q = mesh.vertices[face[(i + 1) % face.size()]];
    nx += (FT(p[1]) - FT(q[1])) * (FT(p[2]) + FT(q[2]));
    ny += (FT(p[2]) - FT(q[2])) * (FT(p[0]) + FT(q[0]));
    nz += (FT(p[0]) - FT(q[0])) * (FT(p[1]) + FT(q[1]));
  }
  return {nx, ny, nz};
}

int largest_axis(const Vec3FT& n) {
  int axis = 0;
  for (int k = 1; k < 3; ++k)
    if (CGAL::abs(n[k]) > CGAL::abs(n[axis])) axis = k;
  return axis;
}

// Model area from twice the area projected along `axis`: times |n| / |n_axis|, in double.
double area_factor(const Vec3FT& n, int axis) {
  double sq = 0;
  for (const FT& c : n) sq += G::rough_double(c) * G::rough_double(c);
  return std::sqrt(sq) / std::abs(G::rough_double(n[axis]));
}

// Twice the signed area of a contour's projection along `axis` (counter-clockwise seen from +axis
// is positive).
FT twice_projected_area(const std::vector<ShadowPoint>& c, int axis) {
  auto coord = [](const ShadowPoint& p, int k) -> const FT& { return k == 0 ? p.x : k == 1 ? p.y : p.z; };
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  FT sum = 0;
  for (std::size_t i = 0; i < c.size(); ++i) {
    const ShadowPoint& a = c[i];
    const ShadowPoint& b = c[(i + 1) % c.size()];
    sum += coord(a, u) * coord(b, v) - coord(b, u) * coord(a, v);
  }
  return sum;
}

// Twice the area of a polygon oriented as seen from the front of a plane with normal n.
FT twice_area_seen_from_front(const ShadowPolygon& p, const Vec3FT& n, int axis) {
  FT sum = twice_projected_area(p.outer, axis);
  for (const auto& h : p.holes) sum += twice_projected_area(h, axis);
  return CGAL::is_negative(n[axis]) ? -sum : sum;
}

std::array<std::uint32_t, 3> uv_axes(int axis) { return {std::uint32_t((axis + 1) % 3), std::uint32_t((axis + 2) % 3), std::uint32_t(axis)}; }

// ---------------------------------------------------------------------------------------------
// The light-independent sources.

struct ModelSources {
  std::vector<ShadowSource> sources;
  std::vector<std::vector<std::uint32_t>> face_source;
  std::vector<std::vector<FT>> face_area2;
  std::vector<std::vector<double>> face_area;
  std::vector<double> factor;  // per source: area_factor
};

ModelSources model_sources(const std::vector<Mesh>& meshes) {
  ModelSources out;
  for (std::uint32_t mi = 0; mi < meshes.size(); ++mi) {
    const Mesh& mesh = meshes[mi];
    const std::size_t nf = mesh.faces.size();
    const detail::MeshTopology topo = detail::analyse_mesh(mesh);
    std::vector<Vec3FT> winding(nf);
    for (std::uint32_t f = 0; f < nf; ++f) winding[f] = newell_normal(mesh, mesh.faces[f]);
    auto front = [&](std::uint32_t f) {
      Vec3FT n = winding[f];
      if (topo.outward[f] < 0)
        for (FT& c : n) c = -c;
      return n;
    };
    auto& face_source = out.face_source.emplace_back(nf, 0);
    auto& face_area2 = out.face_area2.emplace_back(nf, FT(0));
    auto& face_area = out.face_area.emplace_back(nf, 0.0);

    // A face's contour in the plane of the two coordinates other than `axis`, counter-clockwise
    // there, on lines of `lines` (one per mesh edge of the group).
    auto face_contour = [&](std::uint32_t f, int axis, clip::LineTable<K>& lines,
                            std::unordered_map<std::uint64_t, clip::LineId>& line_of) {
      const auto ax = uv_axes(axis);
      const auto& face = mesh.faces[f];
      const std::size_t n = face.size();
      const bool reverse = CGAL::is_negative(winding[f][axis]);
      clip::Contour<K> c;
      for (std::size_t i = 0; i < n; ++i) {
        const std::uint32_t a = face[reverse ? n - 1 - i : i];
        const std::uint32_t b = face[reverse ? (2 * n - 2 - i) % n : (i + 1) % n];
        const auto& p = mesh.vertices[a];
        c.points.push_back(G::point(FT(p[ax[0]]), FT(p[ax[1]])));
        auto [it, added] = line_of.try_emplace(edge_key(a, b), clip::LineId(lines.size()));
        if (added) {
          const auto& q = mesh.vertices[b];
          lines.push_back({G::point(FT(p[ax[0]]), FT(p[ax[1]])), G::point(FT(q[ax[0]]), FT(q[ax[1]]))});
        }
        c.lines.push_back(it->second);
      }
      return c;
    };
    auto lift_contour = [&](const clip::Contour<K>& c, int axis, const Vec3FT& n, const FT& offset) {
      const auto ax = uv_axes(axis);
      std::vector<ShadowPoint> out3;
      for (const P2& q : c.points) {
        FT p[3];
        p[ax[0]] = q.x();
        p[ax[1]] = q.y();
        p[ax[2]] = -(n[ax[0]] * q.x() + n[ax[1]] * q.y() + offset) / n[axis];
        out3.push_back({p[0], p[1], p[2]});
      }
      // Counter-clockwise seen from +axis; seen from the front when the normal points that way.
      if (CGAL::is_negative(n[axis])) std::reverse(out3.begin(), out3.end());
      return out3;
    };
    auto add_source = [&](std::vector<std::uint32_t> faces, const std::vector<clip::Polygon<K>>& uv) {
      ShadowSource s;
      s.mesh = mi;
      s.normal = front(faces.front());
      s.axis = largest_axis(s.normal);
      const auto& p0 = mesh.vertices[mesh.faces[faces.front()][0]];
      s.offset = -(s.normal[0] * FT(p0[0]) + s.normal[1] * FT(p0[1]) + s.normal[2] * FT(p0[2]));
      for (const auto& polygon : uv) {
        ShadowPolygon p;
        p.outer = lift_contour(polygon.outer, s.axis, s.normal, s.offset);
        for (const auto& h : polygon.holes) p.holes.push_back(lift_contour(h, s.axis, s.normal, s.offset));
        s.area2 += clip::twice_area(polygon);
        s.polygons.push_back(std::move(p));
      }
      const double factor = area_factor(s.normal, s.axis);
      s.area = G::to_double(s.area2) / 2 * factor;
      const auto id = std::uint32_t(out.sources.size());
      for (std::uint32_t f : faces) face_source[f] = id;
      s.faces = std::move(faces);
      out.sources.push_back(std::move(s));
      out.factor.push_back(factor);
    };

    std::vector<std::vector<std::uint32_t>> members(nf);
    for (std::uint32_t f = 0; f < nf; ++f) members[topo.coplanar_group[f]].push_back(f);
    for (std::uint32_t g = 0; g < nf; ++g) {
      const auto& faces = members[g];
      if (faces.empty()) continue;
      const int axis = largest_axis(winding[faces.front()]);
      clip::LineTable<K> lines;
      std::unordered_map<std::uint64_t, clip::LineId> line_of;
      std::vector<clip::Contour<K>> contours;
      for (std::uint32_t f : faces) {
        contours.push_back(face_contour(f, axis, lines, line_of));
        face_area2[f] = clip::twice_signed_area(contours.back());
        face_area[f] = G::to_double(face_area2[f]) / 2 * area_factor(winding[f], axis);
      }
      if (faces.size() > 1) {
        try {
          add_source(faces, clip::merge_polygons<K>(contours, lines));
          continue;
        } catch (const clip::ClipError&) {
          // The group's faces overlap (as in build_sources): keep them apart.
        }
      }
      for (std::size_t i = 0; i < faces.size(); ++i) {
        clip::Polygon<K> polygon{contours[i], {}};
        if (mesh.faces[faces[i]].size() > 3)
          if (auto defect = clip::normalize_polygon(polygon))
            throw clip::ClipError("face " + std::to_string(mesh.face_index[faces[i]]) + " of " + mesh.file +
                                  " is not a simple polygon (" + *defect + ")");
        add_source({faces[i]}, {polygon});
      }
    }
  }
  return out;
}

// ---------------------------------------------------------------------------------------------
// One light.

Vec3FT cross(const Vec3FT& a, const Vec3FT& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
FT dot(const Vec3FT& a, const Vec3FT& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// Looking along `direction`: up +Z, or +Y when the direction is vertical.
View light_view_along(const Vec3& direction) {
  View v;
  v.name = "light";
  v.direction = direction;
  v.up = direction[0] == 0 && direction[1] == 0 ? Vec3{0, 1, 0} : Vec3{0, 0, 1};
  return v;
}

// One view of a light: its own view, or one pyramid of the cube around a point light.
struct LightPyramid {
  View view;
  int axis = -1;  // the pyramid (index into kCubeAxes), or -1: the light's one view, unclipped
};

// The cube around a point light e: six pyramids with apex e, along +X, -X, +Y, -Y, +Z, -Z.
// Pyramid i holds the points p with s (p - e)_a >= |(p - e)_b|, |(p - e)_c| (axis a, sign s, b and c
// the other two); the perspective view from e along its axis (light_view_along: up +Z, or +Y for
// +-Z, so that the view's axes are unit and orthogonal) maps it onto the square [-1, 1]^2 of its
// image. The pyramids cover space and overlap only on their planes (p - e)_a = +-(p - e)_b, which pass
// through e: a face with area in one contains e in its plane, is edge-on to the light and cast no
// shadow of area, so the pyramids' lit and shadow polygons add up to each source exactly once.
const Vec3 kCubeAxes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};

// A positive lower bound on the depth s (p - e)_a of the points of the scene inside pyramid
// `axis`, or nothing when no face reaches into it. Each face is clipped by the pyramid's four
// planes (Sutherland-Hodgman, exact): every corner left lies in the closed pyramid, and the corners
// of the face's part inside are among them (a non-convex face may add corners on the planes that
// lie outside it, which only lower the bound). Depth 0 in the closed pyramid is e itself; faces
// whose plane holds e are left out (edge-on from e: build_sources drops them in every view).
std::optional<FT> least_depth_in_pyramid(const std::vector<Mesh>& meshes, const Vec3FT& e, int axis) {
  const int a = axis / 2, b = (a + 1) % 3, c = (a + 2) % 3;
  const bool negative = axis % 2 == 1;
  auto depth = [&](const Vec3FT& q) { return negative ? -q[a] : q[a]; };
  std::optional<FT> least;
  std::vector<Vec3FT> ring, next;
  for (const Mesh& mesh : meshes)
    for (const auto& face : mesh.faces) {
      ring.clear();
      for (std::uint32_t v : face) {
        const Vec3& p = mesh.vertices[v];
        ring.push_back({FT(p[0]) - e[0], FT(p[1]) - e[1], FT(p[2]) - e[2]});
      }
      if (ring.size() < 3 || CGAL::is_zero(dot(newell_normal(mesh, face), ring.front()))) continue;
      for (int plane = 0; plane < 4 && !ring.empty(); ++plane) {
        const int other = plane < 2 ? b : c;
        auto side = [&](const Vec3FT& q) { return plane % 2 ? depth(q) + q[other] : depth(q) - q[other]; };
        next.clear();
        for (std::size_t i = 0; i < ring.size(); ++i) {
          const Vec3FT& p = ring[i];
          const Vec3FT& q = ring[(i + 1) % ring.size()];
          const FT hp = side(p), hq = side(q);
          if (!CGAL::is_negative(hp)) next.push_back(p);
          if ((CGAL::is_positive(hp) && CGAL::is_negative(hq)) || (CGAL::is_negative(hp) && CGAL::is_positive(hq))) {
            const FT t = hp / (hp - hq);
            next.push_back({p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1]), p[2] + t * (q[2] - p[2])});
          }
        }
        ring.swap(next);
      }
      for (const Vec3FT& q : ring)
        if (!least || depth(q) < *least) least = depth(q);
    }
  return least;
}

// The views of the cube around a point light that see something, each with its near plane at a
// power-of-two fraction of the scene's deepest vertex, strictly before everything in its pyramid
// (so that the near plane cuts only what lies outside the closed pyramid, which the square cuts
// away anyway).
std::vector<LightPyramid> cube_views(const std::vector<Mesh>& meshes, const Vec3& e) {
  const Vec3FT eye{FT(e[0]), FT(e[1]), FT(e[2])};
  std::vector<LightPyramid> out;
  for (int axis = 0; axis < 6; ++axis) {
    const auto least = least_depth_in_pyramid(meshes, eye, axis);
    if (!least) continue;
    View view = light_view_along(kCubeAxes[axis]);
    view.eye = e;
    std::optional<FT> deepest;
    const Vec3FT d{FT(kCubeAxes[axis][0]), FT(kCubeAxes[axis][1]), FT(kCubeAxes[axis][2])};
    for (const Mesh& mesh : meshes)
      for (const Vec3& p : mesh.vertices) {
        const FT w = dot(d, {FT(p[0]) - eye[0], FT(p[1]) - eye[1], FT(p[2]) - eye[2]});
        if (!deepest || *deepest < w) deepest = w;
      }
    double fraction = 0.5;
    while (fraction > 0 && !(*deepest * FT(fraction) < *least)) fraction /= 2;
    if (fraction == 0) throw std::invalid_argument("the point light is too close to a face for its cube of views");
    view.near_fraction = fraction;
    out.push_back({view, axis});
  }
  return out;
}

class LightSolver {
 public:
  LightSolver(const std::vector<Mesh>& meshes, ModelSources& model, ShadowResult& result, std::size_t light_index,
              std::size_t light_count, const ShadowOptions& options)
      : meshes_(meshes), model_(model), result_(result), k_(light_index), light_count_(light_count), options_(options) {}

  // Solves one light in its views: the light's one view (light_view_along, point_light_view), or
  // the pyramids of the cube around a point light (cube_views), each clipped to its square.
  void run(const Light& light, const std::vector<LightPyramid>& views, const std::vector<std::vector<bool>>* culled = nullptr) {
    culled_ = culled;
    if (light.kind == Light::point) eye_ = Vec3FT{FT(light.vector[0]), FT(light.vector[1]), FT(light.vector[2])};
    const Vec3& dir = light.vector;
    const Vec3FT d{FT(dir[0]), FT(dir[1]), FT(dir[2])};
    // Facing of every model source, and its slot for this light.
    for (auto& s : model_.sources) {
      // Negative where the light is on the front side: directional, the rays travel against the
      // front normal; point, the light lies in front of the plane (eye-based, as in perspective).
      const int side = eye_ ? -CGAL::sign(dot(s.normal, *eye_) + s.offset) : CGAL::sign(dot(s.normal, d));
      SourceLight sl;
      sl.facing = side < 0 ? Facing::toward : side == 0 ? Facing::edge_on : Facing::away;
      if (sl.facing != Facing::toward)
        for (const auto& p : s.polygons) sl.shadow.push_back({p, {}});
      s.lights.push_back(std::move(sl));
    }
    start_face_areas();
    LightView picture;
    for (std::size_t i = 0; i < views.size(); ++i) {
      if (views.size() > 1)
        stage_ = "light " + std::to_string(k_ + 1) + " of " + std::to_string(light_count_) + ", view " +
                 std::to_string(i + 1) + " of " + std::to_string(views.size());
      else
        stage_ = "light " + std::to_string(k_ + 1) + " of " + std::to_string(light_count_);
      solve_view(views[i], picture);
    }
    // Each face's lit area rounded once, from its exact sum over the pieces (and the views).
    auto& lit_area = result_.face_lit_area.back();
    const auto& lit_area2 = result_.face_lit_area2.back();
    for (std::size_t mi = 0; mi < meshes_.size(); ++mi)
      for (std::size_t f = 0; f < meshes_[mi].faces.size(); ++f)
        lit_area[mi][f] = G::to_double(lit_area2[mi][f]) / 2 * model_.factor[model_.face_source[mi][f]];
    if (options_.light_views) {
      if (!views.empty() && views.front().axis >= 0) {
        picture.view = views.front().view;
        for (const auto& v : views) picture.pyramids.push_back(v.view);
      }
      result_.views.push_back(std::move(picture));
    }
  }

  // Per face, its lit polygons in model space (union_shadows), or empty when not asked for.
  std::vector<std::vector<std::vector<clip::Polygon<K>>>> face_lit_uv;

 private:
  // One view of the light: its sources (clipped to the pyramid's square for a cube view), their
  // area sort, and the fragments taken back to model space as lit and shadow polygons.
  void solve_view(const LightPyramid& pyramid, LightView& picture) {
    const View& view = pyramid.view;
    const ViewFrame<K> frame(view, meshes_);
    const Vec3FT d{FT(view.direction[0]), FT(view.direction[1]), FT(view.direction[2])};
    const Vec3FT up{FT(view.up[0]), FT(view.up[1]), FT(view.up[2])};
    // The axes of ViewFrame (the same formulas), each over its squared length: the inverse map.
    const Vec3FT X = cross(d, up), Y = cross(X, d), Z{-d[0], -d[1], -d[2]};
    const FT nx = dot(X, X), ny = dot(Y, Y), nz = dot(Z, Z);
    for (int i = 0; i < 3; ++i) {
      inverse_[0][i] = X[i] / nx;
      inverse_[1][i] = Y[i] / ny;
      inverse_[2][i] = Z[i] / nz;
    }
    // Line ids and light-view sources are this view's own; lit polygons before this view were
    // counted by the views before it.
    crossings_ = {};
    face_indices_.clear();
    square_.reset();
    lit_before_.clear();
    for (const auto& s : model_.sources) lit_before_.push_back(s.lights[k_].lit.size());

    const std::string& name = stage_;
    options_.progress.check();
    options_.progress.report(name + ": light view");
    auto mark = Clock::now();
    SourceOptions source_options;
    source_options.remove_back_faces = true;
    source_options.consolidate = true;
    source_options.culled = culled_;
    sources_ = build_sources<K>(meshes_, frame, source_options);
    if (pyramid.axis >= 0) clip_sources_to_square();
    result_.times.views += seconds_since(mark);
    options_.progress.check();
    options_.progress.report(name + ": sorting " + std::to_string(sources_.polygons.size()) + " polygons");
    mark = Clock::now();
    AreaSortOptions sort_options = options_.sort;
    sort_options.keep_hidden = true;
    sort_options.stop = options_.progress.stop;
    const VisibilityMap<K> map = area_sort<K>(sources_, sort_options);
    result_.times.sort += seconds_since(mark);
    options_.progress.check();
    options_.progress.report(name + ": lit and shadow polygons");
    mark = Clock::now();

    model_of_.resize(sources_.polygons.size());
    for (std::size_t i = 0; i < sources_.polygons.size(); ++i) {
      const auto& sp = sources_.polygons[i];
      model_of_[i] = model_.face_source[sp.mesh][sp.faces.front()];
    }
    auto toward = [&](std::uint32_t area_source) {
      return model_.sources[model_of_[area_source]].lights[k_].facing == Facing::toward;
    };

    // The visible fragments: the nearest surface everywhere, indexed for `by`.
    CGAL::Bbox_2 domain;
    for (const auto& v : map.visible) domain += detail::box_of(v.polygon);
    detail::LooseGrid grid(domain, map.visible.size());
    for (std::uint32_t i = 0; i < map.visible.size(); ++i) grid.insert(i, detail::box_of(map.visible[i].polygon));

    lit_view_.assign(model_.sources.size(), {});
    for (const auto& v : map.visible)
      if (toward(v.source)) add_lit(v.polygon, v.source);
    auto coplanar = [&](std::uint32_t a, std::uint32_t b) {
      const auto &p = *sources_.polygons[a].plane, &q = *sources_.polygons[b].plane;
      return p.a == q.a && p.b == q.b && p.c == q.c;
    };
    for (const auto& h : map.hidden) {
      if (!toward(h.source)) continue;
      if (!coplanar(h.source, std::uint32_t(h.occluder))) {
        // Something strictly nearer over all of it.
        add_shadow(h.polygon, h.source, nearest_faces(h.polygon, map, grid));
        continue;
      }
      // A coplanar tie: the occluder lies in the same plane, but it need not be the nearest
      // surface there (the sort records the first front that covers a piece). The visible
      // fragments over the piece are: lit under the coplanar ones, in shadow under the others.
      std::vector<std::uint32_t> candidates;
      grid.query(detail::box_of(h.polygon), [&](std::uint32_t id) { candidates.push_back(id); });
      std::sort(candidates.begin(), candidates.end());
      std::vector<clip::Polygon<K>> subjects;
      for (std::uint32_t id : candidates) subjects.push_back(map.visible[id].polygon);
      auto parts = clip_by(h.polygon, subjects);
      for (std::size_t i = 0; i < candidates.size(); ++i) {
        const std::uint32_t over = map.visible[candidates[i]].source;
        for (auto& piece : parts[i].inside) {
          if (coplanar(h.source, over)) add_lit(piece, h.source);
          else add_shadow(piece, h.source, nearest_faces(piece, map, grid));
        }
      }
    }
    add_face_areas();
    if (options_.light_views) add_to_picture(frame, map, pyramid.axis, picture);
    result_.times.map_back += seconds_since(mark);
  }

  // A cube view sees only its pyramid: every source is cut to the square [-1, 1]^2 of the image
  // (exactly, on four auxiliary lines), and what lies outside is left to the other pyramids.
  // Sources keep their order (a coplanar tie goes to the same one as without the cut).
  void clip_sources_to_square() {
    const std::vector<P2> corners{G::point(FT(-1), FT(-1)), G::point(FT(1), FT(-1)), G::point(FT(1), FT(1)),
                                  G::point(FT(-1), FT(1))};
    square_ = clip::Polygon<K>{clip::make_contour<K>(corners, sources_.lines), {}};
    sources_.line_origins.resize(sources_.lines.size());  // auxiliary lines
    const clip::ClipRegion<K> region(*square_, sources_.lines, &crossings_);
    std::vector<clip::Polygon<K>> subjects;
    for (const auto& sp : sources_.polygons) subjects.push_back(sp.polygon);
    auto parts = clip::clip_list<K>(subjects, region);
    std::vector<SourcePolygon<K>> kept;
    for (std::size_t i = 0; i < parts.size(); ++i)
      for (auto& piece : parts[i].inside) {
        SourcePolygon<K> sp = sources_.polygons[i];
        sp.polygon = std::move(piece);
        kept.push_back(std::move(sp));
      }
    sources_.polygons = std::move(kept);
  }
  // A light-view piece of a light-view source, lit or in cast shadow.
  void add_lit(const clip::Polygon<K>& polygon, std::uint32_t area_source) {
    const std::uint32_t m = model_of_[area_source];
    SourceLight& sl = model_.sources[m].lights[k_];
    ShadowPolygon p = lift(polygon, area_source);
    const FT a2 = twice_area_seen_from_front(p, model_.sources[m].normal, model_.sources[m].axis);
    sl.lit_area2 += a2;
    sl.lit_area += G::to_double(a2) / 2 * model_.factor[m];
    sl.lit.push_back(std::move(p));
    lit_view_[m].push_back({polygon, area_source});
  }
  void add_shadow(const clip::Polygon<K>& polygon, std::uint32_t area_source,
                  std::vector<std::array<std::uint32_t, 2>> by) {
    CastShadow shadow;
    shadow.polygon = lift(polygon, area_source);
    shadow.by = std::move(by);
    model_.sources[model_of_[area_source]].lights[k_].shadow.push_back(std::move(shadow));
  }

  ShadowPoint lift(const P2& q, const DepthPlane<K>& plane) const {
    const FT x = q.x(), y = q.y();
    const FT z = plane.a * x + plane.b * y + plane.c;
    if (eye_) {
      // Perspective: (x, y, z) = (X·q, Y·q, 1)/w with q = p − e and w = d·q; Z/|Z|² = −d/|d|².
      const Vec3FT& e = *eye_;
      auto at = [&](int i) { return e[i] + (x * inverse_[0][i] + y * inverse_[1][i] - inverse_[2][i]) / z; };
      return {at(0), at(1), at(2)};
    }
    return {x * inverse_[0][0] + y * inverse_[1][0] + z * inverse_[2][0],
            x * inverse_[0][1] + y * inverse_[1][1] + z * inverse_[2][1],
            x * inverse_[0][2] + y * inverse_[1][2] + z * inverse_[2][2]};
  }
  // Light-view counter-clockwise is counter-clockwise seen from the light, which is the front of a
  // source facing it: no reversal.
  ShadowPolygon lift(const clip::Polygon<K>& polygon, std::uint32_t area_source) const {
    const auto& plane = *sources_.polygons[area_source].plane;
    ShadowPolygon out;
    for (const P2& q : polygon.outer.points) out.outer.push_back(lift(q, plane));
    for (const auto& h : polygon.holes) {
      auto& c = out.holes.emplace_back();
      for (const P2& q : h.points) c.push_back(lift(q, plane));
    }
    return out;
  }

  // A face of a light-view source as polygons on the light view's support lines: its image, or in
  // a cube view its image's part inside the square. A face the near plane cuts is its ring there
  // (near_plane.hpp); the cut lies outside the pyramid (the near plane is before everything in
  // it), so the square takes it away, and its edge may go on a line of its own.
  std::vector<clip::Polygon<K>> face_polygons(std::uint32_t mesh, std::uint32_t f) {
    const auto& face = meshes_[mesh].faces[f];
    const auto& points = sources_.image_points[mesh];
    const auto& edge_lines = sources_.edge_lines[mesh];
    auto line_of = [&](std::uint32_t a, std::uint32_t b) {
      const std::uint64_t key = edge_key(a, b);
      auto it = std::lower_bound(edge_lines.begin(), edge_lines.end(), key,
                                 [](const auto& e, std::uint64_t k) { return e.first < k; });
      return it->second;
    };
    clip::Contour<K> c;
    const NearCut<K>& cut = sources_.near_cuts[mesh];
    if (cut.part(f) == NearCut<K>::Part::cut) {
      const auto& ring = cut.ring(f);
      for (std::size_t i = 0; i < ring.size(); ++i) {
        c.points.push_back(points[ring[i].point]);
        if (ring[i].a != NearCut<K>::kCut) {
          c.lines.push_back(line_of(ring[i].a, ring[i].b));
        } else {
          c.lines.push_back(clip::LineId(sources_.lines.size()));
          sources_.lines.push_back({points[ring[i].point], points[ring[(i + 1) % ring.size()].point]});
          sources_.line_origins.resize(sources_.lines.size());  // auxiliary
        }
      }
    } else {
      for (std::size_t i = 0; i < face.size(); ++i) {
        c.points.push_back(points[face[i]]);
        c.lines.push_back(line_of(face[i], face[(i + 1) % face.size()]));
      }
    }
    if (CGAL::is_negative(clip::twice_signed_area(c))) {
      std::reverse(c.points.begin(), c.points.end());
      std::reverse(c.lines.begin(), c.lines.end());
      std::rotate(c.lines.begin(), c.lines.begin() + 1, c.lines.end());
    }
    clip::Polygon<K> polygon{std::move(c), {}};
    if (!square_) return {std::move(polygon)};
    return clip_by(*square_, std::span<const clip::Polygon<K>>(&polygon, 1))[0].inside;
  }

  // The faces of a consolidated light-view source as polygons, with a grid of their boxes: made
  // once per source, when `by` or a per-face area first needs them.
  struct FaceIndex {
    std::vector<clip::Polygon<K>> polygons;
    std::vector<std::uint32_t> face_of;  // per polygon: its face, as an index into the source's faces
    detail::LooseGrid grid;
  };
  const FaceIndex& face_index(std::uint32_t area_source) {
    auto it = face_indices_.find(area_source);
    if (it != face_indices_.end()) return *it->second;
    const auto& sp = sources_.polygons[area_source];
    std::vector<clip::Polygon<K>> polygons;
    std::vector<std::uint32_t> face_of;
    CGAL::Bbox_2 domain;
    for (std::uint32_t k = 0; k < sp.faces.size(); ++k)
      for (auto& polygon : face_polygons(sp.mesh, sp.faces[k])) {
        domain += detail::box_of(polygon);
        polygons.push_back(std::move(polygon));
        face_of.push_back(k);
      }
    const std::size_t count = polygons.size();
    auto index = std::make_unique<FaceIndex>(FaceIndex{std::move(polygons), std::move(face_of), detail::LooseGrid(domain, count)});
    for (std::uint32_t k = 0; k < index->polygons.size(); ++k) index->grid.insert(k, detail::box_of(index->polygons[k]));
    return *face_indices_.emplace(area_source, std::move(index)).first->second;
  }

  // The pieces of `subjects` inside `region`, per subject.
  std::vector<clip::ClipResult<K>> clip_by(const clip::Polygon<K>& region, std::span<const clip::Polygon<K>> subjects) {
    const clip::ClipRegion<K> r(region, sources_.lines, &crossings_);
    return clip::clip_list<K>(subjects, r);
  }

  // The (mesh, face) pairs of the visible fragments over a hidden fragment (positive overlap).
  std::vector<std::array<std::uint32_t, 2>> nearest_faces(const clip::Polygon<K>& hidden, const VisibilityMap<K>& map,
                                                          const detail::LooseGrid& grid) {
    std::vector<std::uint32_t> candidates;
    grid.query(detail::box_of(hidden), [&](std::uint32_t id) { candidates.push_back(id); });
    std::sort(candidates.begin(), candidates.end());
    std::vector<clip::Polygon<K>> subjects;
    for (std::uint32_t id : candidates) subjects.push_back(map.visible[id].polygon);
    const auto results = clip_by(hidden, subjects);
    std::vector<std::array<std::uint32_t, 2>> by;
    for (std::size_t i = 0; i < candidates.size(); ++i) {
      if (results[i].inside.empty()) continue;
      const auto& sp = sources_.polygons[map.visible[candidates[i]].source];
      if (sp.faces.size() == 1) {
        by.push_back({sp.mesh, sp.faces.front()});
        continue;
      }
      const CGAL::Bbox_2 box = [&] {
        CGAL::Bbox_2 b;
        for (const auto& piece : results[i].inside) b += detail::box_of(piece);
        return b;
      }();
      const FaceIndex& index = face_index(map.visible[candidates[i]].source);
      std::vector<std::uint32_t> near;
      index.grid.query(box, [&](std::uint32_t k) { near.push_back(k); });
      std::sort(near.begin(), near.end());
      for (std::uint32_t k : near) {
        const auto parts = clip_by(index.polygons[k], results[i].inside);
        if (std::any_of(parts.begin(), parts.end(), [](const auto& r) { return !r.inside.empty(); }))
          by.push_back({sp.mesh, sp.faces[index.face_of[k]]});
      }
    }
    std::sort(by.begin(), by.end());
    by.erase(std::unique(by.begin(), by.end()), by.end());
    return by;
  }

  // Per face: its lit area, from its source's lit fragments (clipped by the face in the light
  // view where the source has several faces), added up over the light's views.
  void start_face_areas() {
    auto& lit_area = result_.face_lit_area.emplace_back();
    auto& lit_area2 = result_.face_lit_area2.emplace_back();
    for (std::size_t mi = 0; mi < meshes_.size(); ++mi) {
      lit_area.emplace_back(meshes_[mi].faces.size(), 0.0);
      lit_area2.emplace_back(meshes_[mi].faces.size(), FT(0));
    }
    if (options_.union_shadows) {
      face_lit_uv.assign(meshes_.size(), {});
      for (std::size_t mi = 0; mi < meshes_.size(); ++mi) face_lit_uv[mi].resize(meshes_[mi].faces.size());
    }
  }
  void add_face_areas() {
    auto& lit_area2 = result_.face_lit_area2.back();
    for (std::uint32_t m = 0; m < model_.sources.size(); ++m) {
      const ShadowSource& s = model_.sources[m];
      const SourceLight& sl = s.lights[k_];
      if (sl.facing != Facing::toward) continue;
      auto add = [&](std::uint32_t f, const ShadowPolygon& p) {
        const FT a2 = twice_area_seen_from_front(p, s.normal, s.axis);
        lit_area2[s.mesh][f] += a2;
        if (options_.union_shadows) face_lit_uv[s.mesh][f].push_back(uv_polygon(p, s));
      };
      if (s.faces.size() == 1) {
        for (std::size_t i = lit_before_[m]; i < sl.lit.size(); ++i) add(s.faces.front(), sl.lit[i]);
        continue;
      }
      // Each lit piece clipped by the faces of its light-view source that it can overlap.
      for (const auto& [polygon, area_source] : lit_view_[m]) {
        const FaceIndex& index = face_index(area_source);
        const auto& faces = sources_.polygons[area_source].faces;
        std::vector<std::uint32_t> near;
        index.grid.query(detail::box_of(polygon), [&](std::uint32_t k) { near.push_back(k); });
        std::sort(near.begin(), near.end());
        const std::span<const clip::Polygon<K>> one(&polygon, 1);
        for (std::uint32_t k : near) {
          const auto parts = clip_by(index.polygons[k], one);
          for (const auto& piece : parts[0].inside) add(faces[index.face_of[k]], lift(piece, area_source));
        }
      }
    }
  }

  // A model-space polygon of source s in its axis plane, counter-clockwise there.
  static clip::Polygon<K> uv_polygon(const ShadowPolygon& p, const ShadowSource& s) {
    const auto ax = uv_axes(s.axis);
    auto coord = [](const ShadowPoint& q, std::uint32_t k) -> const FT& { return k == 0 ? q.x : k == 1 ? q.y : q.z; };
    const bool reverse = CGAL::is_negative(s.normal[s.axis]);
    auto contour = [&](const std::vector<ShadowPoint>& c) {
      std::vector<P2> points;
      for (const auto& q : c) points.push_back(G::point(coord(q, ax[0]), coord(q, ax[1])));
      if (reverse) std::reverse(points.begin(), points.end());
      return points;
    };
    clip::Polygon<K> out;
    out.outer.points = contour(p.outer);
    for (const auto& h : p.holes) out.holes.push_back({contour(h), {}});
    return out;
  }

  // The view's visible fragments into the picture. A cube view's square goes to its place in a
  // 3 x 2 layout (+X, -X, +Y over -Y, +Z, -Z), 2.5 apart.
  void add_to_picture(const ViewFrame<K>& frame, const VisibilityMap<K>& map, int axis, LightView& picture) {
    if (picture.polygons.empty() && picture.pyramids.empty()) {
      picture.view = frame.view();
      picture.world_to_view = frame.world_to_view();
    }
    const double dx = axis < 0 ? 0 : 2.5 * (axis % 3), dy = axis < 0 ? 0 : -2.5 * (axis / 3);
    auto rounded = [&](const clip::Contour<K>& c) {
      std::vector<std::array<double, 2>> out;
      for (const P2& q : c.points) out.push_back({frame.rounded(q, 0) + dx, frame.rounded(q, 1) + dy});
      return out;
    };
    for (const auto& v : map.visible) {
      LightViewPolygon p;
      p.outer = rounded(v.polygon.outer);
      for (const auto& h : v.polygon.holes) p.holes.push_back(rounded(h));
      p.source = model_of_[v.source];
      p.lit = model_.sources[p.source].lights[k_].facing == Facing::toward;
      picture.polygons.push_back(std::move(p));
    }
  }

  const std::vector<Mesh>& meshes_;
  ModelSources& model_;
  ShadowResult& result_;
  std::size_t k_, light_count_;
  const ShadowOptions& options_;
  FT inverse_[3][3];
  std::optional<Vec3FT> eye_;  // a point light's position
  Sources<K> sources_;
  std::vector<std::uint32_t> model_of_;  // per light-view source: its model source
  std::vector<std::vector<std::pair<clip::Polygon<K>, std::uint32_t>>> lit_view_;  // per model source: lit pieces
  clip::CrossingCache<K> crossings_;
  std::unordered_map<std::uint32_t, std::unique_ptr<FaceIndex>> face_indices_;
  std::optional<clip::Polygon<K>> square_;  // a cube view: its pyramid's square [-1, 1]^2
  std::vector<std::size_t> lit_before_;  // per model source: its lit polygons from earlier views
  std::string stage_;                    // "light 2 of 7" (", view 3 of 6")
  const std::vector<std::vector<bool>>* culled_ = nullptr;  // faces left out of the light view
};

}  // namespace

const char* facing_name(Facing facing) {
  switch (facing) {
    case Facing::toward: return "toward";
    case Facing::away: return "away";
    case Facing::edge_on: return "edge-on";
  }
  return "?";
}

std::optional<std::string> light_defect(const Light& light) {
  for (double c : light.vector)
    if (!std::isfinite(c))
      return light.kind == Light::directional ? "light direction is not finite" : "light position is not finite";
  if (light.kind == Light::directional && light.vector == Vec3{0, 0, 0}) return "light direction is zero";
  return std::nullopt;
}

namespace {

// The light view along d if every vertex lies strictly in front of the light (d·(p − e) > 0,
// exact), with its near plane at a power-of-two fraction of the deepest vertex, at or before the
// nearest one (so that nothing is clipped).
std::optional<View> view_if_in_front(const std::vector<Mesh>& meshes, const Vec3& e, const Vec3& d) {
  if (!std::isfinite(d[0] + d[1] + d[2]) || d == Vec3{0, 0, 0}) return std::nullopt;
  std::optional<FT> nearest, deepest;
  for (const Mesh& mesh : meshes)
    for (const Vec3& p : mesh.vertices) {
      const FT w = FT(d[0]) * (FT(p[0]) - FT(e[0])) + FT(d[1]) * (FT(p[1]) - FT(e[1])) + FT(d[2]) * (FT(p[2]) - FT(e[2]));
      if (!CGAL::is_positive(w)) return std::nullopt;
      if (!nearest || w < *nearest) nearest = w;
      if (!deepest || *deepest < w) deepest = w;
    }
  if (!nearest) return std::nullopt;
  double fraction = 0.5;
  while (fraction > 0 && *deepest * FT(fraction) > *nearest) fraction /= 2;
  if (fraction == 0) return std::nullopt;
  View view = light_view_along(d);
  view.eye = e;
  view.near_fraction = fraction;
  return view;
}

}  // namespace

std::optional<View> point_light_view(const std::vector<Mesh>& meshes, const Light& light) {
  const Vec3& e = light.vector;
  double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  std::size_t count = 0;
  double centroid[3] = {0, 0, 0};
  for (const Mesh& mesh : meshes)
    for (const Vec3& p : mesh.vertices) {
      ++count;
      for (int k = 0; k < 3; ++k) {
        lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
        centroid[k] += p[k];
      }
    }
  if (count == 0) return std::nullopt;
  // Directions are only candidates (their rounding is harmless): each is tested exactly.
  const Vec3 candidates[] = {{lo[0] / 2 + hi[0] / 2 - e[0], lo[1] / 2 + hi[1] / 2 - e[1], lo[2] / 2 + hi[2] / 2 - e[2]},
                             {0, 0, -1}, {0, 0, 1}, {-1, 0, 0}, {1, 0, 0}, {0, -1, 0}, {0, 1, 0}};
  for (const Vec3& d : candidates)
    if (auto view = view_if_in_front(meshes, e, d)) return view;
  // Otherwise look for the point x of the vertices' convex hull nearest to the light (Frank and
  // Wolfe's iteration, in double): once every vertex lies beyond the plane through the light
  // normal to x − e, that direction is tested exactly.
  Vec3 x{centroid[0] / double(count), centroid[1] / double(count), centroid[2] / double(count)};
  for (int step = 0; step < 64; ++step) {
    const Vec3 g{x[0] - e[0], x[1] - e[1], x[2] - e[2]};
    const Vec3* s = nullptr;
    double least = HUGE_VAL;
    for (const Mesh& mesh : meshes)
      for (const Vec3& p : mesh.vertices) {
        const double w = g[0] * (p[0] - e[0]) + g[1] * (p[1] - e[1]) + g[2] * (p[2] - e[2]);
        if (w < least) least = w, s = &p;
      }
    if (least > 0)
      if (auto view = view_if_in_front(meshes, e, g)) return view;
    // The exact line search toward the vertex s, in double.
    const Vec3 t{(*s)[0] - x[0], (*s)[1] - x[1], (*s)[2] - x[2]};
    const double tt = t[0] * t[0] + t[1] * t[1] + t[2] * t[2];
    if (!(tt > 0)) break;
    const double gamma = std::clamp(-(g[0] * t[0] + g[1] * t[1] + g[2] * t[2]) / tt, 0.0, 1.0);
    if (gamma == 0) break;
    for (int k = 0; k < 3; ++k) x[k] += gamma * t[k];
  }
  return std::nullopt;
}

namespace {

// A face as a polygon in the plane of the two coordinates other than `axis` (its largest normal
// component), normalized; nothing for a face without area.
std::optional<clip::Polygon<K>> face_in_axis_plane(const Mesh& mesh, const std::vector<std::uint32_t>& face, int axis,
                                                   clip::LineTable<K>& lines) {
  const auto ax = uv_axes(axis);
  std::vector<P2> points;
  for (std::uint32_t v : face) points.push_back(G::point(FT(mesh.vertices[v][ax[0]]), FT(mesh.vertices[v][ax[1]])));
  clip::Polygon<K> polygon{clip::make_contour<K>(points, lines), {}};
  if (clip::normalize_polygon(polygon)) return std::nullopt;
  return polygon;
}

// Rays from the light for the inside test: rational directions in no plane of a small integer
// lattice, so that a ray through an edge or a vertex of a model is rare; the first ray that meets
// no edge, no vertex and no face plane it runs in decides.
const std::array<int, 3> kProbeDirections[] = {{3, 5, 7},    {-5, 2, 11}, {7, -3, 2},   {2, 9, -5},  {-7, -11, 3},
                                                {13, -2, -9}, {-3, 8, -13}, {11, 7, 17}, {-17, 5, -4}, {6, -13, 19}};

}  // namespace

std::optional<std::string> point_light_defect(const std::vector<Mesh>& meshes, const Light& light) {
  if (auto defect = light_defect(light)) return defect;
  if (light.kind != Light::point || point_light_view(meshes, light)) return std::nullopt;
  // Among the geometry the cube serves, unless the light is on a face or inside a closed solid
  // (whose back faces, removed, would let the light through). Both decided exactly.
  const Vec3FT e{FT(light.vector[0]), FT(light.vector[1]), FT(light.vector[2])};
  struct SolidFace {
    std::uint32_t mesh, component;
    Vec3FT normal, corner;  // Newell's normal; a corner minus e
    int axis;
    clip::Polygon<K> polygon;  // in the plane of the coordinates other than axis
  };
  std::vector<SolidFace> solid_faces;
  clip::LineTable<K> lines;
  for (std::uint32_t mi = 0; mi < meshes.size(); ++mi) {
    const Mesh& mesh = meshes[mi];
    const ComponentSides sides = component_sides(mesh, edge_uses(mesh));
    for (std::uint32_t f = 0; f < mesh.faces.size(); ++f) {
      const Vec3FT n = newell_normal(mesh, mesh.faces[f]);
      const int axis = largest_axis(n);
      auto polygon = face_in_axis_plane(mesh, mesh.faces[f], axis, lines);
      if (!polygon) continue;
      const Vec3& p0 = mesh.vertices[mesh.faces[f][0]];
      const Vec3FT q0{FT(p0[0]) - e[0], FT(p0[1]) - e[1], FT(p0[2]) - e[2]};
      const auto ax = uv_axes(axis);
      if (CGAL::is_zero(dot(n, q0)) && clip::side_of_polygon<K>(*polygon, G::point(e[ax[0]], e[ax[1]])) >= 0)
        return "the point light lies on face " + std::to_string(mesh.face_index[f]) + " of " + mesh.file;
      if (sides.outward[f] != 0) solid_faces.push_back({mi, sides.component[f], n, q0, axis, std::move(*polygon)});
    }
  }
  if (solid_faces.empty()) return std::nullopt;
  // The parity of a ray's crossings with each closed component: odd inside. A ray that runs in a
  // face's plane or through a face's boundary proves nothing; the next one is tried.
  for (const auto& direction : kProbeDirections) {
    const Vec3FT r{FT(direction[0]), FT(direction[1]), FT(direction[2])};
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> crossings;
    bool degenerate = false;
    for (const SolidFace& face : solid_faces) {
      int& count = crossings[{face.mesh, face.component}];
      // e + s r on the plane n . (x - e - corner) = 0: s (n . r) = n . corner.
      const FT along = dot(face.normal, r), offset = dot(face.normal, face.corner);
      if (CGAL::is_zero(along)) {
        if (CGAL::is_zero(offset)) degenerate = true;  // the ray runs in the face's plane
        if (degenerate) break;
        continue;
      }
      const FT s = offset / along;
      if (!CGAL::is_positive(s)) continue;  // behind the light (or at it: the light is not on the face)
      const auto ax = uv_axes(face.axis);
      const int side = clip::side_of_polygon<K>(face.polygon, G::point(e[ax[0]] + s * r[ax[0]], e[ax[1]] + s * r[ax[1]]));
      if (side == 0) {
        degenerate = true;
        break;
      }
      count += side > 0;
    }
    if (degenerate) continue;
    for (const auto& [component, count] : crossings)
      if (count % 2 == 1)
        return "the point light is inside a closed solid of " + meshes[component.first].file + " (the component of face " +
               std::to_string(meshes[component.first].face_index[component.second]) + ")";
    return std::nullopt;
  }
  return "hlr could not decide whether the point light is inside a closed solid (every probing ray met an edge); "
         "move it a little";
}

std::optional<View> light_view(const std::vector<Mesh>& meshes, const Light& light) {
  if (light.kind == Light::directional) return light_view_along(light.vector);
  return point_light_view(meshes, light);
}

ShadowResult cast_shadows(const std::vector<Mesh>& meshes, const std::vector<Light>& lights, const ShadowOptions& options) {
  // Per light, its views: one (a sun; a point light with the scene on one side of a plane through
  // it), or the cube's (a point light among the geometry, or always with PointLightViews::cube).
  std::vector<std::vector<LightPyramid>> views;
  for (const Light& light : lights) {
    if (auto defect = light_defect(light)) throw std::invalid_argument(*defect);
    std::optional<View> view;
    if (light.kind == Light::directional) view = light_view_along(light.vector);
    else if (options.point_light_views == PointLightViews::automatic) view = point_light_view(meshes, light);
    if (view) {
      views.push_back({{*view, -1}});
      continue;
    }
    if (!point_light_view(meshes, light))
      if (auto defect = point_light_defect(meshes, light)) throw std::invalid_argument(*defect);
    views.push_back(cube_views(meshes, light.vector));
  }
  const auto start = Clock::now();
  ShadowResult result;
  options.progress.report("sources of " + std::to_string(meshes.size()) + " mesh(es)");
  ModelSources model = model_sources(meshes);
  result.times.sources = seconds_since(start);

  // Sun studies: the directional lights in groups, and with culling the faces no direction of a
  // group's part can light, for every light of that part.
  std::vector<CullPart> parts;
  std::vector<std::ptrdiff_t> part_of(lights.size(), -1);
  std::vector<std::ptrdiff_t> group_of(lights.size(), -1);
  {
    std::vector<View> directional;
    std::vector<std::size_t> light_of;
    auto flush = [&] {
      for (const ViewRun& run : group_views(directional, options.cull_extent)) {
        ShadowCullGroup group;
        group.first = light_of[run.first];
        group.count = run.count;
        group.patches = 0;
        for (const Mesh& mesh : meshes) group.patches += mesh.faces.size();
        for (std::size_t i = 0; i < run.count; ++i) group_of[light_of[run.first + i]] = std::ptrdiff_t(result.cull_groups.size());
        if (options.cull) {
          options.progress.check();
          options.progress.report("fuzzy culling for lights " + std::to_string(group.first + 1) + " to " +
                                  std::to_string(group.first + group.count));
          std::vector<std::size_t> members(run.count);
          for (std::size_t i = 0; i < run.count; ++i) members[i] = run.first + i;
          CullPasses passes;
          auto found = cull_parts(meshes, directional, members, options.fuzzy, options.progress.stop, passes);
          group.parts = found.size();
          group.fuzzy_passes = passes.passes;
          group.fuzzy_seconds = passes.seconds;
          for (auto& part : found) {
            group.culled = std::max(group.culled, part.culled);
            if (part.culled > 0)
              for (std::size_t i : part.views) part_of[light_of[i]] = std::ptrdiff_t(parts.size());
            parts.push_back(std::move(part));
          }
        }
        result.cull_groups.push_back(group);
      }
      directional.clear();
      light_of.clear();
    };
    for (std::size_t k = 0; k < lights.size(); ++k) {
      if (lights[k].kind != Light::directional) {
        flush();
        continue;
      }
      directional.push_back(views[k].front().view);
      light_of.push_back(k);
    }
    flush();
  }

  // Per light, per mesh, per face: the lit polygons in the face's source's axis plane.
  std::vector<std::vector<std::vector<std::vector<clip::Polygon<K>>>>> lit_uv;
  for (std::size_t k = 0; k < lights.size(); ++k) {
    const auto mark = Clock::now();
    LightSolver solver(meshes, model, result, k, lights.size(), options);
    const std::vector<std::vector<bool>>* culled = part_of[k] >= 0 ? &parts[std::size_t(part_of[k])].faces : nullptr;
    solver.run(lights[k], views[k], culled);
    result.culled_faces.push_back(part_of[k] >= 0 ? parts[std::size_t(part_of[k])].culled : 0);
    if (group_of[k] >= 0) result.cull_groups[std::size_t(group_of[k])].solve_seconds += seconds_since(mark);
    if (options.union_shadows) lit_uv.push_back(std::move(solver.face_lit_uv));
  }

  if (options.union_shadows) {
    // The shadow over all lights is the face minus what every light reaches: intersect the lit
    // regions light by light, in the face's axis plane.
    options.progress.check();
    options.progress.report("union of the shadows");
    const auto mark = Clock::now();
    for (std::uint32_t mi = 0; mi < meshes.size(); ++mi) {
      const std::size_t nf = meshes[mi].faces.size();
      auto& area = result.face_union_shadow_area.emplace_back(nf, 0.0);
      auto& area2 = result.face_union_shadow_area2.emplace_back(nf, FT(0));
      for (std::uint32_t f = 0; f < nf; ++f) {
        const std::uint32_t m = model.face_source[mi][f];
        std::vector<clip::Polygon<K>> common;
        if (!lights.empty()) {
          clip::LineTable<K> lines;
          auto with_lines = [&](clip::Polygon<K> p) {
            auto register_lines = [&](clip::Contour<K>& c) {
              c.lines.clear();
              for (std::size_t i = 0; i < c.points.size(); ++i) {
                c.lines.push_back(clip::LineId(lines.size()));
                lines.push_back({c.points[i], c.points[(i + 1) % c.points.size()]});
              }
            };
            register_lines(p.outer);
            for (auto& h : p.holes) register_lines(h);
            return p;
          };
          for (const auto& p : lit_uv[0][mi][f]) common.push_back(with_lines(p));
          for (std::size_t k = 1; k < lights.size() && !common.empty(); ++k) {
            std::vector<clip::Polygon<K>> next;
            for (const auto& p : lit_uv[k][mi][f]) {
              const clip::Polygon<K> region = with_lines(p);
              const clip::ClipRegion<K> r(region, lines);
              for (auto& res : clip::clip_list<K>(common, r))
                for (auto& piece : res.inside) next.push_back(std::move(piece));
            }
            common.swap(next);
          }
        }
        FT lit_everywhere = 0;
        for (const auto& p : common) lit_everywhere += clip::twice_area(p);
        area2[f] = model.face_area2[mi][f] - lit_everywhere;
        area[f] = G::to_double(area2[f]) / 2 * model.factor[m];
      }
    }
    result.times.unions = seconds_since(mark);
  }

  result.sources = std::move(model.sources);
  result.face_source = std::move(model.face_source);
  result.face_area = std::move(model.face_area);
  result.face_area2 = std::move(model.face_area2);
  result.times.total = seconds_since(start);
  return result;
}

std::vector<clip::Polygon<K>> shadows_in_view(const ShadowResult& shadows, const ViewFrame<K>& frame, Sources<K>& sources,
                                              const VisibilityMap<K>& map) {
  // Every shadow polygon of a source that the view sees, projected once: a polygon on new support
  // lines of the view's table (its corners are the exact projections of its model corners).
  std::map<std::uint32_t, std::vector<std::pair<clip::Polygon<K>, CGAL::Bbox_2>>> projected;
  auto projection = [&](std::uint32_t model_source) -> const auto& {
    auto [it, added] = projected.try_emplace(model_source);
    if (!added) return it->second;
    auto contour = [&](const std::vector<hidden_line::ShadowPoint>& c) {
      std::vector<G::Point> points;
      for (const auto& p : c) {
        const ViewPoint<K> v = frame.to_view(p.x, p.y, p.z);
        points.push_back(G::point(v.x, v.y));
      }
      clip::Contour<K> out = clip::make_contour<K>(points, sources.lines);
      sources.line_origins.resize(sources.lines.size());  // auxiliary lines
      return out;
    };
    for (const auto& light : shadows.sources[model_source].lights)
      for (const auto& shadow : light.shadow) {
        clip::Polygon<K> polygon{contour(shadow.polygon.outer), {}};
        for (const auto& h : shadow.polygon.holes) polygon.holes.push_back(contour(h));
        // Seen edge-on in this view, a polygon has no area: nothing to draw.
        if (clip::normalize_polygon(polygon)) continue;
        const CGAL::Bbox_2 box = detail::box_of(polygon);
        it->second.push_back({std::move(polygon), box});
      }
    return it->second;
  };

  std::vector<clip::Polygon<K>> out;
  for (const auto& fragment : map.visible) {
    const auto& sp = sources.polygons[fragment.source];
    const auto& polygons = projection(shadows.face_source[sp.mesh][sp.faces.front()]);
    if (polygons.empty()) continue;
    const CGAL::Bbox_2 box = detail::box_of(fragment.polygon);
    std::vector<clip::Polygon<K>> subjects;
    for (const auto& [polygon, b] : polygons)
      if (CGAL::do_overlap(b, box)) subjects.push_back(polygon);
    if (subjects.empty()) continue;
    const clip::ClipRegion<K> region(fragment.polygon, sources.lines);
    for (auto& result : clip::clip_list<K>(subjects, region))
      for (auto& piece : result.inside) out.push_back(std::move(piece));
  }
  return out;
}

ShadowResult cast_shadows(const Scene& scene, const std::vector<Light>& lights, const ShadowOptions& options) {
  return cast_shadows(scene.meshes, lights, options);
}

}  // namespace hlr::hidden_line
