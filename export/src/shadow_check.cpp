// compare_shadows, check_shadows and shadow_check_json (hlr/export/shadow_check.hpp).
#include <hlr/export/shadow_check.hpp>

#include "document_json.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>

namespace hlr::exporter {

ShadowAgreement compare_shadows(const std::vector<Mesh>& meshes, const hidden_line::ShadowResult& exact,
                                std::size_t light, const hidden_line::RasterShadows& raster) {
  ShadowAgreement out;
  out.samples = raster.total_samples;
  double sum_difference = 0;
  for (std::uint32_t m = 0; m < meshes.size(); ++m)
    for (std::uint32_t f = 0; f < meshes[m].faces.size(); ++f) {
      const double area = exact.face_area[m][f];
      if (!(area > 0)) continue;
      const double exact_fraction = std::clamp(exact.face_lit_area[light][m][f] / area, 0.0, 1.0);
      const double raster_fraction = raster.sunlit_fraction[m][f];
      const double difference = std::abs(raster_fraction - exact_fraction);
      ++out.faces;
      out.area += area;
      out.exact_lit_area += exact.face_lit_area[light][m][f];
      out.raster_lit_area += raster_fraction * area;
      out.lit_area_error += difference * area;
      sum_difference += difference;
      if (difference > out.max_difference || out.faces == 1) {
        out.max_difference = difference;
        out.max_mesh = m;
        out.max_face = meshes[m].face_index.empty() ? f : meshes[m].face_index[f];
      }
    }
  out.mean_difference = out.faces > 0 ? sum_difference / out.faces : 0;
  return out;
}

ShadowCheckReport check_shadows(const Scene& scene, const std::vector<hidden_line::Light>& lights,
                                const std::vector<int>& resolutions, const hidden_line::Progress& progress) {
  ShadowCheckReport report;
  report.input = scene.input;
  report.lights = lights;
  hidden_line::ShadowOptions options;
  options.light_views = false;
  options.progress = progress;
  const hidden_line::ShadowResult exact = hidden_line::cast_shadows(scene, lights, options);
  report.reference_seconds = exact.times.total;
  for (int resolution : resolutions) {
    ShadowCheckedMethod method;
    method.resolution = resolution;
    for (std::size_t k = 0; k < lights.size(); ++k) {
      progress.check();
      progress.report("shadow map " + std::to_string(resolution) + ", light " + std::to_string(k + 1) + " of " +
                      std::to_string(lights.size()));
      const auto start = std::chrono::steady_clock::now();
      const hidden_line::RasterShadows raster = hidden_line::raster_shadows(scene.meshes, lights[k], resolution);
      method.seconds += hidden_line::seconds_since(start);
      method.lights.push_back(compare_shadows(scene.meshes, exact, k, raster));
      method.map_size.push_back({raster.grid.width, raster.grid.height});
    }
    report.methods.push_back(std::move(method));
  }
  return report;
}

std::string shadow_check_json(const ShadowCheckReport& report) {
  using nlohmann::json;
  json lights = json::array();
  for (const auto& light : report.lights) lights.push_back(detail::light_json(light));
  json reference_lit = json::array();
  double area = 0;
  json methods = json::array();
  for (const ShadowCheckedMethod& m : report.methods) {
    json per_light = json::array();
    for (std::size_t k = 0; k < m.lights.size(); ++k) {
      const ShadowAgreement& a = m.lights[k];
      per_light.push_back({{"map", {m.map_size[k][0], m.map_size[k][1]}},
                           {"faces", a.faces},
                           {"samples", a.samples},
                           {"area", a.area},
                           {"exact_lit_area", a.exact_lit_area},
                           {"raster_lit_area", a.raster_lit_area},
                           {"lit_area_error", a.lit_area_error},
                           {"relative_lit_area_error", a.relative_error()},
                           {"max_fraction_difference", a.max_difference},
                           {"max_face", {a.max_mesh, a.max_face}},
                           {"mean_fraction_difference", a.mean_difference}});
    }
    methods.push_back({{"method", "raster"},
                       {"resolution", m.resolution},
                       {"seconds", m.seconds},
                       {"status", "ok"},
                       {"lights", std::move(per_light)}});
  }
  if (!report.methods.empty())
    for (const ShadowAgreement& a : report.methods.front().lights) {
      reference_lit.push_back(a.exact_lit_area);
      area = a.area;
    }
  json out = {{"format", "hlr-check/1"},
              {"input", detail::input_json(report.input)},
              {"lights", std::move(lights)},
              {"reference",
               {{"method", "exact"}, {"seconds", report.reference_seconds}, {"area", area},
                {"lit_area", std::move(reference_lit)}}},
              {"shadow_methods", std::move(methods)}};
  return out.dump(1) + "\n";
}

}  // namespace hlr::exporter
