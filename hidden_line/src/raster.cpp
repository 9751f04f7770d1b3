// The raster P-buffer path (raster.hpp). Plain double and float on purpose; nothing here is exact.
#include <hlr/hidden_line/raster.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace hlr::hidden_line {
namespace {

// Polygon offset, as in OpenGL's glPolygonOffset(factor, units): a face's stored depth is pushed
// back by kSlopeOffset pixels times its depth slope, plus kDepthUnits of the normalized depth
// range, so that a line on or next to a face (its own, or one sharing its end vertex) is not
// hidden by that face's depth sampled half a pixel away.
constexpr double kSlopeOffset = 1.5;
constexpr double kDepthUnits = 1.0 / (1 << 20);
constexpr std::uint32_t kNoFace = std::numeric_limits<std::uint32_t>::max();
constexpr int kMargin = 2;  // pixels around the drawing

struct RasterFace {
  std::uint32_t mesh = 0;
  std::vector<std::uint32_t> corners;  // vertex indices into the mesh
  bool fills = false;          // false when seen edge-on (no plane z = a x + b y + c)
  double a = 0, b = 0, c = 0;  // depth plane, orthonormal view frame
  double offset = 0;           // polygon offset, normalized depth units
};

struct RasterLine {
  Vec3 a, b;                         // orthonormal view frame
  std::vector<std::uint32_t> own;    // global face ids whose plane holds the line, sorted
  FeatureLine<DoubleKernel> line;    // what classify() returns, without pieces
};

// The 8x8 tile of DashPattern::paper: a chessboard of 4x4 squares, pass on the dark ones.
bool paper_pattern_passes(int column, int row) { return ((column >> 2) + (row >> 2)) % 2 == 0; }

// Arc-length dashes in pixels: 6 on, 3 off (ISO 128's 12:3 dash-to-gap ratio would need wider lines).
bool arc_dash_passes(double pixels_along) { return std::fmod(pixels_along, 9.0) < 6.0; }

}  // namespace

RasterGrid raster_grid(double x0, double y0, double x1, double y1, int resolution) {
  RasterGrid grid;
  const double w = x1 > x0 ? x1 - x0 : 0, h = y1 > y0 ? y1 - y0 : 0;
  double pixel = std::max(w, h) / double(std::max(1, resolution - 2 * kMargin));
  if (!(pixel > 0) || !std::isfinite(pixel)) pixel = 1;
  grid.pixel = pixel;
  grid.width = std::clamp(static_cast<int>(std::ceil(w / pixel)) + 2 * kMargin, 1, std::max(1, resolution));
  grid.height = std::clamp(static_cast<int>(std::ceil(h / pixel)) + 2 * kMargin, 1, std::max(1, resolution));
  grid.left = x0 - (grid.width * pixel - w) / 2;
  grid.top = y1 + (grid.height * pixel - h) / 2;
  return grid;
}

struct RasterDrawing::Impl {
  ViewFrame<DoubleKernel> frame;
  RasterGrid grid;
  // Per mesh: what the near plane of a perspective view clips (near_plane.hpp), and its points,
  // the vertices and then the edges' crossings with the near plane, in orthonormal view coordinates.
  std::vector<NearCut<DoubleKernel>> cuts;
  std::vector<std::vector<Vec3>> points;
  std::vector<RasterFace> faces;
  std::vector<std::uint32_t> first_face;  // per mesh: its first global face id
  std::vector<RasterLine> lines;
  double z_min = 0, z_range = 1;
  std::vector<float> depth;
  std::vector<std::uint32_t> item;

  Impl(const std::vector<Mesh>& meshes, const View& view, const std::vector<IntersectionSegment>& intersections,
       const LineOptions& options, const RasterOptions& raster)
      : frame(view, meshes) {
    if (raster.resolution < 16 || raster.resolution > 8192)
      throw std::invalid_argument("raster resolution " + std::to_string(raster.resolution) +
                                  " is outside 16..8192 pixels");
    for (const Mesh& mesh : meshes) {
      const NearCut<DoubleKernel>& cut = cuts.emplace_back(mesh, frame);
      auto& pts = points.emplace_back();
      pts.reserve(cut.points().size());
      for (const auto& p : cut.points()) pts.push_back(orthonormal(p));
    }
    make_faces(meshes);
    make_lines(meshes, view, intersections, options);
    make_grid(raster.resolution);
    fill_zbuffer();
  }

