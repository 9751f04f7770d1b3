// Scene import: polygon meshes from OFF, OBJ, STL and PLY files, read exactly and completely.
//
// What comes back is the file's own data, made into simple planar faces that share their edges:
//   - Coordinates are the doubles the file spells. Text numbers ("0.1") are parsed to the nearest
//     double, once, and taken as exact from then on (DESIGN.md, exactness contract); binary float32
//     (STL, PLY float) and float64 (PLY double) values convert to double without rounding.
//   - Vertices keep the file's order and numbers. Vertices whose coordinates are equal as doubles
//     (-0 and +0 count as equal) are welded: faces use the first of them, so that a mesh written
//     with every face's own copies of its corners (STL always, other exporters when they split
//     vertices for normals or UVs) shares its edges again. Nothing else is merged: coordinates
//     that differ in the last bit stay apart. STL's corners are numbered by first appearance.
//   - Faces, in file order, decided exactly on the doubles (face_index says which face of the file
//     each face came from; one file face may give several):
//       * corners repeated in a row count once;
//       * a face that visits a vertex twice (a keyhole face, or two lobes touching at a corner) is
//         split there into loops; loops in one plane become the triangles of the region inside an
//         odd number of them (a loop inside another is a hole); loops in different planes are
//         taken one by one;
//       * a planar loop is one polygon face and must be simple (else an ImportError);
//       * a non-planar loop is the fan of triangles from its first corner; the fan's internal
//         edges are marked in fan_edges (DESIGN.md: feature lines only by the crease rule);
//       * a loop of fewer than 3 corners, or with all its corners on one line, is degenerate and
//         skipped (counted); a face with nothing left is a degenerate face.
//   - Every other face is kept whatever the topology around it: non-manifold and inconsistently
//     oriented faces are kept and counted.
//
// Definitions (applied to the faces kept):
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
// beyond kMaxImportCoordinate in magnitude, a vertex index out of range, a planar face that crosses
// itself, or no face left. Warnings: when more than half of the faces share no edge with another
// face after welding (a triangle soup), and when closed components are wound inward.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace hlr {

// Coordinates beyond this magnitude are rejected, as in the clipper's input (export/polygons.hpp):
// the inexact kernels evaluate products of coordinates (degree 3 and more in 3D) in double, and
// those must not overflow.
inline constexpr double kMaxImportCoordinate = 1e100;

// A circle or circular arc of the source's exact geometry, as the source gives it (doubles), and
// the polyline of mesh edges that stands for it: vertices[k] to vertices[k + 1] are mesh edges
// (input vertex indices); a whole circle ends where it starts.
struct SourceCurve {
  std::array<double, 3> centre{}, normal{};  // normal: of the circle's plane, unit
  double radius = 0;
  std::vector<std::uint32_t> vertices;
};

struct MeshTopology;  // mesh_edges.hpp

struct Mesh {
  std::string file;                               // path as given
  std::vector<std::array<double, 3>> vertices;    // as read, in file order (STL: merged corners)
  std::vector<std::vector<std::uint32_t>> faces;  // welded vertex indices per face (see above)
  std::vector<std::uint32_t> face_index;          // faces[k] came from face number face_index[k] of the file (from 0)
  // Per face, or empty when no face is a fan: bit i set when edge i (corner i to corner i + 1) is
  // an internal edge of a non-planar face's fan.
  std::vector<std::uint8_t> fan_edges;
  std::vector<std::int32_t> face_group;           // per face: group id (see above), or empty
  std::vector<std::string> group_names;           // group_names[id]: a readable name of group id
  // Feature edges given by the source instead of the crease rule (a CAD model's B-rep edges,
  // hlr/cad/cad.hpp), or empty for a mesh file. Per face: bit i (edge i, corner i to corner i + 1)
  // set when the edge lies on a B-rep edge between two B-rep faces; bit i + 4 set when that B-rep
  // edge is also tangent (its faces meet smoothly, as at a fillet's boundary). features.hpp says
  // how they are drawn. Faces of at most 4 corners (the CAD import makes triangles).
  std::vector<std::uint8_t> source_edges;
  // The source's circles and circular arcs (a CAD model's B-rep edges), or empty: export draws
  // the visible and hidden runs of their polylines with the true centre and radius.
  std::vector<SourceCurve> source_curves;
  std::string name;  // the part's name where the source names it (a STEP product), else empty
  // Its edge uses, components and coplanar groups (mesh_edges.hpp: topology_of), found once by
  // Scene::add for every stage and view of the scene; null for a mesh that no Scene holds.
  // Whatever changes a held mesh's faces or vertices must reset it.
  std::shared_ptr<const MeshTopology> topology;
};

struct ImportReport {
  std::size_t degenerate_faces = 0;   // skipped
  std::size_t nonmanifold_faces = 0;  // kept
  std::size_t welded_vertices = 0;    // vertices replaced by an earlier one with equal coordinates
  std::size_t fanned_faces = 0;       // non-planar faces taken as fans of triangles
  std::size_t split_faces = 0;        // faces split at a vertex they visit twice
  std::size_t inward_components = 0;  // closed components wound inward (mesh_edges.hpp)
  std::vector<std::string> warnings;  // one line each, "FILE: ..."
};

struct ImportError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Reads FILE by its extension (.off, .obj, .stl, .ply; any letter case). Throws ImportError.
Mesh load_mesh(const std::string& path, ImportReport& report);

// The same from a file's bytes in memory, in the format `extension` names (".off", ...); `name`
// stands for the file in messages and in Mesh::file. Throws ImportError.
Mesh parse_mesh(const std::string& name, const std::string& extension, std::string bytes, ImportReport& report);
bool is_mesh_extension(const std::string& extension);  // one that load_mesh reads

// The same checks and face preparation for a mesh given as arrays (a program's own data): `name`
// stands for the file in messages and in Mesh::file. Throws ImportError.
Mesh make_mesh(const std::string& name, std::vector<std::array<double, 3>> vertices,
               std::vector<std::vector<std::uint32_t>> faces, ImportReport& report);

// What the documents say about a scene's input.
struct InputInfo {
  std::vector<std::string> files;
  std::size_t faces = 0, vertices = 0;
  std::size_t welded_vertices = 0;  // stats: vertices import replaced by an equal earlier one
  // Per mesh: its Mesh::name ("" when the file names the part: export's part_names takes the
  // file's stem then). Beside `files`, which has the file of each mesh.
  std::vector<std::string> parts;
};

// The meshes of one drawing, and what was read.
struct Scene {
  std::vector<Mesh> meshes;
  InputInfo input;
  std::vector<std::string> warnings;  // the importer's, one line each ("FILE: ...")
  void add(Mesh mesh, const ImportReport& report);
};

// Reads every file (load_mesh) into one scene. Throws ImportError.
Scene load_scene(const std::vector<std::string>& paths);

}  // namespace hlr
