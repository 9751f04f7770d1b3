// hlr kernel, mesh edges: which faces use each undirected edge of a mesh, and in which direction.
// Shared by consolidation and back-face removal (hidden_line) and by feature-edge extraction.
#pragma once

#include <hlr/kernel/scene.hpp>

#include <algorithm>
#include <cstdint>
#include <vector>

namespace hlr {

// One directed use of an undirected mesh edge by a face.
struct EdgeUse {
  std::uint64_t key;   // (min vertex << 32) | max vertex
  std::uint32_t face;  // index into mesh.faces
  bool forward;        // the face runs min -> max
};

inline std::uint64_t edge_key(std::uint32_t a, std::uint32_t b) {
  return (std::uint64_t(std::min(a, b)) << 32) | std::max(a, b);
}
inline std::uint32_t edge_low(std::uint64_t key) { return std::uint32_t(key >> 32); }
inline std::uint32_t edge_high(std::uint64_t key) { return std::uint32_t(key); }

// Every face's edge uses, sorted by (key, face).
inline std::vector<EdgeUse> edge_uses(const Mesh& mesh) {
  std::vector<EdgeUse> uses;
  for (std::uint32_t f = 0; f < mesh.faces.size(); ++f) {
    const auto& face = mesh.faces[f];
    for (std::size_t i = 0; i < face.size(); ++i) {
      const std::uint32_t a = face[i], b = face[(i + 1) % face.size()];
      uses.push_back({edge_key(a, b), f, a < b});
    }
  }
  std::sort(uses.begin(), uses.end(), [](const EdgeUse& x, const EdgeUse& y) {
    return x.key != y.key ? x.key < y.key : x.face < y.face;
  });
  return uses;
}

using EdgeUses = std::vector<EdgeUse>::const_iterator;

// Calls visit(first, last) for the uses of each mesh edge (uses sorted by key).
template <class Visit>
void for_each_edge(const std::vector<EdgeUse>& uses, Visit&& visit) {
  for (EdgeUses first = uses.begin(); first != uses.end();) {
    const std::uint64_t key = first->key;
    const EdgeUses last = std::find_if(first, uses.end(), [key](const EdgeUse& u) { return u.key != key; });
    visit(first, last);
    first = last;
  }
}

}  // namespace hlr