  Vec3 orthonormal(const ViewPoint<DoubleKernel>& p) const {
    return {p.x / frame.scale(0), p.y / frame.scale(1), p.z / frame.scale(2)};
  }

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

  void make_lines(const std::vector<Mesh>& meshes, const View& view,
                  const std::vector<IntersectionSegment>& intersections, const LineOptions& options) {
    for (std::uint32_t m = 0; m < meshes.size(); ++m) {
      const auto& v = meshes[m].vertices;
      for (const FeatureEdge& edge : feature_edges(meshes[m], view, options.features)) {
        const auto ends = cuts[m].edge_ends(edge.v0, edge.v1);
        if (!ends) continue;  // behind the near plane
        RasterLine r;
        r.a = points[m][(*ends)[0]];
        r.b = points[m][(*ends)[1]];
        for (std::uint32_t f : edge.faces) r.own.push_back(first_face[m] + f);
        if (ends == std::array<std::uint32_t, 2>{edge.v0, edge.v1}) {
          r.line.a = frame.to_view(v[edge.v0][0], v[edge.v0][1], v[edge.v0][2]);
          r.line.b = frame.to_view(v[edge.v1][0], v[edge.v1][1], v[edge.v1][2]);
        } else {
          r.line.a = cuts[m].points()[(*ends)[0]];
          r.line.b = cuts[m].points()[(*ends)[1]];
        }
        r.line.kind = edge.kind;
        r.line.mesh = m;
        r.line.v0 = edge.v0;
        r.line.v1 = edge.v1;
        std::sort(r.own.begin(), r.own.end());
        lines.push_back(std::move(r));
      }
    }
    if (!options.intersections) return;
    for (const IntersectionSegment& s : intersections) {
      const auto ends = frame.to_view_clipped(s.a, s.b);
      if (!ends) continue;
      RasterLine r;
      r.line.a = ends->first;
      r.line.b = ends->second;
      r.a = orthonormal(r.line.a);
      r.b = orthonormal(r.line.b);
      r.line.kind = FeatureKind::intersection;
      r.line.mesh = s.mesh_a;
      for (std::uint32_t f : s.faces_a) r.own.push_back(first_face[s.mesh_a] + f);
      for (std::uint32_t f : s.faces_b) r.own.push_back(first_face[s.mesh_b] + f);
      std::sort(r.own.begin(), r.own.end());
      lines.push_back(std::move(r));
    }
  }

  void make_grid(int resolution) {
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
    grid = raster_grid(x0, y0, x1, y1, resolution);
    const double pixel = grid.pixel;
    z_min = z0;
    z_range = z1 > z0 ? z1 - z0 : 1;
    for (RasterFace& face : faces)
      face.offset = kSlopeOffset * pixel * std::hypot(face.a, face.b) / z_range + kDepthUnits;
  }

  double normalized(double z) const { return (z - z_min) / z_range; }

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

  // The class of every pixel step of a line (1 visible, 0 hidden); empty when it projects to a point.
  std::vector<char> sample_classes(const RasterLine& r) const {
    std::vector<char> visible;
    for_each_pixel_step(grid, r.a[0], r.a[1], r.b[0], r.b[1], [&](int column, int row, long k, long n) {
      if (visible.empty()) visible.assign(std::size_t(n), 1);
      const std::size_t p = std::size_t(row) * grid.width + column;
      const std::uint32_t id = item[p];
      if (id == kNoFace || std::binary_search(r.own.begin(), r.own.end(), id)) return;
      const double t = (double(k) + 0.5) / double(n);
      visible[std::size_t(k)] = normalized(r.a[2] + t * (r.b[2] - r.a[2])) >= depth[p];
    });
    return visible;
  }
};

RasterDrawing::RasterDrawing(const std::vector<Mesh>& meshes, const View& view,
                             const std::vector<IntersectionSegment>& intersections, const LineOptions& options,
                             const RasterOptions& raster)
    : impl_(new Impl(meshes, view, intersections, options, raster)) {}

RasterDrawing::~RasterDrawing() { delete impl_; }

