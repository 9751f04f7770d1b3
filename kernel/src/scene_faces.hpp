// Internal to hlr_scene: what load_mesh makes of the faces a reader hands over (hlr/kernel/scene.hpp
// states the rules), decided exactly on the input doubles:
//   - weld_vertices: vertices with equal coordinates (== on double, -0 == +0) become the first of
//     them, so that faces written with their own copies of shared corners share their edges;
//   - prepare_face: one face as read becomes simple planar faces: repeated corners in a row are one
//     corner; a face that visits a vertex twice is split there into loops, and loops in one plane
//     are triangulated as one region (even-odd: a loop inside another is a hole); a non-planar
//     loop is the fan of triangles from its first corner; a planar loop stays one polygon, and
//     must be simple.
#pragma once

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <array>
#include <cstdint>
#include <vector>

namespace hlr::scene_detail {

// canonical[v]: the first vertex with v's coordinates (canonical[v] <= v).
std::vector<std::uint32_t> weld_vertices(const std::vector<std::array<double, 3>>& vertices);

struct PreparedFaces {
  std::vector<std::vector<std::uint32_t>> faces;
  // Per face: bit i set when edge i (corner i to corner i + 1) is an internal edge of a non-planar
  // face's fan.
  std::vector<std::uint8_t> fan_edges;
  std::size_t fanned = 0;  // non-planar faces turned into fans
  std::size_t split = 0;   // faces split at a repeated vertex
};

// Appends what `face` (welded indices) becomes; nothing when it is degenerate (no loop of three
// corners off one line). Returns the number of faces appended. Throws FormatError naming the
// face number `file_face` when a planar face (or the loops of a split face) cross themselves.
using InputPoint3 = CGAL::Exact_predicates_inexact_constructions_kernel::Point_3;
std::size_t prepare_face(const std::vector<InputPoint3>& points, const std::vector<std::uint32_t>& face,
                         std::size_t file_face, PreparedFaces& out);

}  // namespace hlr::scene_detail
