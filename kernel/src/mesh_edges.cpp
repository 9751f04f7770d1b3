// edge_uses, component_sides (hlr/kernel/mesh_edges.hpp): the edge uses sorted (here rather than
// in the header, which nearly every file includes), components, closedness and the exact sign of
// the enclosed volume; coplanar_groups.
#include <hlr/kernel/mesh_edges.hpp>
#include <hlr/kernel/parallel.hpp>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/Mpzf.h>

#include <atomic>
#include <numeric>

namespace hlr {
namespace {

// The sign of the volume a closed component's faces enclose: the sum of the fan tetrahedra's
// determinants from the component's first corner, in interval arithmetic and, when that does not
// decide, in CGAL::Mpzf: exact, the determinants being sums and products of input doubles.
int enclosed_volume_sign(const Mesh& mesh, const std::vector<std::uint32_t>& faces) {
  const auto& o = mesh.vertices[mesh.faces[faces.front()][0]];
  auto volume = [&](auto zero) {
    using NT = decltype(zero);
    NT sum = zero;
    for (std::uint32_t f : faces) {
      const auto& face = mesh.faces[f];
      // An explicit result type: gmpxx would return an expression that refers to dead temporaries.
      auto d = [&](std::uint32_t v, int axis) -> NT { return NT(mesh.vertices[v][axis]) - NT(o[axis]); };
      for (std::size_t k = 1; k + 1 < face.size(); ++k) {
        const std::uint32_t a = face[0], b = face[k], c = face[k + 1];
        const NT ax = d(a, 0), ay = d(a, 1), az = d(a, 2), bx = d(b, 0), by = d(b, 1), bz = d(b, 2);
        const NT cx = d(c, 0), cy = d(c, 1), cz = d(c, 2);
        sum += ax * (by * cz - bz * cy) - ay * (bx * cz - bz * cx) + az * (bx * cy - by * cx);
      }
    }
    return sum;
  };
  {
    CGAL::Protect_FPU_rounding<true> protect;
    const CGAL::Interval_nt<false> approx = volume(CGAL::Interval_nt<false>(0));
    if (approx.inf() > 0) return 1;
    if (approx.sup() < 0) return -1;
  }
  return CGAL::sign(volume(CGAL::Mpzf(0)));
}

}  // namespace

std::vector<EdgeUse> edge_uses(const Mesh& mesh) {
  // Each face's first use, in face order (the order the uses are numbered in).
  const std::size_t nf = mesh.faces.size();
  std::vector<std::uint32_t> first_use(nf + 1, 0);
  std::uint32_t vertices = 0;
  for (std::size_t f = 0; f < nf; ++f) {
    first_use[f + 1] = first_use[f] + std::uint32_t(mesh.faces[f].size());
    for (std::uint32_t v : mesh.faces[f]) vertices = std::max(vertices, v + 1);
  }
  auto each_use = [&](std::size_t begin, std::size_t end, auto visit) {  // visit(use, its number)
    for (std::size_t f = begin; f < end; ++f) {
      const auto& face = mesh.faces[f];
      for (std::size_t i = 0; i < face.size(); ++i) {
        const std::uint32_t a = face[i], b = face[(i + 1) % face.size()];
        // The per-face bits cover the first 8 (fan) and 4 (source) edges: no shift past them.
        const bool fan = !mesh.fan_edges.empty() && i < 8 && (mesh.fan_edges[f] >> i & 1u);
        const std::uint8_t bits = mesh.source_edges.empty() || i >= 4 ? 0 : mesh.source_edges[f] >> i;
        const std::uint8_t source = (bits & 1u) ? std::uint8_t(1u | ((bits >> 4 & 1u) << 1)) : 0;
        visit(EdgeUse{edge_key(a, b), std::uint32_t(f), a < b, fan, source}, first_use[f] + std::uint32_t(i));
      }
    }
  };
  // Filed by their lower vertex on every thread (counted, placed by a scan, written), each
  // vertex's uses then sorted by (key, number): by (key, face), the uses of one face in its
  // corner order, whatever thread filed them.
  constexpr std::size_t kFaces = 16384;
  std::vector<std::uint32_t> start(std::size_t(vertices) + 1, 0);
  aligned_chunks(nf, kFaces, [&](std::size_t begin, std::size_t end) {
    each_use(begin, end, [&](const EdgeUse& u, std::uint32_t) {
      std::atomic_ref(start[edge_low(u.key) + 1]).fetch_add(1, std::memory_order_relaxed);
    });
  });
  std::partial_sum(start.begin(), start.end(), start.begin());
  std::vector<std::uint32_t> next(start.begin(), start.end() - 1), number;
  std::vector<EdgeUse> uses;  // 48 MB at 1M faces: its fresh pages faulted in on every thread
  resize_in_parallel(uses, first_use.back());
  resize_in_parallel(number, first_use.back());
  aligned_chunks(nf, kFaces, [&](std::size_t begin, std::size_t end) {
    each_use(begin, end, [&](const EdgeUse& u, std::uint32_t k) {
      const std::uint32_t at = std::atomic_ref(next[edge_low(u.key)]).fetch_add(1, std::memory_order_relaxed);
      uses[at] = u;
      number[at] = k;
    });
  });
  aligned_chunks(vertices, 1 << 16, [&](std::size_t begin, std::size_t end) {
    struct Numbered {
      std::uint32_t number;
      EdgeUse use;
    };
    std::vector<Numbered> here;  // one vertex's uses
    for (std::size_t v = begin; v < end; ++v) {
      const std::uint32_t lo = start[v], hi = start[v + 1];
      if (hi - lo < 2) continue;
      here.clear();
      for (std::uint32_t k = lo; k < hi; ++k) here.push_back({number[k], uses[k]});
      std::sort(here.begin(), here.end(), [](const Numbered& x, const Numbered& y) {
        return x.use.key != y.use.key ? x.use.key < y.use.key : x.number < y.number;
      });
      for (std::uint32_t k = lo; k < hi; ++k) uses[k] = here[k - lo].use;
    }
  });
  return uses;
}

ComponentSides component_sides(const Mesh& mesh, const std::vector<EdgeUse>& uses) {
  const std::size_t nf = mesh.faces.size();
  UnionFind components(nf);
  for_each_edge(uses, [&](EdgeUses first, EdgeUses last) {
    for (EdgeUses it = first + 1; it != last; ++it) components.join(first->face, it->face);
  });
  std::vector<bool> closed(nf, true);
  for_each_edge(uses, [&](EdgeUses first, EdgeUses last) {
    const bool manifold_pair = last - first == 2 && first[0].forward != first[1].forward;
    if (!manifold_pair) closed[components.find(first->face)] = false;
  });
  ComponentSides out;
  out.component.resize(nf);
  std::vector<std::vector<std::uint32_t>> members(nf);
  for (std::uint32_t f = 0; f < nf; ++f) {
    out.component[f] = components.find(f);
    members[out.component[f]].push_back(f);
  }
  std::vector<std::int8_t> sign(nf, 0);
  for (std::uint32_t root = 0; root < nf; ++root) {
    if (members[root].empty()) continue;
    ++(closed[root] ? out.closed : out.open);
    if (!closed[root]) continue;
    sign[root] = static_cast<std::int8_t>(enclosed_volume_sign(mesh, members[root]));
    out.inward += sign[root] < 0;
  }
  out.outward.resize(nf);
  for (std::uint32_t f = 0; f < nf; ++f) out.outward[f] = sign[out.component[f]];
  return out;
}

CoplanarGroups coplanar_groups(const Mesh& mesh, const std::vector<EdgeUse>& uses) {
  // Predicates only, on input doubles: exact with Epick, and without Epeck's lazy nodes.
  using IK = CGAL::Exact_predicates_inexact_constructions_kernel;
  const std::size_t nf = mesh.faces.size();
  auto point = [&](std::uint32_t v) {
    const auto& p = mesh.vertices[v];
    return IK::Point_3(p[0], p[1], p[2]);
  };
  CoplanarGroups out;
  out.plane_vertices.resize(nf);
  parallel_chunks(nf, 4096, [&](const auto& range) {
    for (std::size_t f = range.begin(); f != range.end(); ++f) {
      const auto& face = mesh.faces[f];
      out.plane_vertices[f] = {face[0], face[1], face[2]};
      for (std::size_t k = 2; k < face.size(); ++k) {
        if (!CGAL::collinear(point(face[0]), point(face[1]), point(face[k]))) {
          out.plane_vertices[f] = {face[0], face[1], face[k]};
          break;
        }
      }
    }
  });
  auto in_plane = [&](std::uint32_t f, std::uint32_t g) {
    const auto& pv = out.plane_vertices[f];
    const IK::Point_3 a = point(pv[0]), b = point(pv[1]), c = point(pv[2]);
    for (std::uint32_t v : mesh.faces[g])
      if (v != pv[0] && v != pv[1] && v != pv[2] && !CGAL::coplanar(a, b, c, point(v))) return false;
    return true;
  };
  // Which edges of exactly two uses, one each way, join two coplanar faces: an orientation test
  // each, on every thread, marked at the edge's first use; then joined in order.
  const std::size_t n = uses.size();
  std::vector<std::uint8_t> joins(n, 0);
  parallel_chunks(n, 8192, [&](const auto& range) {
    for (std::size_t i = range.begin(); i != range.end(); ++i) {
      const std::uint64_t key = uses[i].key;
      const bool two_uses = (i == 0 || uses[i - 1].key != key) && i + 1 < n && uses[i + 1].key == key &&
                            (i + 2 == n || uses[i + 2].key != key);
      if (!two_uses) continue;
      const EdgeUse& u = uses[i];
      const EdgeUse& w = uses[i + 1];
      joins[i] = u.forward != w.forward && u.face != w.face && in_plane(u.face, w.face);
    }
  });
  UnionFind groups(nf);
  for (std::size_t i = 0; i < n; ++i)
    if (joins[i]) groups.join(uses[i].face, uses[i + 1].face);
  out.group.resize(nf);
  for (std::uint32_t f = 0; f < nf; ++f) out.group[f] = groups.find(f);
  return out;
}

MeshTopology analyse_mesh(const Mesh& mesh) {
  MeshTopology t;
  t.uses = edge_uses(mesh);
  t.sides = component_sides(mesh, t.uses);
  t.groups = coplanar_groups(mesh, t.uses);
  return t;
}

std::shared_ptr<const MeshTopology> topology_of(const Mesh& mesh) {
  return mesh.topology ? mesh.topology : std::make_shared<const MeshTopology>(analyse_mesh(mesh));
}

}  // namespace hlr
