// The surfaces writers as templates over the kernel; included only by surfaces_*.cpp.
#pragma once

#include <hlr/export/surfaces.hpp>

#include "document_json.hpp"
#include "numbers.hpp"

#include <hlr/kernel/parallel.hpp>

#include <nlohmann/json.hpp>
#include <tbb/enumerable_thread_specific.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <unordered_map>

namespace hlr::exporter {
namespace detail {

using nlohmann::json;

// View coordinates of the unnormalized frame, divided by the axis scales and rounded once. A
// corner is in several polygons (the visible and hidden pieces around it): on the exact kernel, a
// point that is not one of doubles is rounded once and its doubles kept by its identity.
template <class K>
class Rounder {
 public:
  using Point = typename Geometry<K>::Point;
  explicit Rounder(const ViewFrame<K>& frame) : frame_(frame) {}
  std::array<double, 2> point(const Point& p) const {
    using G = Geometry<K>;
    if constexpr (G::exact_constructions) {
      const CGAL::Bbox_2 box = G::bbox(p);
      if (box.xmin() != box.xmax() || box.ymin() != box.ymax()) {
        const auto [at, made] = rounded_.try_emplace(G::identity(p));
        if (made) at->second = {frame_.rounded(p, 0), frame_.rounded(p, 1)};
        return at->second;
      }
    }
    return {frame_.rounded(p, 0), frame_.rounded(p, 1)};
  }

