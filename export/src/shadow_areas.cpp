// shadow_areas (shadow_areas.hpp).
#include "shadow_areas.hpp"

#include <CGAL/Bbox_2.h>

#include <map>

namespace hlr::exporter::detail {
namespace {

using K = ExactKernel;
using G = Geometry<K>;

CGAL::Bbox_2 box_of(const clip::Polygon<K>& p) {
  CGAL::Bbox_2 box;
  for (const auto& q : p.outer.points) box += G::bbox(q);
  return box;
}

}  // namespace

std::vector<DrawingArea> shadow_areas(const Scene& scene, const ViewFrame<K>& frame, hidden_line::Sources<K>& sources,
                                      const hidden_line::VisibilityMap<K>& map,
                                      const std::vector<hidden_line::Light>& lights) {
  hidden_line::ShadowOptions options;
  options.light_views = false;
  const hidden_line::ShadowResult shadows = hidden_line::cast_shadows(scene, lights, options);

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
      const std::size_t first = sources.lines.size();
      clip::Contour<K> out = clip::make_contour<K>(points, sources.lines);
      sources.line_origins.resize(sources.lines.size());  // auxiliary lines
      (void)first;
      return out;
    };
    for (const auto& light : shadows.sources[model_source].lights)
      for (const auto& shadow : light.shadow) {
        clip::Polygon<K> polygon{contour(shadow.polygon.outer), {}};
        for (const auto& h : shadow.polygon.holes) polygon.holes.push_back(contour(h));
        // Seen edge-on in this view, a polygon has no area: nothing to draw.
        if (clip::normalize_polygon(polygon)) continue;
        const CGAL::Bbox_2 box = box_of(polygon);
        it->second.push_back({std::move(polygon), box});
      }
    return it->second;
  };

  std::vector<DrawingArea> out;
  auto rounded = [&](const clip::Contour<K>& c) {
    std::vector<std::array<double, 2>> points;
    for (const auto& q : c.points) points.push_back({frame.rounded(G::x(q), 0), frame.rounded(G::y(q), 1)});
    return points;
  };
  for (const auto& fragment : map.visible) {
    const auto& sp = sources.polygons[fragment.source];
    const auto& polygons = projection(shadows.face_source[sp.mesh][sp.faces.front()]);
    if (polygons.empty()) continue;
    const CGAL::Bbox_2 box = box_of(fragment.polygon);
    std::vector<clip::Polygon<K>> subjects;
    for (const auto& [polygon, b] : polygons)
      if (CGAL::do_overlap(b, box)) subjects.push_back(polygon);
    if (subjects.empty()) continue;
    const clip::ClipRegion<K> region(fragment.polygon, sources.lines);
    for (const auto& result : clip::clip_list<K>(subjects, region))
      for (const auto& piece : result.inside) {
        DrawingArea area;
        area.outer = rounded(piece.outer);
        for (const auto& h : piece.holes) area.holes.push_back(rounded(h));
        out.push_back(std::move(area));
      }
  }
  return out;
}

}  // namespace hlr::exporter::detail
