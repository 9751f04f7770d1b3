// hlr export, surfaces: the VisibilityMap of one view as a document.
//
//   surfaces_json  the hlr-surfaces/1 contract (DESIGN.md, docs/FORMATS.md): sources with their
//                  faces and planes, visible and hidden polygons with source and occluder tags,
//                  coordinates in the orthonormal view frame, rounded once; `exact` adds the exact
//                  values in the unnormalized frame. Its text comes in parts, in order: the
//                  polygon arrays are written on every thread, a chunk per part.
//   surfaces_svg   a picture for a person: visible polygons filled in a flat shade of their
//                  normal, hidden polygons as dashed outlines.
//
// Writers return the document; the caller writes it to disk (atomically).
#pragma once

#include <hlr/hidden_line/jobs.hpp>

#include <string>
#include <vector>

namespace hlr::exporter {

using hlr::InputInfo;

// The view as the documents write it: the orthonormal frame in double.
struct ViewInfo {
  std::string name;  // "front", ..., "custom"
  std::array<double, 3> direction{}, up{};
  std::array<std::array<double, 4>, 4> world_to_view{};
  std::optional<std::array<double, 3>> eye;  // a perspective view's
};
template <class K>
ViewInfo view_info(const ViewFrame<K>& frame) {
  const View& v = frame.view();
  return {v.name, v.direction, v.up, frame.world_to_view(), v.eye};
}

using hidden_line::StageTimes;

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
std::vector<std::string> surfaces_json(const SurfacesDocument<K>& doc, bool exact);
template <class K>
std::string surfaces_svg(const SurfacesDocument<K>& doc);

#define HLR_EXPORT_SURFACES_DECLARE(K, EXTERN)                                                 \
  EXTERN template std::vector<std::string> surfaces_json<K>(const SurfacesDocument<K>&, bool); \
  EXTERN template std::string surfaces_svg<K>(const SurfacesDocument<K>&);

HLR_EXPORT_SURFACES_DECLARE(ExactKernel, extern)
HLR_EXPORT_SURFACES_DECLARE(EpickKernel, extern)
HLR_EXPORT_SURFACES_DECLARE(DoubleKernel, extern)

}  // namespace hlr::exporter
