// hlr export, frames: a sequence of perspective drawings of one scene (an orbit, a walk-through),
// as `hlr frames` makes them.
//
//   orbit_eyes     N eyes evenly around a target, at an elevation and a distance, Z up.
//   frame_views    the perspective views of a list of eyes looking at one target.
//   draw_frames    every frame's drawing, each as draw_lines (or draw_raster) draws it alone: the
//                  scene's intersections are found once for all; the eyes are grouped, and with
//                  CullMode::fuzzy the faces no eye of a group can see (hidden_line/fuzzy_cull.hpp)
//                  are left out of its frames' sources (exact kernel; the drawings are the same).
//                  A group whose box of eyes is too large to cull anything is split (cull_parts).
//   frames_sheet   the one scale and centre at which every frame's sheet shows it, so that the
//                  frames play as an animation.
#pragma once

#include <hlr/export/jobs.hpp>
#include <hlr/hidden_line/fuzzy_cull.hpp>

#include <memory>
#include <optional>
#include <vector>

namespace hlr::exporter {

// The centre of the scene's bounding box.
Vec3 scene_centre(const Scene& scene);
// The length of the scene's bounding box's diagonal.
double scene_diagonal(const Scene& scene);

// The distance of an orbit when none is given: this many bounding-box diagonals from the target.
inline constexpr double kOrbitDiagonals = 2;

// `count` eyes on the circle around `target` at `elevation_degrees` above the horizontal plane
// through it and `distance` from it, Z up: eye i at azimuth 360 i / count degrees from +X towards
// +Y, starting at -Y (the front view's side).
std::vector<Vec3> orbit_eyes(const Vec3& target, int count, double elevation_degrees, double distance);

// The views from `eyes` looking at `target` (direction target - eye rounded to double), with `up`
// (none: +Z, or +Y for an eye straight above or below the target) and the near fraction.
std::vector<View> frame_views(const std::vector<Vec3>& eyes, const Vec3& target, std::optional<Vec3> up = {},
                              std::optional<double> near_fraction = {});

enum class CullMode { none, fuzzy };

struct FramesOptions {
  DrawOptions draw;
  CullMode cull = CullMode::fuzzy;
  hidden_line::FuzzyOptions fuzzy;
  // Consecutive eyes form a group while the box around them is no longer than this along any
  // axis; 0: a tenth of the scene's bounding-box diagonal (a larger box culls little).
  double group_extent = 0;
  // Pixels: draw each frame by the raster path instead (no culling there), every frame an image of
  // one view-plane window (RasterOptions::window: the union of the frames' raster_extent).
  int raster = 0;
  // With culling: solve every frame a second time without it, for FrameGroup::unculled_seconds
  // (what the culling saved, measured rather than guessed; the run takes about twice as long).
  bool cull_report = false;
};

// The eyes of a group that one fuzzy pass culls for (cull_parts; `views`: its frames).
using hidden_line::CullPart;

struct FrameGroup {
  std::size_t first = 0, count = 0;  // frames first .. first + count - 1
  std::size_t patches = 0;
  std::size_t culled = 0;            // the most faces culled for one of its parts
  std::size_t parts = 1;             // after splitting (cull_parts)
  std::size_t fuzzy_passes = 0;      // those that culled nothing and were split included
  double fuzzy_seconds = 0;          // all its fuzzy passes
  double solve_seconds = 0;          // the sum of its frames' stats.seconds (with the culling)
  std::optional<double> unculled_seconds;  // cull_report: the same sum, solved without culling
  // cull_report: the time the culling saved the group, its fuzzy passes paid for.
  std::optional<double> saved_seconds() const {
    if (!unculled_seconds) return std::nullopt;
    return *unculled_seconds - solve_seconds - fuzzy_seconds;
  }
};

struct FrameSet {
  std::vector<LineDrawing> frames;  // each with its `cull`
  std::vector<std::unique_ptr<hidden_line::RasterDrawing>> rasters;  // with `raster`: per frame
  std::vector<FrameGroup> groups;
};

// The groups of consecutive eyes (FramesOptions::group_extent; hidden_line::group_views).
std::vector<FrameGroup> group_eyes(const std::vector<View>& views, double extent);

// hidden_line::cull_parts of the eyes `frames` of `views`; every pass's time and count go to `group`.
std::vector<CullPart> cull_parts(const Scene& scene, const std::vector<View>& views, std::vector<std::size_t> frames,
                                 const hidden_line::FuzzyOptions& options, StopToken stop, FrameGroup& group);

// Every view must be a perspective view that can be drawn of the scene (perspective_defect). The
// progress gets a stage per frame ("frame 3 of 36"). Throws as draw_lines does.
FrameSet draw_frames(const Scene& scene, const std::vector<View>& views, const FramesOptions& options,
                     const SceneIntersections* intersections = nullptr);

// Every frame's sheet lines at one scale (style.scale, or the largest ISO 5455 scale at which the
// union of the frames' drawn lines fits) about one centre (that union's centre). Throws
// std::invalid_argument with the reason when style.scale is given and the frames do not fit.
std::vector<SheetLines> frames_sheet(const std::vector<LineDrawing>& frames, const DrawingStyle& style);

}  // namespace hlr::exporter
