// add_mesh_file: a mesh file into a scene, read once and analysed once.
#pragma once

#include <hlr/kernel/scene.hpp>

#include <string>

namespace hlr {

// load_mesh and Scene::add, with the topology that the import's checks found kept in the mesh
// (Mesh::topology) rather than found again. Throws ImportError.
void add_mesh_file(Scene& scene, const std::string& path);

}  // namespace hlr
