// The raster path's Z-buffer (raster.hpp), shared by the P-buffer drawing (raster.cpp) and the
// raster shadow map (raster_shadows.cpp): every face of the scene scan-converted at pixel centres
// in the orthonormal frame of one view, keeping per pixel the nearest face's depth (normalized to
// the scene's depth range, as float, pushed back by a polygon offset) and its id. A perspective
// view's frame is projective (view.hpp), so faces stay planes and "nearer" is "larger z" there too.
// Plain double and float on purpose; nothing here is exact.
#pragma once

#include <hlr/hidden_line/raster.hpp>

#include <algorithm>
#include <array>
#include <optional>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace hlr::hidden_line::detail {

// Polygon offset, as in OpenGL's glPolygonOffset(factor, units): a face's stored depth is pushed
// back by kSlopeOffset pixels times its depth slope, plus kDepthUnits of the normalized depth
// range, so that a line on or next to a face (its own, or one sharing its end vertex) is not
// hidden by that face's depth sampled half a pixel away. For the shadow map it is the usual
// slope-scaled depth bias, for the same reason: a sample on a face is not shadowed by that face.
constexpr double kSlopeOffset = 1.5;
constexpr double kDepthUnits = 1.0 / (1 << 20);
constexpr std::uint32_t kNoFace = std::numeric_limits<std::uint32_t>::max();

struct RasterFace {
  std::uint32_t mesh = 0;
  std::vector<std::uint32_t> corners;  // vertex indices into the mesh
  bool fills = false;          // false when seen edge-on (no plane z = a x + b y + c)
  double a = 0, b = 0, c = 0;  // depth plane, orthonormal view frame
  double offset = 0;           // polygon offset, normalized depth units
};

struct DepthBuffer {
  ViewFrame<DoubleKernel> frame;
  RasterGrid grid;
  // Per mesh: what the near plane of a perspective view clips (near_plane.hpp), and its points,
  // the vertices and then the edges' crossings with the near plane, in orthonormal view coordinates.
  std::vector<NearCut<DoubleKernel>> cuts;
  std::vector<std::vector<Vec3>> points;
  std::vector<RasterFace> faces;
  std::vector<std::uint32_t> first_face;  // per mesh: its first global face id
  double z_min = 0, z_range = 1;
  std::vector<float> depth;
  std::vector<std::uint32_t> item;

  // Throws std::invalid_argument for a resolution outside 16..8192. With a window (RasterOptions),
  // the grid lies over it instead of over the scene's box.
  DepthBuffer(const std::vector<Mesh>& meshes, const View& view, int resolution,
              const std::optional<std::array<double, 4>>& window = std::nullopt)
      : frame(view, meshes) {
    if (resolution < 16 || resolution > 8192)
      throw std::invalid_argument("raster resolution " + std::to_string(resolution) + " is outside 16..8192 pixels");
    project(meshes);
    make_faces(meshes);
    make_grid(resolution, window);
    fill_zbuffer();
  }

  // Only the projection (cuts, points) and its box, for raster_extent.
  struct ProjectOnly {};
  DepthBuffer(const std::vector<Mesh>& meshes, const View& view, ProjectOnly) : frame(view, meshes) { project(meshes); }

  void project(const std::vector<Mesh>& meshes) {
    for (const Mesh& mesh : meshes) {
      const NearCut<DoubleKernel>& cut = cuts.emplace_back(mesh, frame);
      auto& pts = points.emplace_back();
      pts.reserve(cut.points().size());
      for (const auto& p : cut.points()) pts.push_back(orthonormal(p));
    }
  }

  // The box of the points not behind the near plane: x0, y0, x1, y1, z0, z1 (all zero for none).
  std::array<double, 6> box() const {
    double x0 = std::numeric_limits<double>::infinity(), x1 = -x0, y0 = x0, y1 = -x0, z0 = x0, z1 = -x0;
    for (std::size_t m = 0; m < points.size(); ++m)
      for (std::uint32_t v = 0; v < points[m].size(); ++v) {
        if (cuts[m].behind(v)) continue;
        const Vec3& p = points[m][v];
        x0 = std::min(x0, p[0]), x1 = std::max(x1, p[0]);
        y0 = std::min(y0, p[1]), y1 = std::max(y1, p[1]);
        z0 = std::min(z0, p[2]), z1 = std::max(z1, p[2]);
      }
    if (!(x0 <= x1)) x0 = x1 = y0 = y1 = z0 = z1 = 0;  // no vertex: an empty image
    return {x0, y0, x1, y1, z0, z1};
  }

  Vec3 orthonormal(const ViewPoint<DoubleKernel>& p) const {
    return {p.x / frame.scale(0), p.y / frame.scale(1), p.z / frame.scale(2)};
  }

  double normalized(double z) const { return (z - z_min) / z_range; }

