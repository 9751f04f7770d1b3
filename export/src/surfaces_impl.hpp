// The surfaces writers as templates over the kernel; included only by surfaces_*.cpp.
#pragma once

#include <hlr/export/surfaces.hpp>

#include "document_json.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace hlr::exporter {
namespace detail {

using nlohmann::json;

// View coordinates of the unnormalized frame, divided by the axis scales and rounded once.
template <class K>
struct Rounder {
  const ViewFrame<K>& frame;
  double x(const typename Geometry<K>::Point& p) const { return frame.rounded(Geometry<K>::x(p), 0); }
  double y(const typename Geometry<K>::Point& p) const { return frame.rounded(Geometry<K>::y(p), 1); }
};

template <class K>
json contour_json(const clip::Contour<K>& c, const Rounder<K>& r) {
  json out = json::array();
  for (const auto& p : c.points) out.push_back({r.x(p), r.y(p)});
  return out;
}

template <class K>
json contour_exact(const clip::Contour<K>& c) {
  using G = Geometry<K>;
  json out = json::array();
  for (const auto& p : c.points) out.push_back({G::exact_string(G::x(p)), G::exact_string(G::y(p))});
  return out;
}

template <class K>
json polygon_json(const clip::Polygon<K>& polygon, const Rounder<K>& r, bool exact) {
  json p;
  p["outer"] = contour_json(polygon.outer, r);
  p["holes"] = json::array();
  for (const auto& h : polygon.holes) p["holes"].push_back(contour_json(h, r));
  if (exact) {
    p["outer_exact"] = contour_exact(polygon.outer);
    p["holes_exact"] = json::array();
    for (const auto& h : polygon.holes) p["holes_exact"].push_back(contour_exact(h));
  }
  return p;
}

// A source plane z = a x + b y + c of the unnormalized frame, as a unit-normal plane
// [a, b, c, d] of the orthonormal frame with its normal toward the viewer.
template <class K>
std::array<double, 4> orthonormal_plane(const hidden_line::DepthPlane<K>& plane, const ViewFrame<K>& frame) {
  // With x' = sx x, y' = sy y, z' = sz z: -a sx x - b sy y + sz z - c = 0.
  using G = Geometry<K>;
  const double n[4] = {-G::rough_double(plane.a) * frame.scale(0), -G::rough_double(plane.b) * frame.scale(1),
                       frame.scale(2), -G::rough_double(plane.c)};
  const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  return {n[0] / len, n[1] / len, n[2] / len, n[3] / len};
}


}  // namespace detail

template <class K>
std::string surfaces_json(const SurfacesDocument<K>& doc, bool exact) {
  using detail::json;
  using G = Geometry<K>;
  const detail::Rounder<K> r{doc.frame};
  json out;
  out["format"] = "hlr-surfaces/1";
  out["input"] = detail::input_json(doc.input);
  out["view"] = detail::view_json(view_info(doc.frame));
  out["kernel"] = kernel_name(doc.kernel);

  json sources = json::array();
  for (const auto& s : doc.sources.polygons) {
    json js;
    js["mesh"] = s.mesh;
    const Mesh& mesh = doc.meshes[s.mesh];
    std::vector<std::uint32_t> faces;  // file faces; one may have given several (scene.hpp)
    for (std::uint32_t f : s.faces) faces.push_back(mesh.face_index.empty() ? f : mesh.face_index[f]);
    std::sort(faces.begin(), faces.end());
    faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
    js["faces"] = faces;
    const auto plane = detail::orthonormal_plane(*s.plane, doc.frame);
    js["plane"] = {plane[0], plane[1], plane[2], plane[3]};
    if (exact)
      js["plane_exact"] = {G::exact_string(s.plane->a), G::exact_string(s.plane->b), "-1", G::exact_string(s.plane->c)};
    sources.push_back(std::move(js));
  }
  out["sources"] = std::move(sources);

  json visible = json::array(), hidden = json::array();
  for (const auto& f : doc.map.visible) {
    json p = detail::polygon_json(f.polygon, r, exact);
    p["source"] = f.source;
    visible.push_back(std::move(p));
  }
  for (const auto& f : doc.map.hidden) {
    json p = detail::polygon_json(f.polygon, r, exact);
    p["source"] = f.source;
    p["occluder"] = f.occluder;
    hidden.push_back(std::move(p));
  }
  out["visible"] = std::move(visible);
  out["hidden"] = std::move(hidden);

  const auto& ss = doc.sources.stats;
  const auto& as = doc.map.stats;
  out["stats"] = {
      {"seconds", doc.times.total},
      {"stage_seconds", {{"read", doc.times.read}, {"sources", doc.times.sources}, {"sort", doc.times.sort}}},
      {"faces", ss.faces},
      {"welded_vertices", doc.input.welded_vertices},
      {"back_faces_removed", ss.back_faces_removed},
      {"edge_on_faces_removed", ss.edge_on_faces_removed},
      {"faces_consolidated", ss.faces_consolidated},
      {"sources", ss.sources},
      {"closed_components", ss.closed_components},
      {"open_components", ss.open_components},
      {"inward_components", ss.inward_components},
      {"clips", as.clips},
      {"recursions", as.recursions},
      {"penetration_splits", as.penetration_splits},
      {"coplanar_ties", as.coplanar_ties},
  };
  return out.dump(1) + "\n";
}

