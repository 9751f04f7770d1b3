// The independent oracle of the shadow tests. It shares no code with hidden_line/src: it reads the
// meshes as read and a ShadowResult (shadows.hpp is only its data), and decides by brute force in
// exact arithmetic (CGAL Epeck), with the surface oracle's 2D helpers (locate, interior_point,
// closed_sides), whether the result keeps the contract of hlr-shadows/1:
//   - every lit and shadow polygon lies exactly in its source's plane and is oriented as seen from
//     the front (outer counter-clockwise, holes clockwise);
//   - lit + shadow = source, exactly, on areas (projected along the source's largest normal
//     component, Newell's normal of the faces as read);
//   - at an exact interior point of every lit polygon the ray toward the light (p - t d, t > 0;
//     a point light at e: the open segment p + t (e - p), 0 < t < 1) meets no face (faces as closed sets; faces parallel to the light, which cast no shadow of
//     positive area, left out), and the source faces the light; at one of every shadow polygon of
//     a source that faces the light the ray meets a face, and a face it meets nearest to the light
//     is in `by`; sources facing away or edge-on have `by` empty;
//   - facing agrees with the faces' own normals (the outside of a closed component wound inward);
//   - an exact interior point of every face lies in exactly one lit or shadow polygon of its source
//     (strictly inside at most one, inside or on the boundary of at least one);
//   - per face, the lit areas add up to the source's, and no face is more than fully lit.
#pragma once

#include "surface_oracle.hpp"

#include <hlr/hidden_line/shadows.hpp>

#include <string>
#include <vector>

namespace hlr::hltest {

struct ShadowCheckOptions {
  std::size_t max_errors = 10;
  // Sampled polygons per source and light (0: all): the ray tests are brute force.
  std::size_t max_polygons = 0;
};

// Every problem found, one line each (empty: the result keeps the contract).
std::vector<std::string> check_shadows(const std::vector<Mesh>& meshes, const std::vector<hidden_line::Light>& lights,
                                       const hidden_line::ShadowResult& result, const ShadowCheckOptions& options = {});

// The lit state of a model point, by the oracle alone: whether the ray from p toward a
// directional light, or the segment from p to a point light, meets a face (nearest: the faces it
// meets nearest to the light).
struct RayProbe {
  bool blocked = false;
  std::vector<FaceRef> nearest;
};
class ShadowOracle {
 public:
  explicit ShadowOracle(const std::vector<Mesh>& meshes);
  // Along p - t d for t > 0; with `segment`, for 0 < t < 1 only (d = p - e for a light at e).
  RayProbe probe(const std::array<FT, 3>& p, const std::array<FT, 3>& d, bool segment = false) const;
  // Sign of (front normal · d) of a face: -1 facing the light, 0 edge-on, +1 away (a point light
  // at e: d = a corner of the face - e).
  int facing(FaceRef f, const std::array<FT, 3>& d) const;

  struct Face {
    std::vector<std::array<FT, 3>> corners;
    std::array<FT, 3> normal;       // Newell, of the winding
    int side = 1;                   // -1 in a closed component wound inward: the front is the back
    int axis = 2;                   // largest |normal|
    std::vector<P2> projected;      // along axis
    std::array<double, 6> box{};    // x, y, z min then max
  };
  const Face& face(FaceRef f) const { return meshes_[f.mesh][f.face]; }

 private:
  std::vector<std::vector<Face>> meshes_;
};

}  // namespace hlr::hltest