  void make_faces(const std::vector<Mesh>& meshes) {
    using Part = NearCut<DoubleKernel>::Part;
    for (std::uint32_t m = 0; m < meshes.size(); ++m) {
      first_face.push_back(static_cast<std::uint32_t>(faces.size()));
      for (std::uint32_t f = 0; f < meshes[m].faces.size(); ++f) {
        RasterFace face;
        face.mesh = m;
        const Part part = cuts[m].part(f);
        if (part == Part::behind) {  // behind the near plane: a face that fills nothing
          faces.push_back(face);
          continue;
        }
        face.corners = part == Part::cut ? cuts[m].ring_points(f) : meshes[m].faces[f];
        // Newell's normal, then the plane through the centroid.
        double n[3] = {0, 0, 0}, centroid[3] = {0, 0, 0};
        const auto& corners = face.corners;
        for (std::size_t k = 0; k < corners.size(); ++k) {
          const Vec3& p = points[m][corners[k]];
          const Vec3& q = points[m][corners[(k + 1) % corners.size()]];
          n[0] += (p[1] - q[1]) * (p[2] + q[2]);
          n[1] += (p[2] - q[2]) * (p[0] + q[0]);
          n[2] += (p[0] - q[0]) * (p[1] + q[1]);
          for (int i = 0; i < 3; ++i) centroid[i] += p[i] / double(corners.size());
        }
        const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        face.fills = std::abs(n[2]) > 1e-9 * length;  // nearly edge-on faces cover no pixel worth a plane
        if (face.fills) {
          face.a = -n[0] / n[2];
          face.b = -n[1] / n[2];
          face.c = centroid[2] - face.a * centroid[0] - face.b * centroid[1];
        }
        faces.push_back(face);
      }
    }
  }

  void make_grid(int resolution, const std::optional<std::array<double, 4>>& window) {
    const auto [x0, y0, x1, y1, z0, z1] = box();
    grid = window ? raster_grid((*window)[0], (*window)[1], (*window)[2], (*window)[3], resolution)
                  : raster_grid(x0, y0, x1, y1, resolution);
    const double pixel = grid.pixel;
    z_min = z0;
    z_range = z1 > z0 ? z1 - z0 : 1;
    for (RasterFace& face : faces)
      face.offset = kSlopeOffset * pixel * std::hypot(face.a, face.b) / z_range + kDepthUnits;
  }

  // Calls visit(column, row, depth) for every pixel whose centre is inside the face (even-odd rule,
  // half-open rows and columns), depth normalized and offset.
  template <class Visit>
  void fill_face(std::uint32_t id, Visit&& visit) const {
    const RasterFace& face = faces[id];
    if (!face.fills) return;
    const auto& corners = face.corners;
    const auto& pts = points[face.mesh];
    double r0 = std::numeric_limits<double>::infinity(), r1 = -r0;
    for (std::uint32_t v : corners) r0 = std::min(r0, grid.row(pts[v][1])), r1 = std::max(r1, grid.row(pts[v][1]));
    const int row_first = std::max(0, static_cast<int>(std::ceil(r0 - 0.5)));
    const int row_last = std::min(grid.height - 1, static_cast<int>(std::ceil(r1 - 0.5)) - 1);
    std::vector<double> crossings;
    for (int row = row_first; row <= row_last; ++row) {
      const double y = grid.top - (row + 0.5) * grid.pixel;
      crossings.clear();
      for (std::size_t k = 0; k < corners.size(); ++k) {
        const Vec3& p = pts[corners[k]];
        const Vec3& q = pts[corners[(k + 1) % corners.size()]];
        if ((p[1] <= y) == (q[1] <= y)) continue;
        crossings.push_back(p[0] + (y - p[1]) / (q[1] - p[1]) * (q[0] - p[0]));
      }
      std::sort(crossings.begin(), crossings.end());
      for (std::size_t k = 0; k + 1 < crossings.size(); k += 2) {
        const int c0 = std::max(0, static_cast<int>(std::ceil(grid.column(crossings[k]) - 0.5)));
        const int c1 = std::min(grid.width, static_cast<int>(std::ceil(grid.column(crossings[k + 1]) - 0.5)));
        for (int column = c0; column < c1; ++column) {
          const double x = grid.left + (column + 0.5) * grid.pixel;
          visit(column, row, normalized(face.a * x + face.b * y + face.c) - face.offset);
        }
      }
    }
  }

  void fill_zbuffer() {
    const std::size_t n = std::size_t(grid.width) * std::size_t(grid.height);
    depth.assign(n, -std::numeric_limits<float>::infinity());
    item.assign(n, kNoFace);
    for (std::uint32_t id = 0; id < faces.size(); ++id)
      fill_face(id, [&](int column, int row, double z) {
        const std::size_t p = std::size_t(row) * grid.width + column;
        if (z > depth[p]) depth[p] = static_cast<float>(z), item[p] = id;
      });
  }
};

}  // namespace hlr::hidden_line::detail