template <class K>
std::string surfaces_svg(const SurfacesDocument<K>& doc) {
  const detail::Rounder<K> r{doc.frame};
  double x0 = HUGE_VAL, y0 = HUGE_VAL, x1 = -HUGE_VAL, y1 = -HUGE_VAL;
  auto grow = [&](const clip::Polygon<K>& p) {
    for (const auto& q : p.outer.points) {
      x0 = std::min(x0, r.x(q));
      x1 = std::max(x1, r.x(q));
      y0 = std::min(y0, r.y(q));
      y1 = std::max(y1, r.y(q));
    }
  };
  for (const auto& f : doc.map.visible) grow(f.polygon);
  for (const auto& f : doc.map.hidden) grow(f.polygon);
  if (x0 > x1) x0 = y0 = 0, x1 = y1 = 1;  // nothing to draw
  const double size = std::max({x1 - x0, y1 - y0, 1e-300});
  const double margin = 0.03 * size, stroke = 0.0015 * size;
  const double width_px = 1000, height_px = std::max(100.0, 1000 * (y1 - y0 + 2 * margin) / (x1 - x0 + 2 * margin));

  std::ostringstream out;
  out.precision(9);
  auto path = [&](const clip::Polygon<K>& p) {
    std::ostringstream d;
    d.precision(9);
    auto contour = [&](const clip::Contour<K>& c) {
      for (std::size_t i = 0; i < c.points.size(); ++i)
        d << (i == 0 ? "M" : "L") << r.x(c.points[i]) << ' ' << -r.y(c.points[i]) << ' ';
      d << "Z ";
    };
    contour(p.outer);
    for (const auto& h : p.holes) contour(h);
    return d.str();
  };
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width_px << "\" height=\"" << height_px
      << "\" viewBox=\"" << x0 - margin << ' ' << -(y1 + margin) << ' ' << x1 - x0 + 2 * margin << ' '
      << y1 - y0 + 2 * margin << "\">\n"
      << "<title>hlr surfaces: " << doc.map.visible.size() << " visible, " << doc.map.hidden.size()
      << " hidden polygons</title>\n"
      << "<rect x=\"" << x0 - margin << "\" y=\"" << -(y1 + margin) << "\" width=\"" << x1 - x0 + 2 * margin
      << "\" height=\"" << y1 - y0 + 2 * margin << "\" fill=\"white\"/>\n"
      << "<g id=\"visible\" stroke=\"#1a1a1a\" stroke-width=\"" << stroke << "\" stroke-linejoin=\"round\" fill-rule=\"evenodd\">\n";
  for (const auto& f : doc.map.visible) {
    // Lambert shade, light from the upper left behind the viewer, so that faces of different
    // orientation differ even where they make the same angle with the view direction.
    const auto n = detail::orthonormal_plane(*doc.sources.polygons[f.source].plane, doc.frame);
    const double shade = std::clamp(0.35 + 0.65 * (-0.42 * n[0] + 0.56 * n[1] + 0.71 * n[2]), 0.0, 1.0);
    const int red = int(70 + 160 * shade), green = int(95 + 150 * shade), blue = int(125 + 125 * shade);
    out << "<path d=\"" << path(f.polygon) << "\" fill=\"rgb(" << red << ',' << green << ',' << blue << ")\"/>\n";
  }
  out << "</g>\n<g id=\"hidden\" fill=\"none\" stroke=\"#c0392b\" stroke-opacity=\"0.7\" stroke-width=\"" << stroke
      << "\" stroke-dasharray=\"" << 4 * stroke << ' ' << 3 * stroke << "\">\n";
  for (const auto& f : doc.map.hidden) out << "<path d=\"" << path(f.polygon) << "\"/>\n";
  out << "</g>\n</svg>\n";
  return out.str();
}

}  // namespace hlr::exporter
