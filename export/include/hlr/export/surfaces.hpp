// hlr export, surfaces: the VisibilityMap of one view as a document.
//
//   surfaces_json  the hlr-surfaces/1 contract (DESIGN.md, docs/FORMATS.md): sources with their
//                  faces and planes, visible and hidden polygons with source and occluder tags,
//                  coordinates in the orthonormal view frame, rounded once; `exact` adds the exact
//                  values in the unnormalized frame.
//   surfaces_svg   a picture for a person: visible polygons filled in a flat shade of their
//                  normal, hidden polygons as dashed outlines.
//
// Writers return the document; the caller writes it to disk (atomically).
#pragma once

#include <hlr/hidden_line/visibility.hpp>

#include <string>
#include <vector>

namespace hlr::exporter {

struct InputInfo {
  std::vector<std::string> files;
  std::size_t faces = 0, vertices = 0;
  std::size_t welded_vertices = 0;  // stats: vertices import replaced by an equal earlier one
};

// The view as the documents write it: the orthonormal frame in double.
struct ViewInfo {
  std::string name;  // "front", ..., "custom"
  std::array<double, 3> direction{}, up{};
  std::array<std::array<double, 4>, 4> world_to_view{};
};
template <class K>
ViewInfo view_info(const ViewFrame<K>& frame) {
  const View& v = frame.view();
  return {v.name, v.direction, v.up, frame.world_to_view()};
}

// Seconds per stage, reported in "stats".
struct StageTimes {
  double read = 0, sources = 0, sort = 0, total = 0;     // total: reading and solving, every stage but `write`
  double intersections = 0, lines = 0, precedence = 0;  // hlr draw: penetrations, classification, ISO 128 precedence
  // hlr draw: the output stage, from the end of precedence to the finished JSON document (rounding
  // the exact drawing, the sheet lines, the SVG, DXF and PNG, the JSON itself); see lines_json.
  double write = 0;
};

template <class K>
struct SurfacesDocument {
  const InputInfo& input;
  const std::vector<Mesh>& meshes;
  const ViewFrame<K>& frame;
  const hidden_line::Sources<K>& sources;
  const hidden_line::VisibilityMap<K>& map;
  KernelKind kernel;
  StageTimes times;
};

template <class K>
std::string surfaces_json(const SurfacesDocument<K>& doc, bool exact);
template <class K>
std::string surfaces_svg(const SurfacesDocument<K>& doc);

#define HLR_EXPORT_SURFACES_DECLARE(K, EXTERN)                                    \
  EXTERN template std::string surfaces_json<K>(const SurfacesDocument<K>&, bool); \
  EXTERN template std::string surfaces_svg<K>(const SurfacesDocument<K>&);

HLR_EXPORT_SURFACES_DECLARE(ExactKernel, extern)
HLR_EXPORT_SURFACES_DECLARE(EpickKernel, extern)
HLR_EXPORT_SURFACES_DECLARE(DoubleKernel, extern)

}  // namespace hlr::exporter
