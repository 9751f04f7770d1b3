// hlr kernel, the near plane of a perspective view (DESIGN.md "Near plane").
//
// A perspective frame maps only points in front of the eye: faces and edges that reach behind the
// near plane d·(p−e) = ν are clipped by it exactly, in model space, before anything is divided.
// A face's part in front is a ring of corners: its vertices in front and the points where its
// edges cross the near plane (each made once per edge, so faces sharing an edge share the point),
// and between two corners either a piece of a mesh edge or a piece of the cut, which lies on the
// line where the face's plane meets the near plane and draws no line.
//
// perspective_defect says why a perspective view cannot be drawn at all: the whole scene behind
// the eye, or the eye on a face (decided exactly on the input doubles).
#pragma once

#include <hlr/kernel/errors.hpp>
#include <hlr/kernel/mesh_edges.hpp>
#include <hlr/kernel/view.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace hlr {

// Why this perspective view of the scene cannot be drawn, or nothing (also nothing for an
// orthographic view).
std::optional<std::string> perspective_defect(const std::vector<Mesh>& meshes, const View& view);

// One mesh seen from a frame: its vertices in view coordinates and its faces clipped by the near
// plane. In an orthographic frame, or when every vertex is in front, nothing is clipped.
template <GeometryKernel K>
class NearCut {
 public:
  using FT = typename Geometry<K>::FT;
  static constexpr std::uint32_t kCut = ~std::uint32_t(0);

  // A ring corner: the index of its point (points()), and the edge from it to the next corner: a
  // piece of mesh edge (a, b), or a piece of the cut (a == kCut).
  struct Corner {
    std::uint32_t point, a, b;
  };
  enum class Part : std::uint8_t { whole, cut, behind };

  NearCut(const Mesh& mesh, const ViewFrame<K>& frame) : mesh_(&mesh) {
    const std::size_t nv = mesh.vertices.size();
    points_.resize(nv);
    if (!frame.perspective()) {
      for (std::size_t v = 0; v < nv; ++v) points_[v] = frame.to_view(mesh.vertices[v]);
      return;
    }
    std::vector<FT> depth(nv);
    std::vector<int> side(nv);  // sign of depth − ν: the corner is kept where it is not negative
    bool clipped = false;
    for (std::size_t v = 0; v < nv; ++v) {
      depth[v] = frame.eye_depth(mesh.vertices[v]);
      side[v] = CGAL::compare(depth[v], frame.near());
      if (side[v] >= 0) points_[v] = frame.to_view(mesh.vertices[v]);
      else clipped = true;
    }
    if (!clipped) return;
    side_.assign(side.begin(), side.end());
    make_crossings(frame, depth, side);
    make_rings(side);
  }

  // The mesh's vertices in view coordinates (those behind the near plane hold zeros and are never
  // used), then the crossings of edges with the near plane.
  const std::vector<ViewPoint<K>>& points() const { return points_; }
  std::vector<ViewPoint<K>> take_points() { return std::move(points_); }
  // Whether anything of the mesh lies behind the near plane.
  bool clipped() const { return !side_.empty(); }
  // Whether vertex v lies behind the near plane (false for a crossing point).
  bool behind(std::uint32_t v) const { return v < side_.size() && side_[v] < 0; }
  Part part(std::uint32_t face) const { return parts_.empty() ? Part::whole : parts_[face]; }
  // The ring of a face whose part is `cut`: at least three corners, in the face's order.
  const std::vector<Corner>& ring(std::uint32_t face) const { return rings_[ring_of_[face]]; }
  // The same corners' points.
  const std::vector<std::uint32_t>& ring_points(std::uint32_t face) const { return ring_points_[ring_of_[face]]; }

  // The points of an edge's ends in front of the near plane, in the order (v0, v1): the vertices,
  // a crossing in place of a vertex behind; nothing when no more than a point of it is in front.
  std::optional<std::array<std::uint32_t, 2>> edge_ends(std::uint32_t v0, std::uint32_t v1) const {
    if (!behind(v0) && !behind(v1)) return std::array<std::uint32_t, 2>{v0, v1};
    if (side_[v0] <= 0 && side_[v1] <= 0) return std::nullopt;
    const std::uint32_t c = crossing(v0, v1);
    return behind(v0) ? std::array<std::uint32_t, 2>{c, v1} : std::array<std::uint32_t, 2>{v0, c};
  }