 private:
  const ViewFrame<K>& frame_;
  mutable std::unordered_map<std::uintptr_t, std::array<double, 2>> rounded_;
};
// What a thread writing polygons keeps: its corners' doubles and its numbers' texts.
template <class K>
struct PointWriter {
  explicit PointWriter(const ViewFrame<K>& frame) : rounder(frame) {}
  Rounder<K> rounder;
  JsonNumbers numbers;
};
template <class K>
using ThreadPointWriters = tbb::enumerable_thread_specific<PointWriter<K>>;

// A document's text as parts in order: the large arrays are written on every thread in chunks,
// kept as they are rather than copied into one string (tens of megabytes for a large scene).
struct TextParts {
  std::vector<std::string> parts{1};
  std::string& tail() { return parts.back(); }
};

// The text of dump(1), written without a JSON tree: `level` is the indent of the line a value
// starts on, its elements go one level in.
inline void new_line(std::string& out, int level) {
  out += '\n';
  out.append(std::size_t(level), ' ');
}
// An exact value's "p/q" text as a JSON string: digits, '-' and '/', nothing to escape.
inline void append_quoted(std::string& out, const std::string& text) {
  out += '"';
  out += text;
  out += '"';
}
// `"name": ` on a new line at `level`.
inline void append_key(std::string& out, int level, const char* name) {
  new_line(out, level);
  out += '"';
  out += name;
  out += "\": ";
}
template <class Element>
void append_array(std::string& out, std::size_t n, int level, Element&& element) {
  if (n == 0) {
    out += "[]";
    return;
  }
  out += '[';
  for (std::size_t i = 0; i < n; ++i) {
    if (i > 0) out += ',';
    new_line(out, level + 1);
    element(i, level + 1);
  }
  new_line(out, level);
  out += ']';
}
// append_array for a large array, on every thread: element(text, i, level) appends element i to
// `text`. Each chunk of elements is a part of its own, so the text is the same for any number of
// threads.
template <class Element>
void append_array_in_parallel(TextParts& out, std::size_t n, int level, const Element& element) {
  constexpr std::size_t grain = 512;
  if (n == 0) {
    out.tail() += "[]";
    return;
  }
  std::vector<std::string> chunks((n + grain - 1) / grain);
  aligned_chunks(n, grain, [&](std::size_t begin, std::size_t end) {
    std::string& text = chunks[begin / grain];
    for (std::size_t i = begin; i < end; ++i) {
      text += i == 0 ? '[' : ',';
      new_line(text, level + 1);
      element(text, i, level + 1);
    }
  });
  for (std::string& chunk : chunks) out.parts.push_back(std::move(chunk));
  out.parts.emplace_back();
  new_line(out.tail(), level);
  out.tail() += ']';
}
// A contour's points rounded ([x, y] numbers) or, `exact`, as "p/q" strings.
template <class K>
void append_contour(std::string& out, const clip::Contour<K>& c, PointWriter<K>& w, bool exact, int level) {
  using G = Geometry<K>;
  append_array(out, c.points.size(), level, [&](std::size_t i, int at) {
    const auto& p = c.points[i];
    std::array<double, 2> xy{};
    if (!exact) xy = w.rounder.point(p);
    append_array(out, 2, at, [&](std::size_t k, int) {
      if (exact) append_quoted(out, G::exact_string(k == 0 ? G::x(p) : G::y(p)));
      else w.numbers.append(out, xy[k]);
    });
  });
}
// The "visible" or "hidden" array: each fragment an object, its keys in order.
template <class K>
void append_fragments(TextParts& out, const std::vector<hidden_line::Fragment<K>>& fragments,
                      ThreadPointWriters<K>& writers, bool exact, bool hidden) {
  append_array_in_parallel(out, fragments.size(), 1, [&](std::string& text, std::size_t i, int at) {
    const auto& f = fragments[i];
    PointWriter<K>& w = writers.local();
    auto key = [&](const char* name) { append_key(text, at + 1, name); };
    auto holes = [&](bool as_exact) {
      append_array(text, f.polygon.holes.size(), at + 1,
                   [&](std::size_t h, int in) { append_contour(text, f.polygon.holes[h], w, as_exact, in); });
    };
    text += '{';
    key("holes");
    holes(false);
    if (exact) {
      text += ',';
      key("holes_exact");
      holes(true);
    }
    if (hidden) {
      text += ',';
      key("occluder");
      text += std::to_string(f.occluder);
    }
    text += ',';
    key("outer");
    append_contour(text, f.polygon.outer, w, false, at + 1);
    if (exact) {
      text += ',';
      key("outer_exact");
      append_contour(text, f.polygon.outer, w, true, at + 1);
    }
    text += ',';
    key("source");
    append_unsigned(text, f.source);
    new_line(text, at);
    text += '}';
  });
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


// The "sources" array: each source's file faces, mesh, rounded plane and (exact) plane values.
template <class K>
void append_sources(TextParts& out, const SurfacesDocument<K>& doc, bool exact) {
  using G = Geometry<K>;
  append_array_in_parallel(out, doc.sources.polygons.size(), 1, [&](std::string& text, std::size_t i, int at) {
    const auto& s = doc.sources.polygons[i];
    const Mesh& mesh = doc.meshes[s.mesh];
    std::vector<std::uint32_t> faces;  // file faces; one may have given several (scene.hpp)
    faces.reserve(s.faces.size());
    for (std::uint32_t f : s.faces) faces.push_back(mesh.face_index.empty() ? f : mesh.face_index[f]);
    std::sort(faces.begin(), faces.end());
    faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
    text += '{';
    append_key(text, at + 1, "faces");
    append_array(text, faces.size(), at + 1, [&](std::size_t k, int) { append_unsigned(text, faces[k]); });
    text += ',';
    append_key(text, at + 1, "mesh");
    append_unsigned(text, s.mesh);
    text += ',';
    append_key(text, at + 1, "plane");
    const auto plane = orthonormal_plane(*s.plane, doc.frame);
    append_array(text, 4, at + 1, [&](std::size_t k, int) { append_json_number(text, plane[k]); });
    if (exact) {
      text += ',';
      append_key(text, at + 1, "plane_exact");
      const std::string values[4] = {G::exact_string(s.plane->a), G::exact_string(s.plane->b), "-1",
                                     G::exact_string(s.plane->c)};
      append_array(text, 4, at + 1, [&](std::size_t k, int) { append_quoted(text, values[k]); });
    }
    new_line(text, at);
    text += '}';
  });
}

}  // namespace detail

// The document as nlohmann::json's dump(1) would write it, members in the order of their keys, made
// member by member so that "stats" is made last (its `write` times the making of the others) and
// put in its place.
template <class K>
std::vector<std::string> surfaces_json(const SurfacesDocument<K>& doc, bool exact) {
  using detail::append_member;
  const auto begin = std::chrono::steady_clock::now();
  detail::ThreadPointWriters<K> writers([&] { return detail::PointWriter<K>(doc.frame); });

  detail::TextParts before, after;
  before.tail() = "{";
  append_member(before.tail(), "format", "hlr-surfaces/1");
  before.tail() += ",\n \"hidden\": ";
  detail::append_fragments(before, doc.map.hidden, writers, exact, true);
  before.tail() += ',';
  append_member(before.tail(), "input", detail::input_json(doc.input));
  before.tail() += ',';
  append_member(before.tail(), "kernel", kernel_name(doc.kernel));
  before.tail() += ",\n \"sources\": ";
  detail::append_sources(before, doc, exact);
  before.tail() += ',';
  after.tail() = ",";
  append_member(after.tail(), "view", detail::view_json(view_info(doc.frame)));
  after.tail() += ",\n \"visible\": ";
  detail::append_fragments(after, doc.map.visible, writers, exact, false);
  after.tail() += "\n}\n";

  const auto& ss = doc.sources.stats;
  const auto& as = doc.map.stats;
  const double write = doc.times.write + hidden_line::seconds_since(begin);
  std::string& stats = before.parts.emplace_back();
  append_member(stats, "stats",
                {
                    {"seconds", doc.times.total + write},
                    {"stage_seconds",
                     {{"read", doc.times.read}, {"sources", doc.times.sources}, {"sort", doc.times.sort}, {"write", write}}},
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
                });
  for (std::string& part : after.parts) before.parts.push_back(std::move(part));
  return std::move(before.parts);
}

template <class K>
std::string surfaces_svg(const SurfacesDocument<K>& doc) {
  const detail::Rounder<K> r(doc.frame);
  double x0 = HUGE_VAL, y0 = HUGE_VAL, x1 = -HUGE_VAL, y1 = -HUGE_VAL;
  auto grow = [&](const clip::Polygon<K>& p) {
    for (const auto& q : p.outer.points) {
      const auto [x, y] = r.point(q);
      x0 = std::min(x0, x);
      x1 = std::max(x1, x);
      y0 = std::min(y0, y);
      y1 = std::max(y1, y);
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
      for (std::size_t i = 0; i < c.points.size(); ++i) {
        const auto [x, y] = r.point(c.points[i]);
        d << (i == 0 ? "M" : "L") << x << ' ' << -y << ' ';
      }
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
