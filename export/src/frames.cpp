// The frames job (frames.hpp): eyes, groups, the fuzzy culling of each group, one drawing per
// frame, and the sheet they share.
#include <hlr/export/frames.hpp>

#include "paint.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

namespace hlr::exporter {
namespace {

constexpr double pi = 3.14159265358979323846;

struct SceneBox {
  Vec3 lo{HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
};

SceneBox scene_box(const Scene& scene) {
  SceneBox box;
  for (const Mesh& mesh : scene.meshes)
    for (const Vec3& p : mesh.vertices)
      for (int k = 0; k < 3; ++k) box.lo[k] = std::min(box.lo[k], p[k]), box.hi[k] = std::max(box.hi[k], p[k]);
  if (box.lo[0] > box.hi[0]) box = SceneBox{{0, 0, 0}, {0, 0, 0}};
  return box;
}

}  // namespace

Vec3 scene_centre(const Scene& scene) {
  const SceneBox b = scene_box(scene);
  return {(b.lo[0] + b.hi[0]) / 2, (b.lo[1] + b.hi[1]) / 2, (b.lo[2] + b.hi[2]) / 2};
}

double scene_diagonal(const Scene& scene) {
  const SceneBox b = scene_box(scene);
  return std::hypot(b.hi[0] - b.lo[0], b.hi[1] - b.lo[1], b.hi[2] - b.lo[2]);
}

std::vector<Vec3> orbit_eyes(const Vec3& target, int count, double elevation_degrees, double distance) {
  std::vector<Vec3> eyes;
  const double elevation = elevation_degrees * pi / 180;
  for (int i = 0; i < count; ++i) {
    const double azimuth = -pi / 2 + 2 * pi * i / count;
    const double r = distance * std::cos(elevation);
    eyes.push_back({target[0] + r * std::cos(azimuth), target[1] + r * std::sin(azimuth),
                    target[2] + distance * std::sin(elevation)});
  }
  return eyes;
}

std::vector<View> frame_views(const std::vector<Vec3>& eyes, const Vec3& target, std::optional<Vec3> up,
                              std::optional<double> near_fraction) {
  std::vector<View> views;
  for (const Vec3& eye : eyes) {
    View v;
    v.name = "custom";
    v.eye = eye;
    v.direction = {target[0] - eye[0], target[1] - eye[1], target[2] - eye[2]};
    // As hlr draw --eye --target: +Z up, or +Y when looking straight along Z.
    v.up = up ? *up : v.direction[0] == 0 && v.direction[1] == 0 ? Vec3{0, 1, 0} : Vec3{0, 0, 1};
    v.near_fraction = near_fraction;
    views.push_back(v);
  }
  return views;
}

std::vector<FrameGroup> group_eyes(const std::vector<View>& views, double extent) {
  std::vector<FrameGroup> groups;
  for (const hidden_line::ViewRun& run : hidden_line::group_views(views, extent)) groups.push_back({run.first, run.count});
  return groups;
}

std::vector<CullPart> cull_parts(const Scene& scene, const std::vector<View>& views, std::vector<std::size_t> frames,
                                 const hidden_line::FuzzyOptions& options, StopToken stop, FrameGroup& group) {
  hidden_line::CullPasses passes;
  auto parts = hidden_line::cull_parts(scene.meshes, views, std::move(frames), options, stop, passes);
  group.fuzzy_passes += passes.passes;
  group.fuzzy_seconds += passes.seconds;
  group.patches = passes.patches;
  return parts;
}

FrameSet draw_frames(const Scene& scene, const std::vector<View>& views, const FramesOptions& options,
                     const SceneIntersections* shared) {
  std::unique_ptr<SceneIntersections> own;
  if (!shared) own = std::make_unique<SceneIntersections>(scene, options.draw.intersections, options.draw.progress);
  const SceneIntersections& intersections = shared ? *shared : *own;
  const double extent = options.group_extent > 0 ? options.group_extent : scene_diagonal(scene) / 10;
  FrameSet out;
  out.groups = group_eyes(views, extent);
  out.frames.resize(views.size());
  if (options.raster > 0) out.rasters.resize(views.size());
  // The culled faces change no drawing of the exact kernel, and the others ignore them.
  const bool cull = options.cull == CullMode::fuzzy && options.raster == 0 && options.draw.kernel == KernelKind::exact;
  // Raster frames share one view-plane window, the union of every frame's own box, so that they
  // have one pixel size and a model point at rest keeps its pixel.
  hidden_line::RasterOptions raster;
  raster.resolution = options.raster;
  if (options.raster > 0) {
    std::array<double, 4> window{HUGE_VAL, HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    for (const View& view : views) {
      const auto e = hidden_line::raster_extent(scene.meshes, view);
      window = {std::min(window[0], e[0]), std::min(window[1], e[1]), std::max(window[2], e[2]), std::max(window[3], e[3])};
    }
    if (!views.empty()) raster.window = window;
  }
  for (std::size_t g = 0; g < out.groups.size(); ++g) {
    FrameGroup& group = out.groups[g];
    group.patches = scene.input.faces;
    std::vector<std::size_t> frames(group.count);
    for (std::size_t i = 0; i < group.count; ++i) frames[i] = group.first + i;
    std::vector<CullPart> parts;
    if (cull) {
      options.draw.progress.check();
      options.draw.progress.report("fuzzy culling for frames " + std::to_string(group.first + 1) + " to " +
                                   std::to_string(group.first + group.count));
      parts = cull_parts(scene, views, frames, options.fuzzy, options.draw.progress.stop, group);
    } else {
      parts.push_back(CullPart{frames, 0, 0, {}});
    }
    group.parts = parts.size();
    for (const CullPart& part : parts) group.culled = std::max(group.culled, part.culled);
    for (std::size_t p = 0; p < parts.size(); ++p)
      for (std::size_t i : parts[p].views) {
        options.draw.progress.check();
        options.draw.progress.report("frame " + std::to_string(i + 1) + " of " + std::to_string(views.size()));
        DrawOptions draw = options.draw;
        draw.free_at_exit = false;  // a frame's solution goes before the next is made
        if (parts[p].culled > 0) draw.culled_faces = &parts[p].faces;
        LineDrawing& frame = out.frames[i];
        if (options.raster > 0) {
          RasterRun run = draw_raster(scene, views[i], raster, draw, &intersections);
          frame = std::move(run.drawing);
          out.rasters[i] = std::move(run.raster);
        } else {
          frame = draw_lines(scene, views[i], draw, &intersections);
        }
        group.solve_seconds += frame.times.total + frame.times.write;  // as its stats.seconds
        frame.cull = LineDrawing::CullCounts{g, p, parts.size(), group.patches, parts[p].culled, 0, {}, {}};
        if (cull && options.cull_report) {
          options.draw.progress.report("frame " + std::to_string(i + 1) + " of " + std::to_string(views.size()) +
                                       " without culling (--cull-report)");
          draw.culled_faces = nullptr;
          const StageTimes unculled = draw_lines(scene, views[i], draw, &intersections).times;
          frame.cull->unculled_seconds = unculled.total + unculled.write;
          group.unculled_seconds = group.unculled_seconds.value_or(0) + *frame.cull->unculled_seconds;
        }
      }
    for (std::size_t i = group.first; i < group.first + group.count; ++i) {
      out.frames[i].cull->fuzzy_seconds = group.fuzzy_seconds;
      out.frames[i].cull->group_saved_seconds = group.saved_seconds();
    }
  }
  return out;
}

std::vector<SheetLines> frames_sheet(const std::vector<LineDrawing>& frames, const DrawingStyle& style) {
  auto union_of = [](const std::vector<SheetLines>& sheets) {
    std::optional<Bounds> all;
    for (const SheetLines& s : sheets)
      if (const auto b = sheet_bounds(s)) {
        if (!all) all = *b;
        all->x0 = std::min(all->x0, b->x0), all->y0 = std::min(all->y0, b->y0);
        all->x1 = std::max(all->x1, b->x1), all->y1 = std::max(all->y1, b->y1);
      }
    return all;
  };
  // Each frame alone, at the scale that fits it (sheet_lines ends with sheet_lines_at there): a
  // frame whose own scale is the common one keeps that sheet instead of merging its segments again.
  const std::vector<SheetLines> own = [&] {
    std::vector<SheetLines> out;
    for (const LineDrawing& f : frames) out.push_back(sheet_lines(f, style));
    return out;
  }();
  std::vector<SheetLines> sheets;
  std::optional<Bounds> all = union_of(own);
  double scale = style.scale ? *style.scale : all ? fitting_scale(*all, style) : style.unit_mm;
  const detail::Box area = detail::frame_of(style.sheet, detail::draw_title_height).area;
  for (int step = 0;; ++step) {
    sheets.clear();
    for (std::size_t i = 0; i < frames.size(); ++i)
      sheets.push_back(own[i].scale == scale ? own[i] : sheet_lines_at(frames[i], style, scale));
    all = union_of(sheets);
    if (!all) break;
    const bool fits = all->width() * scale <= area.width() * (1 + 1e-12) && all->height() * scale <= area.height() * (1 + 1e-12);
    if (fits) break;
    if (style.scale)
      throw std::invalid_argument("the frames need " + std::to_string(int(std::ceil(all->width() * scale))) + " x " +
                                  std::to_string(int(std::ceil(all->height() * scale))) + " mm; the drawing area of " +
                                  style.sheet.name + " is " + std::to_string(int(area.width())) + " x " +
                                  std::to_string(int(area.height())) + " mm");
    if (step > 3) break;
    // Recovered circles reach beyond their polygons: one step down the series.
    scale = style.unit_mm * iso_scale_at_most(scale / style.unit_mm * (1 - 1e-6));
  }
  if (all)
    for (SheetLines& s : sheets) s.centre = std::array<double, 2>{(all->x0 + all->x1) / 2, (all->y0 + all->y1) / 2};
  return sheets;
}

}  // namespace hlr::exporter
