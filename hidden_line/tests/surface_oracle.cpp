// The independent oracle (see surface_oracle.hpp). Brute force, exact, deliberately plain.
#include "surface_oracle.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace hlr::hltest {

bool same_plane(const Plane& p, const Plane& q) { return p.a == q.a && p.b == q.b && p.c == q.c; }

FT twice_signed_area(const std::vector<P2>& c) {
  FT sum = 0;
  for (std::size_t i = 0, n = c.size(); i < n; ++i) {
    const P2& a = c[i];
    const P2& b = c[(i + 1) % n];
    sum += a.x() * b.y() - b.x() * a.y();
  }
  return sum;
}

int locate(const std::vector<P2>& c, const P2& q) {
  int winding = 0;
  for (std::size_t i = 0, n = c.size(); i < n; ++i) {
    const P2& a = c[i];
    const P2& b = c[(i + 1) % n];
    const CGAL::Orientation o = CGAL::orientation(a, b, q);
    if (o == CGAL::COLLINEAR && CGAL::collinear_are_ordered_along_line(a, q, b)) return 0;
    if (CGAL::compare_y(a, q) != CGAL::LARGER) {
      if (CGAL::compare_y(b, q) == CGAL::LARGER && o == CGAL::LEFT_TURN) ++winding;
    } else if (CGAL::compare_y(b, q) != CGAL::LARGER && o == CGAL::RIGHT_TURN) {
      --winding;
    }
  }
  return winding != 0 ? 1 : -1;
}

bool strictly_inside(const std::vector<P2>& outer, const std::vector<std::vector<P2>>& holes, const P2& q) {
  if (locate(outer, q) != 1) return false;
  for (const auto& h : holes)
    if (locate(h, q) != -1) return false;
  return true;
}

std::optional<P2> interior_point(const std::vector<P2>& outer, const std::vector<std::vector<P2>>& holes) {
  std::vector<FT> ys;
  auto collect = [&](const std::vector<P2>& c) {
    for (const P2& p : c) ys.push_back(p.y());
  };
  collect(outer);
  for (const auto& h : holes) collect(h);
  std::sort(ys.begin(), ys.end());
  ys.erase(std::unique(ys.begin(), ys.end()), ys.end());
  if (ys.size() < 2) return std::nullopt;
  std::size_t widest = 0;
  FT gap = ys[1] - ys[0];
  for (std::size_t i = 1; i + 1 < ys.size(); ++i) {
    FT g = ys[i + 1] - ys[i];
    if (g > gap) {
      gap = g;
      widest = i;
    }
  }
  const FT y = (ys[widest] + ys[widest + 1]) / 2;
  std::vector<FT> xs;
  auto cross = [&](const std::vector<P2>& c) {
    for (std::size_t i = 0, n = c.size(); i < n; ++i) {
      const P2& a = c[i];
      const P2& b = c[(i + 1) % n];
      if ((a.y() < y && y < b.y()) || (b.y() < y && y < a.y()))
        xs.push_back(a.x() + (y - a.y()) * (b.x() - a.x()) / (b.y() - a.y()));
    }
  };
  cross(outer);
  for (const auto& h : holes) cross(h);
  if (xs.size() < 2) return std::nullopt;
  std::sort(xs.begin(), xs.end());
  return P2((xs[0] + xs[1]) / 2, y);
}

namespace {

}  // namespace

// Closed, consistently oriented components of one mesh: faces connected through shared edges;
// closed when every edge of the component is used by exactly two of its faces, in opposite
// directions. Their side is the sign of the volume they enclose (divergence theorem, exact).
std::vector<int> closed_sides(const Mesh& mesh) {
  const std::size_t nf = mesh.faces.size();
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::pair<std::uint32_t, bool>>> uses;
  for (std::uint32_t f = 0; f < nf; ++f) {
    const auto& face = mesh.faces[f];
    for (std::size_t i = 0; i < face.size(); ++i) {
      std::uint32_t a = face[i], b = face[(i + 1) % face.size()];
      uses[{std::min(a, b), std::max(a, b)}].push_back({f, a < b});
    }
  }
  std::vector<std::vector<std::uint32_t>> neighbours(nf);
  for (const auto& [edge, list] : uses)
    for (const auto& [f, dir] : list)
      for (const auto& [g, dir2] : list)
        if (f != g) neighbours[f].push_back(g);
  std::vector<int> component(nf, -1);
  std::vector<std::vector<std::uint32_t>> members;
  for (std::uint32_t f = 0; f < nf; ++f) {
    if (component[f] >= 0) continue;
    const int id = static_cast<int>(members.size());
    members.push_back({});
    std::vector<std::uint32_t> stack{f};
    component[f] = id;
    while (!stack.empty()) {
      std::uint32_t g = stack.back();
      stack.pop_back();
      members[id].push_back(g);
      for (std::uint32_t h : neighbours[g])
        if (component[h] < 0) {
          component[h] = id;
          stack.push_back(h);
        }
    }
  }
  std::vector<bool> component_closed(members.size(), true);
  for (const auto& [edge, list] : uses) {
    const bool good = list.size() == 2 && list[0].second != list[1].second;
    if (!good) component_closed[component[list[0].first]] = false;
  }
  std::vector<int> side(members.size(), 0);
  for (std::size_t c = 0; c < members.size(); ++c) {
    if (!component_closed[c]) continue;
    FT volume = 0;
    for (std::uint32_t f : members[c]) {
      const auto& idx = mesh.faces[f];
      auto p = [&](std::size_t k) { return mesh.vertices[idx[k]]; };
      for (std::size_t k = 1; k + 1 < idx.size(); ++k) {
        const auto a = p(0), b = p(k), q = p(k + 1);
        volume += FT(a[0]) * (FT(b[1]) * FT(q[2]) - FT(b[2]) * FT(q[1])) -
                  FT(a[1]) * (FT(b[0]) * FT(q[2]) - FT(b[2]) * FT(q[0])) +
                  FT(a[2]) * (FT(b[0]) * FT(q[1]) - FT(b[1]) * FT(q[0]));
      }
    }
    side[c] = static_cast<int>(CGAL::sign(volume));
  }
  std::vector<int> out(nf);
  for (std::uint32_t f = 0; f < nf; ++f) out[f] = side[component[f]];
  return out;
}

