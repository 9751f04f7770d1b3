// hlr kernel, mesh edges: which faces use each undirected edge of a mesh, and in which direction;
// the mesh's components and which way each closed one faces; which faces are coplanar. Shared by
// consolidation and back-face removal (hidden_line), feature-edge extraction and import, and
// found once per mesh of a scene (MeshTopology).
#pragma once

#include <hlr/kernel/scene.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <memory>
#include <numeric>
#include <vector>

namespace hlr {

// One directed use of an undirected mesh edge by a face.
struct EdgeUse {
  std::uint64_t key;   // (min vertex << 32) | max vertex
  std::uint32_t face;  // index into mesh.faces
  bool forward;        // the face runs min -> max
  bool fan = false;    // an internal edge of a non-planar face's fan (Mesh::fan_edges)
  std::uint8_t source = 0;  // Mesh::source_edges of this edge: 1 a B-rep edge, 3 a tangent one
};

inline std::uint64_t edge_key(std::uint32_t a, std::uint32_t b) {
  return (std::uint64_t(std::min(a, b)) << 32) | std::max(a, b);
}
inline std::uint32_t edge_low(std::uint64_t key) { return std::uint32_t(key >> 32); }
inline std::uint32_t edge_high(std::uint64_t key) { return std::uint32_t(key); }

// Every face's edge uses, sorted by (key, face).
std::vector<EdgeUse> edge_uses(const Mesh& mesh);

using EdgeUses = std::vector<EdgeUse>::const_iterator;

// Calls visit(first, last) for the uses of each mesh edge in [begin, end) (uses sorted by key;
// begin and end where edges start).
template <class Visit>
void for_each_edge(EdgeUses begin, EdgeUses end, Visit&& visit) {
  for (EdgeUses first = begin; first != end;) {
    const std::uint64_t key = first->key;
    const EdgeUses last = std::find_if(first, end, [key](const EdgeUse& u) { return u.key != key; });
    visit(first, last);
    first = last;
  }
}
template <class Visit>
void for_each_edge(const std::vector<EdgeUse>& uses, Visit&& visit) {
  for_each_edge(uses.begin(), uses.end(), visit);
}


struct UnionFind {
  std::vector<std::uint32_t> parent;
  explicit UnionFind(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0u); }
  std::uint32_t find(std::uint32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  void join(std::uint32_t a, std::uint32_t b) {
    a = find(a);
    b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);  // the root is the lowest face
  }
};

// Components are faces joined across shared edges. A component is closed when every edge has
// exactly two faces that run it in opposite directions; then the sign of the volume it encloses
// (exact, from the input doubles) says whether its faces' front sides face outward (+) or inward
// (-, wound clockwise seen from outside, as exporters with flipped normals write).
struct ComponentSides {
  std::vector<std::uint32_t> component;  // per face: the lowest face of its component
  // Per face: +1 in a closed, outward component, -1 in a closed, inward one, 0 elsewhere (open,
  // inconsistently oriented, or enclosing no volume: no side is the outside).
  std::vector<std::int8_t> outward;
  std::size_t closed = 0, open = 0, inward = 0;  // component counts
};
ComponentSides component_sides(const Mesh& mesh, const std::vector<EdgeUse>& uses);

// Coplanar groups, facts of the model decided exactly on the input doubles (Epick's predicates):
// faces joined across an edge of exactly two faces that run it in opposite directions, with every
// corner of one in the plane of the other. The surfaces the area sort consolidates (hidden_line)
// and the planar surfaces of the smooth-edge rule (features.hpp).
struct CoplanarGroups {
  std::vector<std::array<std::uint32_t, 3>> plane_vertices;  // per face: three non-collinear corners
  std::vector<std::uint32_t> group;                          // per face: the lowest face of its group
};
CoplanarGroups coplanar_groups(const Mesh& mesh, const std::vector<EdgeUse>& uses);

// All of the above for one mesh: facts of the model, the same in every view.
struct MeshTopology {
  std::vector<EdgeUse> uses;
  ComponentSides sides;
  CoplanarGroups groups;
};
MeshTopology analyse_mesh(const Mesh& mesh);
// The mesh's topology as its Scene keeps it (Mesh::topology), or for a mesh that no Scene holds,
// found now.
std::shared_ptr<const MeshTopology> topology_of(const Mesh& mesh);

}  // namespace hlr
