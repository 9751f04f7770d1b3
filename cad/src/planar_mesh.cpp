// CGAL first: OpenCASCADE defines a macro Handle(C), which CGAL's own Handle names would expand.
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include "planar_mesh.hpp"

#include <BRepMesh_DataStructureOfDelaun.hxx>
#include <BRepMesh_DelaunayBaseMeshAlgo.hxx>
#include <BRepMesh_Edge.hxx>
#include <BRepMesh_MeshAlgoFactory.hxx>
#include <BRepMesh_Triangle.hxx>
#include <IMeshData_Face.hxx>
#include <TopExp_Explorer.hxx>

#include <cstdlib>
#include <deque>
#include <utility>
#include <vector>

namespace hlr::cad {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<Standard_Integer, Kernel>;  // the node's index
using FaceBase = CGAL::Constrained_triangulation_face_base_2<
    Kernel, CGAL::Triangulation_face_base_with_info_2<int, Kernel>>;  // nesting depth, -1 unknown
// Constraints that cross, or that pass through a node, throw: such a boundary goes to BRepMesh.
using Triangulation = CGAL::Constrained_Delaunay_triangulation_2<
    Kernel, CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>, CGAL::No_constraint_intersection_tag>;

// Vertices or edges inside the face, off its boundary wires: BRepMesh's own algorithm takes them.
bool has_inner_parts(const TopoDS_Face& face) {
  for (TopExp_Explorer e(face, TopAbs_VERTEX, TopAbs_EDGE); e.More(); e.Next()) return true;
  for (TopExp_Explorer e(face, TopAbs_EDGE); e.More(); e.Next())
    if (e.Current().Orientation() == TopAbs_INTERNAL || e.Current().Orientation() == TopAbs_EXTERNAL) return true;
  return false;
}

// Each triangle's depth in the nesting of the boundary's loops, from the outside (0): a triangle
// with an odd depth is inside the B-rep face (as in CGAL's polygon-with-holes example).
void mark_depths(Triangulation& t) {
  for (auto f = t.all_faces_begin(); f != t.all_faces_end(); ++f) f->info() = -1;
  std::deque<std::pair<Triangulation::Face_handle, int>> seeds{{t.infinite_face(), 0}};
  while (!seeds.empty()) {
    const auto [seed, depth] = seeds.front();
    seeds.pop_front();
    if (seed->info() != -1) continue;
    std::deque<Triangulation::Face_handle> queue{seed};
    seed->info() = depth;
    while (!queue.empty()) {
      const Triangulation::Face_handle f = queue.front();
      queue.pop_front();
      for (int i = 0; i < 3; ++i) {
        const Triangulation::Face_handle n = f->neighbor(i);
        if (n->info() != -1) continue;
        if (t.is_constrained({f, i})) {
          seeds.emplace_back(n, depth + 1);
        } else {
          n->info() = depth;
          queue.push_back(n);
        }
      }
    }
  }
}

class PlanarFaceAlgo : public BRepMesh_DelaunayBaseMeshAlgo {
 public:
  void Perform(const IMeshData::IFaceHandle& face, const IMeshTools_Parameters& parameters,
               const Message_ProgressRange& range) override {
    if (has_inner_parts(face->GetFace())) {
      BRepMesh_MeshAlgoFactory().GetAlgo(GeomAbs_Plane, parameters)->Perform(face, parameters, range);
      return;
    }
    BRepMesh_DelaunayBaseMeshAlgo::Perform(face, parameters, range);
  }

 protected:
  // The boundary's nodes and links are in the structure (initDataStructure); the triangles inside
  // them are added, or BRepMesh's Delaunay makes them where the triangulation cannot.
  void generateMesh(const Message_ProgressRange& range) override {
    const Handle(BRepMesh_DataStructureOfDelaun)& structure = getStructure();
    if (!triangulate(*structure)) BRepMesh_DelaunayBaseMeshAlgo::generateMesh(range);
  }

 private:
  static bool triangulate(BRepMesh_DataStructureOfDelaun& structure) {
    const Standard_Integer nodes = structure.NbNodes();
    if (nodes < 3) return false;
    std::vector<std::pair<Kernel::Point_2, Standard_Integer>> points;
    points.reserve(std::size_t(nodes));
    for (Standard_Integer i = 1; i <= nodes; ++i) {
      const gp_XY& uv = structure.GetNode(i).Coord();
      points.emplace_back(Kernel::Point_2(uv.X(), uv.Y()), i);
    }
    Triangulation t;
    t.insert(points.begin(), points.end());
    if (t.number_of_vertices() != std::size_t(nodes)) return false;  // two nodes at one point
    std::vector<Triangulation::Vertex_handle> vertex(std::size_t(nodes) + 1);
    for (auto v = t.finite_vertices_begin(); v != t.finite_vertices_end(); ++v) vertex[std::size_t(v->info())] = v;
    try {
      for (IMeshData::IteratorOfMapOfInteger it(structure.LinksOfDomain()); it.More(); it.Next()) {
        const BRepMesh_Edge& link = structure.GetLink(it.Key());
        t.insert_constraint(vertex[std::size_t(link.FirstNode())], vertex[std::size_t(link.LastNode())]);
      }
    } catch (const Triangulation::Intersection_of_constraints_exception&) {
      return false;
    }
    mark_depths(t);
    for (auto f = t.finite_faces_begin(); f != t.finite_faces_end(); ++f) {
      if (f->info() % 2 == 0) continue;
      Standard_Integer links[3];
      Standard_Boolean forward[3];
      for (int k = 0; k < 3; ++k) {
        const Standard_Integer id =
            structure.AddLink(BRepMesh_Edge(f->vertex(k)->info(), f->vertex((k + 1) % 3)->info(), BRepMesh_Free));
        links[k] = std::abs(id);
        forward[k] = id > 0;
      }
      structure.AddElement(BRepMesh_Triangle(links, forward, BRepMesh_Free));
    }
    return true;
  }
};

}  // namespace

Handle(IMeshTools_MeshAlgo) PlanarFirstMeshAlgoFactory::GetAlgo(const GeomAbs_SurfaceType type,
                                                                const IMeshTools_Parameters& parameters) const {
  if (type == GeomAbs_Plane) return new PlanarFaceAlgo;
  return BRepMesh_MeshAlgoFactory().GetAlgo(type, parameters);
}

}  // namespace hlr::cad