 private:
  // The point where edge (v, w), one end in front and one behind, crosses the near plane.
  std::uint32_t crossing(std::uint32_t v, std::uint32_t w) const {
    const std::uint64_t key = edge_key(v, w);
    auto it = std::lower_bound(crossings_.begin(), crossings_.end(), key,
                               [](const auto& c, std::uint64_t k) { return c.first < k; });
    return it->second;
  }

  // Every edge with one end strictly in front and one behind, once, from the end in front: the
  // same exact point whichever face asks.
  void make_crossings(const ViewFrame<K>& frame, const std::vector<FT>& depth, const std::vector<int>& side) {
    std::vector<std::uint64_t> keys;
    for (const auto& face : mesh_->faces)
      for (std::size_t i = 0; i < face.size(); ++i) {
        const std::uint32_t v = face[i], w = face[(i + 1) % face.size()];
        if (side[v] * side[w] < 0) keys.push_back(edge_key(v, w));
      }
    std::sort(keys.begin(), keys.end());
    keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
    for (std::uint64_t key : keys) {
      std::uint32_t front = edge_low(key), back = edge_high(key);
      if (side[front] < 0) std::swap(front, back);
      const FT t = (depth[front] - frame.near()) / (depth[front] - depth[back]);
      const Vec3 &p = mesh_->vertices[front], &q = mesh_->vertices[back];
      auto at = [&](int k) { return FT(p[k]) + t * (FT(q[k]) - FT(p[k])); };
      const FT x = at(0), y = at(1), z = at(2);
      crossings_.emplace_back(key, static_cast<std::uint32_t>(points_.size()));
      points_.push_back(frame.to_view(x, y, z));
    }
  }

  // Each face's part in front, walked once around (Sutherland–Hodgman). A face whose corners go
  // from front to behind more than once would be cut into several pieces: refused.
  void make_rings(const std::vector<int>& side) {
    const std::size_t nf = mesh_->faces.size();
    parts_.assign(nf, Part::whole);
    ring_of_.assign(nf, 0);
    for (std::uint32_t f = 0; f < nf; ++f) {
      const auto& face = mesh_->faces[f];
      const std::size_t n = face.size();
      std::size_t kept = 0, changes = 0;
      for (std::size_t i = 0; i < n; ++i) {
        kept += side[face[i]] >= 0;
        changes += (side[face[i]] >= 0) != (side[face[(i + 1) % n]] >= 0);
      }
      if (kept == n) continue;
      if (changes > 2)
        throw UserError(mesh_->file, "face " + std::to_string(mesh_->face_index[f]) +
                                        " is cut into several pieces by the near plane (move the eye, or set --near)");
      std::vector<Corner> ring;
      for (std::size_t i = 0; i < n; ++i) {
        const std::uint32_t v = face[i], w = face[(i + 1) % n];
        if (side[v] >= 0) {
          // Toward a corner behind: the edge runs on to its crossing, or, from a corner on the
          // near plane, the cut starts here.
          const bool on_edge = side[w] >= 0 || side[v] > 0;
          ring.push_back({v, on_edge ? v : kCut, w});
          if (side[v] > 0 && side[w] < 0) ring.push_back({crossing(v, w), kCut, kCut});
        } else if (side[w] > 0) {
          ring.push_back({crossing(v, w), v, w});
        }
      }
      if (ring.size() < 3) {
        parts_[f] = Part::behind;
        continue;
      }
      parts_[f] = Part::cut;
      ring_of_[f] = static_cast<std::uint32_t>(rings_.size());
      auto& points = ring_points_.emplace_back();
      for (const Corner& c : ring) points.push_back(c.point);
      rings_.push_back(std::move(ring));
    }
  }

  const Mesh* mesh_;  // a pointer, so that a NearCut can be assigned
  std::vector<ViewPoint<K>> points_;
  std::vector<std::int8_t> side_;  // per vertex, the sign of depth − ν; empty when nothing is clipped
  std::vector<std::pair<std::uint64_t, std::uint32_t>> crossings_;  // (edge key, point), sorted
  std::vector<Part> parts_;                                         // per face; empty: all whole
  std::vector<std::uint32_t> ring_of_;
  std::vector<std::vector<Corner>> rings_;
  std::vector<std::vector<std::uint32_t>> ring_points_;
};

}  // namespace hlr