namespace {

CGAL::Bbox_2 interval_box(const P2& p) {
  auto x = CGAL::to_interval(p.x());
  auto y = CGAL::to_interval(p.y());
  return CGAL::Bbox_2(x.first, y.first, x.second, y.second);
}

}  // namespace

NearPlane::NearPlane(const std::vector<Mesh>& meshes, const View& view) {
  if (!view.eye) return;
  eye_ = P3((*view.eye)[0], (*view.eye)[1], (*view.eye)[2]);
  d_ = EK::Vector_3(view.direction[0], view.direction[1], view.direction[2]);
  std::optional<FT> deepest;
  for (const Mesh& mesh : meshes)
    for (const auto& v : mesh.vertices) {
      const FT w = depth(P3(v[0], v[1], v[2]));
      if (!deepest || w > *deepest) deepest = w;
    }
  nu_ = view.near_fraction ? *deepest * FT(*view.near_fraction) : *deepest / 1000;
}

P3 NearPlane::crossing(const P3& a, const P3& b) const {
  const EK::Plane_3 plane(*eye_ + d_ * (nu_ / d_.squared_length()), d_);
  const auto hit = CGAL::intersection(EK::Segment_3(a, b), plane);
  return *boost::get<P3>(&*hit);  // the segment crosses the plane: a point
}

std::vector<P3> NearPlane::clip(const std::vector<P3>& polygon) const {
  if (!eye_) return polygon;
  std::vector<P3> out;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const P3 &p = polygon[i], &q = polygon[(i + 1) % polygon.size()];
    const CGAL::Sign sp = CGAL::sign(depth(p) - nu_), sq = CGAL::sign(depth(q) - nu_);
    if (sp >= 0) out.push_back(p);
    if (sp * sq < 0) out.push_back(crossing(p, q));
  }
  if (out.size() < 3) out.clear();
  return out;
}

std::optional<std::pair<P3, P3>> NearPlane::clip(const P3& a, const P3& b) const {
  const bool fa = in_front(a), fb = in_front(b);
  if (!fa && !fb) return std::nullopt;
  if (fa && fb) return std::pair{a, b};
  const std::pair<P3, P3> part = fa ? std::pair{a, crossing(a, b)} : std::pair{crossing(a, b), b};
  if (part.first == part.second) return std::nullopt;  // one end on the near plane, the other behind it
  return part;
}

