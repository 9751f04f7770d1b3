// hlr export, shadow check: the exact lit areas of every face (hidden_line::cast_shadows) against
// the raster shadow map's sunlit fractions (hidden_line::raster_shadows), for `hlr check --sun`
// and `--point-light`, and its report as hlr-check/1 JSON (docs/FORMATS.md).
//
// Per light and map resolution, over the faces with area: the largest and the mean absolute
// difference in sunlit fraction (lit area over area; 0 for a face turned away), and the
// area-weighted total, the lit-area error sum(area |raster fraction - exact fraction|). The exact
// fractions are the exact lit areas rounded once (shadows.hpp), the reference.
#pragma once

#include <hlr/export/surfaces.hpp>
#include <hlr/hidden_line/jobs.hpp>
#include <hlr/hidden_line/raster_shadows.hpp>
#include <hlr/hidden_line/shadows.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace hlr::exporter {

struct ShadowAgreement {
  std::uint32_t faces = 0;      // faces with area
  std::uint64_t samples = 0;    // the raster's samples (on faces that face the light)
  double area = 0;              // of those faces
  double exact_lit_area = 0, raster_lit_area = 0;
  double lit_area_error = 0;    // sum of area |raster fraction - exact fraction|
  double max_difference = 0;    // the largest |raster fraction - exact fraction|, on this face:
  std::uint32_t max_mesh = 0, max_face = 0;  // (as the file numbers it)
  double mean_difference = 0;   // mean over the faces
  double relative_error() const { return area > 0 ? lit_area_error / area : 0; }
};

// Light `light` of `exact` (solved for `meshes`) against a raster run of the same light.
ShadowAgreement compare_shadows(const std::vector<Mesh>& meshes, const hidden_line::ShadowResult& exact,
                                std::size_t light, const hidden_line::RasterShadows& raster);

struct ShadowCheckedMethod {
  int resolution = 0;                  // the map's pixels along its longer side
  double seconds = 0;                  // all lights: the maps and the sampling
  std::vector<ShadowAgreement> lights;  // per light
  std::vector<std::array<int, 2>> map_size;  // per light: width, height in pixels
};
struct ShadowCheckReport {
  InputInfo input;
  std::vector<hidden_line::Light> lights;
  double reference_seconds = 0;             // cast_shadows, all lights
  std::vector<ShadowCheckedMethod> methods;  // one per resolution, in the order asked
};

// The job of `hlr check --sun ...`: cast_shadows, then a raster run per resolution and light.
// Throws std::invalid_argument as cast_shadows and raster_shadows do, and Cancelled.
ShadowCheckReport check_shadows(const Scene& scene, const std::vector<hidden_line::Light>& lights,
                                const std::vector<int>& resolutions, const hidden_line::Progress& progress = {});

std::string shadow_check_json(const ShadowCheckReport& report);

}  // namespace hlr::exporter
