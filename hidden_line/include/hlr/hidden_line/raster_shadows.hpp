// hlr hidden_line, raster shadows: the classic shadow map (Williams 1978), as the inexact peer of
// cast_shadows (shadows.hpp) in `hlr check --sun/--point-light`. Like the P-buffer drawing
// (raster.hpp) it is floating point on purpose, and shares its Z-buffer:
//   - the map is the Z-buffer of every face of the scene seen from the light (light_view: an
//     orthographic view along a sun's rays, the perspective view from a point light), N pixels
//     along its longer side, with the raster path's slope-scaled polygon offset as depth bias;
//   - every face is sampled on a regular square grid in its own plane (sample centres inside the
//     face, even-odd rule; a face too small for any gets its corners' mean), at the map's pixel
//     spacing on that face: the pixel size for a sun, the pixel size times the face's least
//     distance along the light view's axis for a point light;
//   - a sample is lit when its face's front side faces the light (its Newell normal, in double,
//     turned over in a closed component wound inward, as cast_shadows takes the front side)
//     and its depth in the light view is no farther than the map's biased depth at its pixel.
// A face's sunlit fraction is its lit samples over its samples. docs/STABILITY.md says where the
// map is wrong (grazing light, contact shadows) and by how much.
#pragma once

#include <hlr/hidden_line/raster.hpp>
#include <hlr/hidden_line/shadows.hpp>

#include <cstdint>
#include <vector>

namespace hlr::hidden_line {

struct RasterShadows {
  RasterGrid grid;  // the map's pixels, in the light view's orthonormal frame
  // Per mesh, per face (as the meshes hold them): the sunlit fraction in [0, 1] and the samples.
  std::vector<std::vector<double>> sunlit_fraction;
  std::vector<std::vector<std::uint32_t>> samples;
  std::uint64_t total_samples = 0;
};

// The shadow map of one light at `resolution` pixels (16..8192) and every face sampled against
// it. Throws std::invalid_argument for a resolution outside that range, a light with a defect or
// a point light without a light view (point_light_defect, or a light among the geometry: the map
// has no cube of views).
RasterShadows raster_shadows(const std::vector<Mesh>& meshes, const Light& light, int resolution);

}  // namespace hlr::hidden_line
