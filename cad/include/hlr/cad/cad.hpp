// hlr cad: CAD models in, through OpenCASCADE (STEP, IGES, OCC's own .brep).
//
// load_cad reads the model, tessellates it with BRepMesh and returns one hlr Mesh per solid (a
// shell or the free faces where there is no solid), as kernel's make_mesh prepares a mesh:
//   - vertices are welded where OCC's tessellation shares them: the nodes of one B-rep edge's
//     polygon in each of its faces, and the nodes on one B-rep vertex, are one vertex (topology,
//     no tolerance); then, as for mesh files, nodes with equal coordinates;
//   - triangles keep their B-rep face's orientation (a reversed face flips them) and location
//     transforms; face_group is the B-rep face (its number in the solid), so that `hlr mesh`'s
//     OFF/OBJ/PLY keep it;
//   - Mesh::source_edges marks the triangle edges on B-rep edges between two faces, and which of
//     those are tangent: features.hpp draws them instead of applying the crease rule;
//   - Mesh::source_curves holds the circles and circular arcs among those B-rep edges (OCC's
//     centre, normal and radius, and the edge's polyline), which export draws as true curves;
//   - a mesh is named from the STEP product (XCAF) where the file has one, else "STEM#N".
// The tessellation is the model: every visibility decision downstream is exact on its doubles.
// Tangency (G1) of a B-rep edge is OCC's classification of the input (BRepLib::EncodeRegularity
// at kTangentDegrees), not a visibility decision, so its tolerance is no breach of exactness.
//
// Kernel reads mesh files and knows nothing of OCC; the hook is load_scene below, which the
// program calls instead of kernel's: CAD extensions come here, the others go to load_mesh. OCC
// stays in this module, and in a part of it (the hlr_cad_occ.so module) that is loaded only when a
// CAD file is read, so that runs on meshes do not pay for loading OCC (src/occ_module.hpp).
//
// Errors throw ImportError "FILE: problem": unreadable or not a STEP/IGES/BRep file, no shape, no
// faces, a failed tessellation, a bad deflection, the OCC module missing. OCC's own messages are
// silenced.
#pragma once

#include <hlr/kernel/scene.hpp>

#include <string>
#include <vector>

namespace hlr::cad {

inline constexpr double kDefaultRelativeDeflection = 0.001;  // of the bounding box's diagonal
inline constexpr double kDefaultAngularDegrees = 20;
inline constexpr double kTangentDegrees = 0.5;  // B-rep edges whose faces meet below this are tangent

struct CadOptions {
  double deflection = 0;  // BRepMesh's linear deflection, model units; 0: 0.001 x the diagonal
  double angular_degrees = kDefaultAngularDegrees;  // BRepMesh's angular deflection
};

// .step, .stp, .iges, .igs, .brep (any letter case).
bool is_cad_extension(const std::string& extension);

// One solid (or shell, or the free faces) of a model, and what kernel's import reported on it.
struct CadPart {
  Mesh mesh;
  ImportReport report;
};

// The parts of one CAD file, in the file's order (assemblies depth first). Throws ImportError.
std::vector<CadPart> load_cad(const std::string& path, const CadOptions& options = {});

// Reads every file into one scene: CAD files by load_cad, mesh files by load_mesh.
Scene load_scene(const std::vector<std::string>& paths, const CadOptions& options = {});

}  // namespace hlr::cad
