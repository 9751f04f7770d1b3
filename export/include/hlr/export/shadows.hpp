// hlr export, shadows: a ShadowResult (hidden_line/shadows.hpp) as documents.
//
//   shadows_json  the hlr-shadows/1 contract (DESIGN.md, docs/FORMATS.md): lights, sources with
//                 their faces, plane, area, and per light facing, lit area, lit and shadow
//                 polygons in model coordinates, rounded once;
//   shadows_csv   one row per input face (as the file numbers them; faces the importer split or
//                 fanned add up): mesh, face, area, and per light the lit area and sunlit
//                 fraction; with the union, the area in shadow under at least one light;
//   shadows_svg   the view from each light (the light view, orthonormal frame; a point light's
//                 is its perspective image, x and y at focal length 1): what the light
//                 sees, lit faces light and faces turned away from it dark, one panel per light.
//
// Writers return the document; the caller writes it to disk (atomically).
#pragma once

#include <hlr/export/surfaces.hpp>
#include <hlr/hidden_line/shadows.hpp>

#include <optional>
#include <string>
#include <vector>

namespace hlr::exporter {

// What a document says about a light beyond its direction: where it came from.
struct LightLabel {
  std::string name;  // a CSV column suffix and an SVG caption: "sun1", or the time of --sun-at
  // --sun-at: the time as given (ISO 8601), the site, and the sun's azimuth (degrees clockwise
  // from north) and altitude (degrees above the horizon).
  std::optional<std::string> time;
  std::array<double, 3> site{};  // latitude, longitude, north (degrees)
  double azimuth = 0, altitude = 0;
};

struct ShadowsDocument {
  const InputInfo& input;
  const std::vector<Mesh>& meshes;
  const std::vector<hidden_line::Light>& lights;
  const std::vector<LightLabel>& labels;  // per light
  const hidden_line::ShadowResult& result;
  double read_seconds = 0;
  bool cull = false;  // ShadowOptions::cull: stats.cull reports the groups' culling
};

std::string shadows_json(const ShadowsDocument& doc);
std::string shadows_csv(const ShadowsDocument& doc);
std::string shadows_svg(const ShadowsDocument& doc);

}  // namespace hlr::exporter
