// The shadow documents (shadows.hpp): hlr-shadows/1 JSON, the per-face CSV, the view from the sun.
#include <hlr/export/shadows.hpp>

#include "document_json.hpp"
#include "numbers.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <map>

namespace hlr::exporter {
namespace {

using nlohmann::json;
using hidden_line::Facing;
using hidden_line::ShadowPoint;
using hidden_line::ShadowPolygon;
// Output in double: unit normals and shading, a picture and a measure, never a decision.
constexpr auto rough = &Geometry<ExactKernel>::rough_double;

double rounded(const hidden_line::ShadowFT& v) { return Geometry<ExactKernel>::to_double(v) + 0.0; }

json contour_json(const std::vector<ShadowPoint>& c) {
  json out = json::array();
  for (const auto& p : c) out.push_back({rounded(p.x), rounded(p.y), rounded(p.z)});
  return out;
}

json polygon_json(const ShadowPolygon& p) {
  json out;
  out["outer"] = contour_json(p.outer);
  out["holes"] = json::array();
  for (const auto& h : p.holes) out["holes"].push_back(contour_json(h));
  return out;
}

// A face as the file numbers it.
std::uint32_t file_face(const Mesh& mesh, std::uint32_t f) { return mesh.face_index.empty() ? f : mesh.face_index[f]; }

}  // namespace

namespace detail {

nlohmann::json light_json(const hidden_line::Light& light, const LightLabel& label) {
  json out;
  if (light.kind == hidden_line::Light::directional) {
    out["type"] = "directional";
    out["direction"] = {light.vector[0], light.vector[1], light.vector[2]};
  } else {
    out["type"] = "point";
    out["position"] = {light.vector[0], light.vector[1], light.vector[2]};
  }
  if (label.time) {
    out["time"] = *label.time;
    out["site"] = {{"latitude", label.site[0]}, {"longitude", label.site[1]}, {"north", label.site[2]}};
    out["azimuth"] = label.azimuth;
    out["altitude"] = label.altitude;
  }
  return out;
}

}  // namespace detail

std::string shadows_json(const ShadowsDocument& doc) {
  const auto& r = doc.result;
  json out;
  out["format"] = "hlr-shadows/1";
  out["input"] = detail::input_json(doc.input);
  json lights = json::array();
  for (std::size_t k = 0; k < doc.lights.size(); ++k) lights.push_back(detail::light_json(doc.lights[k], doc.labels[k]));
  out["lights"] = std::move(lights);

  const bool with_union = !r.face_union_shadow_area.empty();
  json sources = json::array();
  for (const auto& s : r.sources) {
    const Mesh& mesh = doc.meshes[s.mesh];
    json js;
    js["mesh"] = s.mesh;
    std::vector<std::uint32_t> faces;
    for (std::uint32_t f : s.faces) faces.push_back(file_face(mesh, f));
    std::sort(faces.begin(), faces.end());
    faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
    js["faces"] = faces;
    const double n[3] = {rough(s.normal[0]), rough(s.normal[1]), rough(s.normal[2])};
    const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    js["plane"] = {n[0] / len + 0.0, n[1] / len + 0.0, n[2] / len + 0.0, rough(s.offset) / len + 0.0};
    js["area"] = s.area;
    json per_light = json::array();
    for (const auto& sl : s.lights) {
      json jl;
      jl["facing"] = hidden_line::facing_name(sl.facing);
      jl["lit_area"] = sl.lit_area;
      json lit = json::array(), shadow = json::array();
      for (const auto& p : sl.lit) lit.push_back(polygon_json(p));
      for (const auto& sh : sl.shadow) {
        json p = polygon_json(sh.polygon);
        std::vector<std::array<std::uint32_t, 2>> by;
        for (const auto& [m, f] : sh.by) by.push_back({m, file_face(doc.meshes[m], f)});
        std::sort(by.begin(), by.end());
        by.erase(std::unique(by.begin(), by.end()), by.end());
        p["by"] = json::array();
        for (const auto& b : by) p["by"].push_back({b[0], b[1]});
        shadow.push_back(std::move(p));
      }
      jl["lit"] = std::move(lit);
      jl["shadow"] = std::move(shadow);
      per_light.push_back(std::move(jl));
    }
    js["lights"] = std::move(per_light);
    if (with_union) {
      double area = 0;
      for (std::uint32_t f : s.faces) area += r.face_union_shadow_area[s.mesh][f];
      js["union_shadow_area"] = area;
    }
    sources.push_back(std::move(js));
  }
  out["sources"] = std::move(sources);
  const auto& t = r.times;
  out["stats"] = {{"seconds", doc.read_seconds + t.total},
                  {"stage_seconds",
                   {{"read", doc.read_seconds},
                    {"sources", t.sources},
                    {"light_views", t.views},
                    {"sort", t.sort},
                    {"map_back", t.map_back},
                    {"union", t.unions}}}};
  json groups = json::array();
  for (const auto& g : r.cull_groups)
    groups.push_back({{"lights", {g.first, g.first + g.count - 1}},
                      {"patches", g.patches},
                      {"culled", doc.cull ? g.culled : 0},
                      {"parts", g.parts},
                      {"fuzzy_seconds", g.fuzzy_seconds},
                      {"solve_seconds", g.solve_seconds}});
  out["stats"]["cull"] = {{"mode", doc.cull ? "fuzzy" : "none"}, {"groups", std::move(groups)}};
  return out.dump(1) + "\n";
}

std::string shadows_csv(const ShadowsDocument& doc) {
  using detail::append_json_number;
  using detail::append_unsigned;
  const auto& r = doc.result;
  const bool with_union = !r.face_union_shadow_area.empty();
  std::string out = "mesh,face,area";
  for (const auto& label : doc.labels) out += ",lit_area_" + label.name + ",sunlit_fraction_" + label.name;
  if (with_union) out += ",union_shadow_area,union_sunlit_fraction";
  out += '\n';
  for (std::uint32_t mi = 0; mi < doc.meshes.size(); ++mi) {
    const Mesh& mesh = doc.meshes[mi];
    // Rows by the file's face numbers, in order; the faces one of them gave add up.
    std::map<std::uint32_t, std::vector<std::uint32_t>> rows;
    for (std::uint32_t f = 0; f < mesh.faces.size(); ++f) rows[file_face(mesh, f)].push_back(f);
    for (const auto& [face, parts] : rows) {
      double area = 0;
      for (std::uint32_t f : parts) area += r.face_area[mi][f];
      append_unsigned(out, mi);
      out += ',';
      append_unsigned(out, face);
      out += ',';
      append_json_number(out, area);
      for (std::size_t k = 0; k < doc.lights.size(); ++k) {
        double lit = 0;
        for (std::uint32_t f : parts) lit += r.face_lit_area[k][mi][f];
        out += ',';
        append_json_number(out, lit);
        out += ',';
        append_json_number(out, area > 0 ? lit / area : 0.0);
      }
      if (with_union) {
        double shadow = 0;
        for (std::uint32_t f : parts) shadow += r.face_union_shadow_area[mi][f];
        out += ',';
        append_json_number(out, shadow);
        out += ',';
        append_json_number(out, area > 0 ? 1 - shadow / area : 0.0);
      }
      out += '\n';
    }
  }
  return out;
}

std::string shadows_svg(const ShadowsDocument& doc) {
  using detail::append_fixed;
  constexpr double panel = 480, gap = 20, caption = 28;
  const auto& views = doc.result.views;
  const double width = std::max<std::size_t>(views.size(), 1) * (panel + gap) + gap;
  const double height = panel + caption + 2 * gap;
  std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"";
  append_fixed(out, width, 0);
  out += "\" height=\"";
  append_fixed(out, height, 0);
  out += "\" viewBox=\"0 0 ";
  append_fixed(out, width, 0);
  out += ' ';
  append_fixed(out, height, 0);
  out += "\">\n<title>hlr shadows: the view from each light</title>\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  for (std::size_t k = 0; k < views.size(); ++k) {
    const auto& v = views[k];
    double x0 = HUGE_VAL, y0 = HUGE_VAL, x1 = -HUGE_VAL, y1 = -HUGE_VAL;
    for (const auto& p : v.polygons)
      for (const auto& q : p.outer) {
        x0 = std::min(x0, q[0]);
        x1 = std::max(x1, q[0]);
        y0 = std::min(y0, q[1]);
        y1 = std::max(y1, q[1]);
      }
    if (x0 > x1) x0 = y0 = 0, x1 = y1 = 1;
    const double size = std::max({x1 - x0, y1 - y0, 1e-300});
    const double scale = panel / size;
    const double left = gap + double(k) * (panel + gap);
    // Model units to pixels: x right, y up; centred in the panel.
    const double ox = left + (panel - (x1 - x0) * scale) / 2 - x0 * scale;
    const double oy = gap + (panel + (y1 - y0) * scale) / 2 + y0 * scale;
    out += "<g id=\"light-" + std::to_string(k) + "\">\n";
    const bool point = doc.lights[k].kind == hidden_line::Light::point;
    // The direction the light travels to a source (a point light: to its first corner).
    auto light_direction = [&](std::uint32_t source) -> std::array<double, 3> {
      if (!point) return v.view.direction;
      const auto& q = doc.result.sources[source].polygons.front().outer.front();
      const auto& e = doc.lights[k].vector;
      return {rough(q.x) - e[0], rough(q.y) - e[1], rough(q.z) - e[2]};
    };
    for (int pass = 0; pass < 2; ++pass) {
      const bool lit = pass == 1;
      // Lit faces in a warm light shade, brighter where the light falls more steeply on them
      // (the cosine of incidence, in double: only a picture); faces turned away dark.
      out += lit ? "<g class=\"lit\"" : "<g class=\"shadow\" fill=\"#4a5060\"";
      out += " stroke=\"#3a3a3a\" stroke-width=\"0.4\" stroke-linejoin=\"round\" fill-rule=\"evenodd\">\n";
      for (const auto& p : v.polygons) {
        if (p.lit != lit) continue;
        out += "<path";
        if (lit) {
          const auto& n = doc.result.sources[p.source].normal;
          const auto d = light_direction(p.source);
          const double dl = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
          const double nx = rough(n[0]), ny = rough(n[1]), nz = rough(n[2]);
          const double cosine = std::clamp(-(nx * d[0] + ny * d[1] + nz * d[2]) / (dl * std::sqrt(nx * nx + ny * ny + nz * nz)), 0.0, 1.0);
          const int red = int(200 + 55 * cosine), green = int(160 + 80 * cosine), blue = int(90 + 80 * cosine);
          out += " fill=\"rgb(" + std::to_string(red) + ',' + std::to_string(green) + ',' + std::to_string(blue) + ")\"";
        }
        out += " d=\"";
        auto contour = [&](const std::vector<std::array<double, 2>>& c) {
          for (std::size_t i = 0; i < c.size(); ++i) {
            out += i == 0 ? 'M' : 'L';
            append_fixed(out, ox + c[i][0] * scale, 3);
            out += ' ';
            append_fixed(out, oy - c[i][1] * scale, 3);
          }
          out += 'Z';
        };
        contour(p.outer);
        for (const auto& h : p.holes) contour(h);
        out += "\"/>\n";
      }
      out += "</g>\n";
    }
    std::string text = doc.labels[k].time ? *doc.labels[k].time : doc.labels[k].name;
    out += "<text x=\"";
    append_fixed(out, left, 1);
    out += "\" y=\"";
    append_fixed(out, gap + panel + caption - 6, 1);
    out += "\" font-family=\"sans-serif\" font-size=\"14\">" + text + (point ? " at (" : " (");
    for (int i = 0; i < 3; ++i) {
      if (i) out += ", ";
      detail::append_json_number(out, point ? doc.lights[k].vector[i] : v.view.direction[i]);
    }
    out += ")</text>\n</g>\n";
  }
  out += "</svg>\n";
  return out;
}

}  // namespace hlr::exporter
