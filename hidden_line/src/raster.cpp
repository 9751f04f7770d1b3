// The raster P-buffer path (raster.hpp). Plain double and float on purpose; nothing here is exact.
#include <hlr/hidden_line/raster.hpp>

#include "depth_buffer.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace hlr::hidden_line {
namespace {

using detail::kNoFace;
constexpr int kMargin = 2;  // pixels around the drawing

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

std::array<double, 4> raster_extent(const std::vector<Mesh>& meshes, const View& view) {
  const detail::DepthBuffer projection(meshes, view, detail::DepthBuffer::ProjectOnly{});
  const auto b = projection.box();
  return {b[0], b[1], b[2], b[3]};
}

// The Z-buffer (depth_buffer.hpp) and the lines to classify against it.
struct RasterDrawing::Impl : detail::DepthBuffer {
  std::vector<RasterLine> lines;

  Impl(const std::vector<Mesh>& meshes, const View& view, const std::vector<IntersectionSegment>& intersections,
       const LineOptions& options, const RasterOptions& raster)
      : DepthBuffer(meshes, view, raster.resolution, raster.window) {
    make_lines(meshes, view, intersections, options);
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
  // Smooth lines are not drawn hidden: their ink is marked, a nearer face erases it whatever the
  // pattern, and a farther smooth line pixel is not drawn.
  const std::size_t pixels = std::size_t(g.width) * g.height;
  std::vector<float> depth(pixels, -std::numeric_limits<float>::infinity());
  std::vector<char> smooth_ink(pixels, 0);
  for (std::uint32_t id = 0; id < d.faces.size(); ++id) {
    d.fill_face(id, [&](int column, int row, double z) {
      const std::size_t p = std::size_t(row) * g.width + column;
      if (z > depth[p]) {
        depth[p] = static_cast<float>(z);
        if (smooth_ink[p] || !paper_pattern_passes(column, row)) paint(column, row, kBackground);
        smooth_ink[p] = 0;
      }
    });
    for (std::uint32_t i : lines_of_face[id]) {
      const RasterLine& r = d.lines[i];
      const bool smooth = r.line.kind == FeatureKind::smooth;
      for_each_pixel_step(g, r.a[0], r.a[1], r.b[0], r.b[1], [&](int column, int row, long k, long n) {
        const double z = d.normalized(r.a[2] + (double(k) + 0.5) / double(n) * (r.b[2] - r.a[2]));
        const std::size_t p = std::size_t(row) * g.width + column;
        if (z > depth[p]) {
          depth[p] = static_cast<float>(z);
          paint(column, row, kLine);
          smooth_ink[p] = smooth;
        } else if (!smooth && paper_pattern_passes(column, row)) {
          paint(column, row, kLine);
          smooth_ink[p] = 0;
        }
      });
    }
  }
  return image;
}

}  // namespace hlr::hidden_line
