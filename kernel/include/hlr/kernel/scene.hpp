// Scene import: polygon meshes from OFF, OBJ, STL and PLY files, read exactly and completely.
//
// What comes back is the file's own data, not a cleaned-up mesh:
//   - Coordinates are the doubles the file spells. Text numbers ("0.1") are parsed to the nearest
//     double, once, and taken as exact from then on (DESIGN.md, exactness contract); binary float32
//     (STL, PLY float) and float64 (PLY double) values convert to double without rounding.
//   - Vertices keep the file's order. STL repeats the corner coordinates in every triangle; its
//     corners are merged when their coordinates are equal as doubles (-0 and +0 count as equal),
//     so that the mesh's edges are shared again. Nothing else is merged.
//   - Every face is kept, in file order, whatever the topology around it: non-manifold and
//     inconsistently oriented faces are kept and counted. Only degenerate faces are skipped
//     (counted too), and face_index says which face of the file each kept face was.
//
// Definitions (applied to the faces kept):
//   - degenerate: fewer than 3 vertex indices, a vertex index repeated anywhere in the face, or
//     all its vertices on one line (zero area, coincident points included), decided exactly.
//   - edge: two cyclically consecutive vertex indices of a face, unordered.
//   - non-manifold face: a face with an edge that (a) belongs to more than two faces, or
//     (b) belongs to exactly two faces that run along it in the same direction (an orientation
//     clash: the two faces are not consistently oriented, and no half-edge mesh can hold them).
//     Vertices whose faces form several fans (bow-ties) are not counted: they trouble no edge.
//
// Face groups (DESIGN.md "Feature lines": edges between groups are feature lines):
//   - OBJ: the pair (current `g` names, current `usemtl` material);
//   - OFF: the face's color (the numbers after its vertex indices);
//   - PLY: the face element's red/green/blue/alpha properties;
//   - STL: none.
// Group ids count from 0 in order of first appearance in the file. When the file has no groups
// (no g/usemtl statement, no face colors), face_group and group_names are empty.
//
// Errors throw ImportError with one line "FILE: problem": a file that cannot be read, an unknown
// extension, an empty or truncated file, a syntax error, a non-finite coordinate, a coordinate
// beyond kMaxImportCoordinate in magnitude, a vertex index out of range, or no face left.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace hlr {

// Coordinates beyond this magnitude are rejected, as in the clipper's input (app/polygon_json):
// the inexact kernels evaluate products of coordinates (degree 3 and more in 3D) in double, and
// those must not overflow.
inline constexpr double kMaxImportCoordinate = 1e100;

struct Mesh {
  std::string file;                               // path as given
  std::vector<std::array<double, 3>> vertices;    // as read, in file order (STL: merged corners)
  std::vector<std::vector<std::uint32_t>> faces;  // vertex indices per face, file order; degenerate faces skipped
  std::vector<std::uint32_t> face_index;          // faces[k] was face number face_index[k] of the file (from 0)
  std::vector<std::int32_t> face_group;           // per face: group id (see above), or empty
  std::vector<std::string> group_names;           // group_names[id]: a readable name of group id
};

struct ImportReport {
  std::size_t degenerate_faces = 0;   // skipped
  std::size_t nonmanifold_faces = 0;  // kept
  std::vector<std::string> warnings;  // one line each, "FILE: ..."
};

struct ImportError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Reads FILE by its extension (.off, .obj, .stl, .ply; any letter case). Throws ImportError.
Mesh load_mesh(const std::string& path, ImportReport& report);

}  // namespace hlr
