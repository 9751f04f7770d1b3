// hlrdraw, arrays: meshes and drawings between numpy arrays and the library's types.
//
//   mesh_from_arrays  a mesh from a program's arrays, through hlr::make_mesh, so that it is checked
//                     and prepared as a file is (scene.hpp); faces are an (m, k) integer array or a
//                     sequence of integer sequences (polygons of any size). What make_mesh cannot
//                     see, because it takes unsigned indices, is checked here first: the arrays'
//                     shapes, integer faces, negative indices. Every problem is one line
//                     "NAME: problem" (hlr::ImportError), NAME standing for the file.
//   mesh_vertices, mesh_faces
//                     a mesh's vertices as an (n, 3) array, its faces as an (m, k) array when all
//                     have k corners, else a list of 1-D arrays.
//   drawing_arrays    the pieces of a line drawing as a dict of arrays, one row per piece of
//                     hlr-lines/1: a, b (n, 3), visible (bool), kind (codes of FeatureKind), mesh,
//                     edge (n, 2; -1 for intersection lines, which lie on no mesh edge).
#pragma once

#include <hlr/export/lines.hpp>
#include <hlr/kernel/scene.hpp>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <string>

namespace hlrdraw {

namespace py = pybind11;

hlr::Mesh mesh_from_arrays(const std::string& name, const py::handle& vertices, const py::handle& faces,
                           hlr::ImportReport& report);

py::array_t<double> mesh_vertices(const hlr::Mesh& mesh);
py::object mesh_faces(const hlr::Mesh& mesh);

py::dict drawing_arrays(const hlr::exporter::LineDrawing& drawing);

}  // namespace hlrdraw
