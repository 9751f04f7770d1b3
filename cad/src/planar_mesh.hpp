// Internal to the OCC module: BRepMesh's meshing algorithms, with planar faces triangulated by
// CGAL's constrained Delaunay triangulation instead of BRepMesh's own Delaunay.
//
// BRepMesh triangulates a planar face from its boundary nodes alone, and its Delaunay (Watson, a
// cell filter of circumcircles) grows far faster than the nodes on a face with many holes: a
// 10 x 10 plate with a 40 x 40 grid of holes spends about 20 s in its top and bottom faces. The
// boundary (the nodes and links BRepMesh put on the face's edges, shared with the neighbouring
// faces) is kept as it is; only the triangles inside it are made here. A face whose boundary the
// constrained triangulation cannot take as it is (constraints that cross or pass through another
// node, two nodes at one point) and a face with vertices or edges inside it go to BRepMesh's own
// algorithm.
#pragma once

#include <IMeshTools_MeshAlgoFactory.hxx>

namespace hlr::cad {

class PlanarFirstMeshAlgoFactory : public IMeshTools_MeshAlgoFactory {
 public:
  Handle(IMeshTools_MeshAlgo) GetAlgo(const GeomAbs_SurfaceType type,
                                      const IMeshTools_Parameters& parameters) const override;
};

}  // namespace hlr::cad
