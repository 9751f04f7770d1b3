// build_sources as a template over the kernel; included only by the instantiate_*.cpp files.
//
// Which faces are coplanar, which components are closed and consistently oriented, and which of
// those are inward (wound clockwise seen from outside, as STL exporters with flipped normals write
// them), are facts of the model, decided once in model space with exact arithmetic on the input
// doubles (Epick's predicates, which are exact on them), whatever the kernel; so the same faces are consolidated and culled in every view, and a
// mesh with every face reversed gives the same sources. Facing and
// everything after it is decided in view space on kernel K.
#pragma once

#include <hlr/clipper/area_sign.hpp>
#include <hlr/hidden_line/parallel.hpp>
#include <hlr/hidden_line/visibility.hpp>
#include <hlr/kernel/mesh_edges.hpp>
#include <hlr/kernel/near_plane.hpp>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <numeric>

namespace hlr::hidden_line {
namespace detail {

// Model-space facts about one mesh's faces, independent of the view (hlr::MeshTopology, found
// once per mesh of a scene), under the names the stages use.
struct MeshTopology {
  explicit MeshTopology(std::shared_ptr<const hlr::MeshTopology> topology)
      : kept(std::move(topology)), uses(kept->uses), outward(kept->sides.outward),
        plane_vertices(kept->groups.plane_vertices), coplanar_group(kept->groups.group),
        closed_components(kept->sides.closed), open_components(kept->sides.open),
        inward_components(kept->sides.inward) {}
  std::shared_ptr<const hlr::MeshTopology> kept;
  const std::vector<EdgeUse>& uses;                                // sorted by key
  const std::vector<std::int8_t>& outward;                         // per face, as ComponentSides::outward
  const std::vector<std::array<std::uint32_t, 3>>& plane_vertices;  // per face: three non-collinear corners
  const std::vector<std::uint32_t>& coplanar_group;  // per face: lowest face of its coplanar, connected group
  std::size_t closed_components, open_components, inward_components;
};

// Predicates only, on input doubles: exact with Epick, and without Epeck's lazy nodes.
using IK = CGAL::Exact_predicates_inexact_constructions_kernel;

inline MeshTopology analyse_mesh(const Mesh& mesh) { return MeshTopology(topology_of(mesh)); }

}  // namespace detail

template <class K>
Sources<K> build_sources(const std::vector<Mesh>& meshes, const ViewFrame<K>& frame, const SourceOptions& options) {
  using G = Geometry<K>;
  using FT = typename G::FT;
  using P = typename G::Point;
  Sources<K> out;

  std::size_t polls = 0;
  for (std::uint32_t mi = 0; mi < meshes.size(); ++mi) {
    options.stop.check();
    const Mesh& mesh = meshes[mi];
    const std::size_t nf = mesh.faces.size();
    out.stats.faces += nf;
    const detail::MeshTopology topo = detail::analyse_mesh(mesh);
    out.stats.closed_components += topo.closed_components;
    out.stats.open_components += topo.open_components;
    out.stats.inward_components += topo.inward_components;

    // The vertices in view coordinates, then (perspective) the points where edges cross the near
    // plane; faces reaching behind it are clipped to rings of those points (near_plane.hpp).
    NearCut<K> cut(mesh, frame);
    std::vector<ViewPoint<K>> vp = cut.take_points();
    std::vector<P> p2(vp.size());
    for (std::size_t v = 0; v < vp.size(); ++v) p2[v] = G::point(vp[v].x, vp[v].y);
    using Part = typename NearCut<K>::Part;
    // A face's corners as point indices: its vertices, or its ring where the near plane cuts it.
    auto corners = [&](std::uint32_t f) -> const std::vector<std::uint32_t>& {
      return cut.part(f) == Part::cut ? cut.ring_points(f) : mesh.faces[f];
    };

    // One support line per mesh edge.
    std::vector<clip::LineId> edge_line(topo.uses.size());
    auto& edge_lines = out.edge_lines.emplace_back();
    std::size_t edge_count = 0;  // grown by doubling, edge_lines would keep up to half of it unused
    for_each_edge(topo.uses, [&](EdgeUses, EdgeUses) { ++edge_count; });
    edge_lines.reserve(edge_count);
    for (std::size_t i = 0; i < topo.uses.size(); ++i) {
      if (i > 0 && topo.uses[i].key == topo.uses[i - 1].key) {
        edge_line[i] = edge_line[i - 1];
        continue;
      }
      const std::uint32_t v0 = std::uint32_t(topo.uses[i].key >> 32), v1 = std::uint32_t(topo.uses[i].key);
      edge_line[i] = static_cast<clip::LineId>(out.lines.size());
      edge_lines.emplace_back(topo.uses[i].key, edge_line[i]);
      // An edge reaching behind the near plane lies on the line of its part in front; one wholly
      // behind is no face's edge in the view, and gets a line of one point.
      const auto ends = cut.edge_ends(v0, v1);
      out.lines.push_back(ends ? clip::SupportLine<K>{p2[(*ends)[0]], p2[(*ends)[1]]} : clip::SupportLine<K>{p2[v0], p2[v0]});
      if (options.line_origins) {
        LineOrigin origin;
        origin.kind = LineOrigin::mesh_edge;
        origin.mesh = static_cast<std::int32_t>(mi);
        origin.v0 = v0;
        origin.v1 = v1;
        out.line_origins.push_back(origin);
      }
    }
    auto line_of = [&](std::uint32_t a, std::uint32_t b) {
      const std::uint64_t key = edge_key(a, b);
      auto it = std::lower_bound(topo.uses.begin(), topo.uses.end(), key,
                                 [](const EdgeUse& u, std::uint64_t k) { return u.key < k; });
      return edge_line[static_cast<std::size_t>(it - topo.uses.begin())];
    };
    // The line of each face's edge from corner k to k + 1, by face (corner_start): every use is one
    // such edge, so a pass over the uses fills it, and the faces' contours need no search.
    std::vector<std::uint32_t> corner_start(nf + 1, 0);
    for (std::uint32_t f = 0; f < nf; ++f) corner_start[f + 1] = corner_start[f] + std::uint32_t(mesh.faces[f].size());
    constexpr clip::LineId kNoLine = ~clip::LineId(0);
    std::vector<clip::LineId> corner_line(corner_start[nf], kNoLine);
    for (std::size_t i = 0; i < topo.uses.size(); ++i) {
      const auto& face = mesh.faces[topo.uses[i].face];
      const std::size_t n = face.size();
      for (std::size_t k = 0; k < n; ++k) {
        clip::LineId& line = corner_line[corner_start[topo.uses[i].face] + k];
        if (line == kNoLine && edge_key(face[k], face[(k + 1) % n]) == topo.uses[i].key) {
          line = edge_line[i];
          break;
        }
      }
    }

    // Culled faces (fuzzy_cull.hpp) are hidden strictly, from every point of their closure, by
    // faces that the view keeps: they are left out before anything is computed for them, so that
    // the view spends nothing on them (their facing, their part of a coplanar group's merge, the
    // area sort). What is left covers the same points at the same depths where anything is seen.
    const std::vector<bool>* culled = options.culled ? &(*options.culled)[mi] : nullptr;
    auto is_culled = [&](std::uint32_t f) { return culled && (*culled)[f]; };

    // Facing: the sign of the projected area (+1 toward the viewer).
    std::vector<int> facing(nf);
    for (std::uint32_t f = 0; f < nf; ++f) {
      options.stop.check_every(polls, 4096);
      if (cut.part(f) == Part::behind || is_culled(f)) continue;
      const auto& face = corners(f);
      if (face.size() == 3) {
        facing[f] = G::orientation(p2[face[0]], p2[face[1]], p2[face[2]]);
      } else {
        clip::Contour<K> c;
        for (std::uint32_t v : face) c.points.push_back(p2[v]);
        facing[f] = clip::area_sign(c);
      }
    }
    std::vector<bool> keep(nf);
    // A component that the near plane cuts open shows its inside through the cut: its back faces
    // stay.
    const bool remove_back_faces = options.remove_back_faces && !cut.clipped();
    auto edge_on = [&](std::uint32_t f) { return facing[f] == 0 && cut.part(f) != Part::behind && !is_culled(f); };
    for (std::uint32_t f = 0; f < nf; ++f) {
      if (cut.part(f) == Part::behind) {
        ++out.stats.faces_behind_eye;
      } else if (is_culled(f)) {
        ++out.stats.faces_culled;
      } else if (facing[f] == 0) {
        ++out.stats.edge_on_faces_removed;
      } else if (facing[f] * topo.outward[f] < 0 && remove_back_faces) {
        ++out.stats.back_faces_removed;
      } else {
        keep[f] = true;
      }
    }

    // The edges of the edge-on faces, but those inside a region of coplanar ones: between two
    // triangles of one coplanar group that lie on opposite sides of it (decided on input doubles).
    auto third_corner = [&](std::uint32_t f, std::uint64_t key) {
      for (std::uint32_t v : mesh.faces[f])
        if (v != edge_low(key) && v != edge_high(key)) return v;
      return mesh.faces[f][0];
    };
    auto inside_region = [&](EdgeUses first, EdgeUses last) {
      if (!options.consolidate || last - first != 2) return false;
      const EdgeUse &u = first[0], &w = first[1];
      if (!edge_on(u.face) || !edge_on(w.face) || u.forward == w.forward ||
          topo.coplanar_group[u.face] != topo.coplanar_group[w.face])
        return false;
      if (mesh.faces[u.face].size() != 3 || mesh.faces[w.face].size() != 3) return false;
      const auto& v = mesh.vertices;
      auto point = [&](std::uint32_t i) { return detail::IK::Point_3(v[i][0], v[i][1], v[i][2]); };
      return CGAL::coplanar_orientation(point(edge_low(u.key)), point(edge_high(u.key)), point(third_corner(u.face, u.key)),
                                        point(third_corner(w.face, w.key))) == CGAL::NEGATIVE;
    };
    for_each_edge(topo.uses, [&](EdgeUses first, EdgeUses last) {
      if (std::none_of(first, last, [&](const EdgeUse& u) { return edge_on(u.face); })) return;
      if (inside_region(first, last)) return;
      if (const auto ends = cut.edge_ends(edge_low(first->key), edge_high(first->key)))
        out.edge_on_edges.push_back({mi, (*ends)[0], (*ends)[1]});
    });
    // A clipped face seen edge-on covers along its cut too.
    for (std::uint32_t f = 0; f < nf; ++f) {
      if (cut.part(f) != Part::cut || facing[f] != 0) continue;
      const auto& ring = cut.ring(f);
      for (std::size_t i = 0; i < ring.size(); ++i)
        if (ring[i].a == NearCut<K>::kCut) out.edge_on_edges.push_back({mi, ring[i].point, ring[(i + 1) % ring.size()].point});
    }

    // The line of the cut through each coplanar group's faces (the group's plane meets the near
    // plane in one line), made when a contour first needs it.
    std::vector<clip::LineId> cut_lines;
    auto cut_line = [&](std::uint32_t f, const P& a, const P& b) {
      if (cut_lines.empty()) cut_lines.assign(nf, ~clip::LineId(0));
      clip::LineId& id = cut_lines[topo.coplanar_group[f]];
      if (id == ~clip::LineId(0)) {
        id = static_cast<clip::LineId>(out.lines.size());
        out.lines.push_back({a, b});
        if (options.line_origins) out.line_origins.push_back(LineOrigin{});
      }
      return id;
    };

    // A face's contour, counter-clockwise in the view.
    auto face_contour = [&](std::uint32_t f) {
      const bool ring = cut.part(f) == Part::cut;
      const auto& face = corners(f);
      clip::Contour<K> c;
      const std::size_t n = face.size();
      // The edge from corner k to corner `next`, adjacent to it.
      auto line_between = [&](std::size_t k, std::size_t next) {
        if (!ring) return corner_line[corner_start[f] + ((k + 1) % n == next ? k : next)];
        const auto& corner = cut.ring(f)[(k + 1) % n == next ? k : next];
        if (corner.a != NearCut<K>::kCut) return line_of(corner.a, corner.b);
        return cut_line(f, p2[face[k]], p2[face[next]]);
      };
      for (std::size_t i = 0; i < n; ++i) {
        const std::size_t k = facing[f] > 0 ? i : n - 1 - i;
        const std::size_t next = facing[f] > 0 ? (i + 1) % n : (2 * n - 2 - i) % n;
        c.points.push_back(p2[face[k]]);
        c.lines.push_back(line_between(k, next));
      }
      return c;
    };
    // Three corners whose images span the face's plane: the chosen input corners, or for a ring
    // the first fan triangle from its first corner with an area (it has one: it is not edge-on).
    auto plane_corners = [&](std::uint32_t f) -> std::array<std::uint32_t, 3> {
      if (cut.part(f) != Part::cut) return topo.plane_vertices[f];
      const auto& c = corners(f);
      for (std::size_t k = 2; k < c.size(); ++k)
        if (G::orientation(p2[c[0]], p2[c[k - 1]], p2[c[k]]) != 0) return {c[0], c[k - 1], c[k]};
      return {c[0], c[1], c[2]};
    };
    auto plane_of = [&](std::uint32_t f) {
      const auto pv = plane_corners(f);
      const ViewPoint<K>&a = vp[pv[0]], &b = vp[pv[1]], &c = vp[pv[2]];
      const FT ux = b.x - a.x, uy = b.y - a.y, uz = b.z - a.z;
      const FT wx = c.x - a.x, wy = c.y - a.y, wz = c.z - a.z;
      const FT nx = uy * wz - uz * wy, ny = uz * wx - ux * wz, nz = ux * wy - uy * wx;
      DepthPlane<K> plane;
      plane.a = -nx / nz;
      plane.b = -ny / nz;
      plane.c = a.z - plane.a * a.x - plane.b * a.y;
      return plane;
    };
    auto add_source = [&](std::vector<SourcePolygon<K>>& made, clip::Polygon<K> polygon, std::vector<std::uint32_t> faces) {
      SourcePolygon<K> s;
      s.polygon = std::move(polygon);
      s.plane_points = plane_corners(faces.front());
      if (options.depth_planes) s.plane = plane_of(faces.front());
      s.mesh = mi;
      s.faces = std::move(faces);
      made.push_back(std::move(s));
    };
    // A group's sources, added to `made`: its faces merged, or each on its own. Returns the faces
    // consolidated.
    auto add_group = [&](std::vector<SourcePolygon<K>>& made, const std::vector<std::uint32_t>& faces) -> std::size_t {
      if (faces.size() > 1) {
        std::vector<clip::Contour<K>> contours;
        for (std::uint32_t f : faces) contours.push_back(face_contour(f));
        try {
          auto merged = clip::merge_polygons<K>(contours, out.lines);
          for (auto& polygon : merged) add_source(made, std::move(polygon), faces);
          return faces.size();
        } catch (const clip::ClipError&) {
          // The group's faces overlap in the view (a face and its reverse, with back faces kept;
          // or rounding on an inexact kernel): keep them apart.
        }
      }
      for (std::uint32_t f : faces) {
        clip::Polygon<K> polygon{face_contour(f), {}};
        // Import makes every polygon face planar and simple, so its projection is simple unless a
        // kernel rounds it: then the kernel fails here rather than draw without the face.
        if (mesh.faces[f].size() > 3)
          if (auto defect = clip::normalize_polygon(polygon))
            throw clip::ClipError("face " + std::to_string(mesh.face_index[f]) + " of " + mesh.file +
                                  " projects to a non-simple polygon (" + *defect + ")");
        add_source(made, std::move(polygon), {f});
      }
      return 0;
    };

    // Groups in order of their lowest face, so sources are ordered by (mesh, first face).
    std::vector<std::vector<std::uint32_t>> members(nf);
    for (std::uint32_t f = 0; f < nf; ++f)
      if (keep[f]) members[options.consolidate ? topo.coplanar_group[f] : f].push_back(f);
    std::vector<std::uint32_t> groups;
    for (std::uint32_t g = 0; g < nf; ++g)
      if (!members[g].empty()) groups.push_back(g);
    // The groups' sources on every thread: their planes and contours are most of the lazy numbers
    // a view makes. The lines of the near plane's cuts are made first, in group order, so that the
    // threads only read the line table.
    if (cut.clipped())
      for (std::uint32_t g : groups)
        for (std::uint32_t f : members[g])
          if (cut.part(f) == Part::cut) face_contour(f);
    constexpr std::size_t kGroupsPerChunk = 256;
    std::vector<std::vector<SourcePolygon<K>>> made((groups.size() + kGroupsPerChunk - 1) / kGroupsPerChunk);
    std::vector<std::size_t> consolidated(made.size(), 0);
    aligned_chunks(groups.size(), kGroupsPerChunk, [&](std::size_t begin, std::size_t end) {
      options.stop.check();
      const std::size_t chunk = begin / kGroupsPerChunk;
      made[chunk].reserve(end - begin);  // most groups make one polygon
      for (std::size_t i = begin; i != end; ++i) consolidated[chunk] += add_group(made[chunk], members[groups[i]]);
    });
    // Grown by doubling, the polygons would leave up to half their room unused, where the run's
    // memory peaks.
    std::size_t count = 0;
    for (const auto& chunk : made) count += chunk.size();
    out.polygons.reserve(out.polygons.size() + count);
    for (std::size_t k = 0; k < made.size(); ++k) {
      out.stats.faces_consolidated += consolidated[k];
      for (auto& polygon : made[k]) out.polygons.push_back(std::move(polygon));
      std::vector<SourcePolygon<K>>().swap(made[k]);
    }
    out.view_points.push_back(std::move(vp));
    out.image_points.push_back(std::move(p2));
    out.near_cuts.push_back(std::move(cut));
  }
  // Grown by doubling, and kept until the lines are classified (a drawing) or to the end of the run.
  out.polygons.shrink_to_fit();
  out.lines.shrink_to_fit();
  out.line_origins.shrink_to_fit();
  out.stats.sources = out.polygons.size();
  return out;
}

}  // namespace hlr::hidden_line