SceneOracle::SceneOracle(const std::vector<Mesh>& meshes, const View& view) {
  const ViewFrame<EK> frame(view, meshes);
  const NearPlane near(meshes, view);
  std::size_t live = 0;
  bool first = true;
  for (const Mesh& mesh : meshes) {
    auto model = [&](std::uint32_t v) { return P3(mesh.vertices[v][0], mesh.vertices[v][1], mesh.vertices[v][2]); };
    std::vector<ViewPoint<EK>> vp(mesh.vertices.size());  // of the vertices in front of the near plane
    std::vector<bool> front(mesh.vertices.size());
    for (std::uint32_t v = 0; v < mesh.vertices.size(); ++v)
      if ((front[v] = near.in_front(model(v)))) vp[v] = frame.to_view(mesh.vertices[v]);
    // A mesh that reaches behind the near plane is cut open: no face of it counts as closed.
    const bool cut_open = std::find(front.begin(), front.end(), false) != front.end();
    std::vector<int> sides = closed_sides(mesh);
    if (cut_open) sides.assign(sides.size(), 0);
    std::vector<Face> faces(mesh.faces.size());
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
      // The face's corners in view coordinates: of its part in front of the near plane.
      std::vector<ViewPoint<EK>> corners;
      const auto& face = mesh.faces[f];
      if (std::all_of(face.begin(), face.end(), [&](std::uint32_t v) { return front[v]; })) {
        for (std::uint32_t v : face) corners.push_back(vp[v]);
      } else {
        std::vector<P3> polygon;
        for (std::uint32_t v : face) polygon.push_back(model(v));
        for (const P3& p : near.clip(polygon)) corners.push_back(frame.to_view(p.x(), p.y(), p.z()));
      }
      Face& out = faces[f];
      out.side = sides[f];
      out.closed = sides[f] != 0;
      if (corners.empty()) {  // wholly behind the near plane: no face of the view
        out.behind = true;
        continue;
      }
      FT nx = 0, ny = 0, nz = 0;
      for (std::size_t i = 0; i < corners.size(); ++i) {
        const ViewPoint<EK>& p = corners[i];
        const ViewPoint<EK>& q = corners[(i + 1) % corners.size()];
        nx += (p.y - q.y) * (p.z + q.z);
        ny += (p.z - q.z) * (p.x + q.x);
        nz += (p.x - q.x) * (p.y + q.y);
        out.points.push_back(P2(p.x, p.y));
      }
      out.twice_projected_area = nz;
      out.facing = static_cast<int>(CGAL::sign(nz));
      out.box = interval_box(out.points[0]);
      for (const P2& p : out.points) out.box += interval_box(p);
      if (out.facing != 0) {
        const ViewPoint<EK>& v0 = corners[0];
        out.plane = {-nx / nz, -ny / nz, (nx * v0.x + ny * v0.y + nz * v0.z) / nz};
        ++live;
        extent_ = first ? out.box : extent_ + out.box;
        first = false;
      }
    }
    meshes_.push_back(std::move(faces));
  }
  // Grid: about two faces per cell on average, at most 1024 x 1024.
  const double w = std::max(extent_.xmax() - extent_.xmin(), 1e-300);
  const double h = std::max(extent_.ymax() - extent_.ymin(), 1e-300);
  const double cells = std::max<double>(1, live / 2.0);
  nx_ = std::clamp(static_cast<int>(std::sqrt(cells * w / h)), 1, 1024);
  ny_ = std::clamp(static_cast<int>(cells / nx_), 1, 1024);
  cells_.assign(static_cast<std::size_t>(nx_) * ny_, {});
  for (std::uint32_t m = 0; m < meshes_.size(); ++m)
    for (std::uint32_t f = 0; f < meshes_[m].size(); ++f) {
      const Face& face = meshes_[m][f];
      if (face.facing == 0) continue;
      int x0, x1, y0, y1;
      cell_range(face.box, x0, x1, y0, y1);
      for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) cells_[static_cast<std::size_t>(y) * nx_ + x].push_back({m, f});
    }
}

void SceneOracle::cell_range(const CGAL::Bbox_2& b, int& x0, int& x1, int& y0, int& y1) const {
  auto index = [](double v, double lo, double hi, int n) {
    if (!(hi > lo)) return 0;
    double t = (v - lo) / (hi - lo) * n;
    return std::clamp(static_cast<int>(std::floor(t)), 0, n - 1);
  };
  x0 = index(b.xmin(), extent_.xmin(), extent_.xmax(), nx_);
  x1 = index(b.xmax(), extent_.xmin(), extent_.xmax(), nx_);
  y0 = index(b.ymin(), extent_.ymin(), extent_.ymax(), ny_);
  y1 = index(b.ymax(), extent_.ymin(), extent_.ymax(), ny_);
}

bool SceneOracle::kept(FaceRef f, bool remove_back_faces) const {
  const Face& face = this->face(f);
  if (face.facing == 0) return false;
  if (remove_back_faces && face.facing * face.side < 0) return false;
  return true;
}

bool SceneOracle::contains(FaceRef f, const P2& q) const {
  const Face& face = this->face(f);
  if (face.facing == 0) return false;
  if (!CGAL::do_overlap(face.box, interval_box(q))) return false;
  return locate(face.points, q) >= 0;
}

SceneOracle::Probe SceneOracle::probe(const P2& q) const {
  Probe out;
  const CGAL::Bbox_2 qb = interval_box(q);
  if (!CGAL::do_overlap(qb, extent_)) return out;
  int x0, x1, y0, y1;
  cell_range(qb, x0, x1, y0, y1);
  std::vector<FaceRef> candidates;
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) {
      const auto& cell = cells_[static_cast<std::size_t>(y) * nx_ + x];
      candidates.insert(candidates.end(), cell.begin(), cell.end());
    }
  std::sort(candidates.begin(), candidates.end());
  candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
  for (const FaceRef& f : candidates) {
    if (!contains(f, q)) continue;
    out.faces.push_back(f);
    const FT z = face(f).plane.at(q);
    if (!out.max_z || z > *out.max_z) out.max_z = z;
  }
  return out;
}

}  // namespace hlr::hltest