const RasterGrid& RasterDrawing::grid() const { return impl_->grid; }
const ViewFrame<DoubleKernel>& RasterDrawing::frame() const { return impl_->frame; }

LineSet<DoubleKernel> RasterDrawing::classify() const {
  LineSet<DoubleKernel> out;
  for (const RasterLine& r : impl_->lines) {
    FeatureLine<DoubleKernel> line = r.line;
    const std::vector<char> visible = impl_->sample_classes(r);
    const std::size_t n = visible.size();
    for (std::size_t k = 0; k < n;) {
      std::size_t end = k + 1;
      while (end < n && visible[end] == visible[k]) ++end;
      line.pieces.push_back({double(k) / double(n), double(end) / double(n), visible[k] != 0});
      ++(visible[k] ? out.stats.visible_pieces : out.stats.hidden_pieces);
      k = end;
    }
    ++out.stats.by_kind[static_cast<int>(line.kind)];
    if (line.pieces.empty()) ++out.stats.point_in_view;
    out.lines.push_back(std::move(line));
  }
  out.stats.lines = out.lines.size();
  return out;
}

RasterImage RasterDrawing::pbuffer(DashPattern pattern) const {
  const Impl& d = *impl_;
  const RasterGrid& g = d.grid;
  RasterImage image{g.width, g.height, std::vector<std::uint8_t>(std::size_t(g.width) * g.height * 3, 255)};
  auto paint = [&](int column, int row, std::uint8_t value) {
    std::uint8_t* px = &image.rgb[(std::size_t(row) * g.width + column) * 3];
    px[0] = px[1] = px[2] = value;
  };
  constexpr std::uint8_t kLine = 0, kBackground = 255;

  if (pattern == DashPattern::arc_length) {
    // Hidden dashes first, then visible lines over them (ISO 128 precedence); each line is
    // classified once. Smooth lines' hidden pieces are not drawn (lines.hpp, drawing_segments).
    std::vector<std::vector<char>> classes;
    classes.reserve(d.lines.size());
    for (const RasterLine& r : d.lines) classes.push_back(d.sample_classes(r));
    for (const bool visible_pass : {false, true})
      for (std::size_t i = 0; i < d.lines.size(); ++i) {
        const RasterLine& r = d.lines[i];
        if (!visible_pass && r.line.kind == FeatureKind::smooth) continue;
        const std::vector<char>& visible = classes[i];
        for_each_pixel_step(g, r.a[0], r.a[1], r.b[0], r.b[1], [&](int column, int row, long k, long) {
          if (visible[std::size_t(k)] != visible_pass) return;
          if (visible_pass || arc_dash_passes(double(k) + 0.5)) paint(column, row, kLine);
        });
      }
    return image;
  }

  // The paper's single pass (its appendix, P_Buffer::this_Algorithm): faces in input order, each
  // one's interior pixels, then its lines as its boundary pixels.
  std::vector<std::vector<std::uint32_t>> lines_of_face(d.faces.size());
  for (std::uint32_t i = 0; i < d.lines.size(); ++i)
    for (std::uint32_t f : d.lines[i].own) lines_of_face[f].push_back(i);
  std::vector<float> depth(std::size_t(g.width) * g.height, -std::numeric_limits<float>::infinity());
  for (std::uint32_t id = 0; id < d.faces.size(); ++id) {
    d.fill_face(id, [&](int column, int row, double z) {
      float& stored = depth[std::size_t(row) * g.width + column];
      if (z > stored) {
        stored = static_cast<float>(z);
        if (!paper_pattern_passes(column, row)) paint(column, row, kBackground);
      }
    });
    for (std::uint32_t i : lines_of_face[id]) {
      const RasterLine& r = d.lines[i];
      for_each_pixel_step(g, r.a[0], r.a[1], r.b[0], r.b[1], [&](int column, int row, long k, long n) {
        const double z = d.normalized(r.a[2] + (double(k) + 0.5) / double(n) * (r.b[2] - r.a[2]));
        float& stored = depth[std::size_t(row) * g.width + column];
        if (z > stored) {
          stored = static_cast<float>(z);
          paint(column, row, kLine);
        } else if (paper_pattern_passes(column, row)) {
          paint(column, row, kLine);
        }
      });
    }
  }
  return image;
}

}  // namespace hlr::hidden_line
