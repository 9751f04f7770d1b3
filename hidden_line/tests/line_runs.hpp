// One run of the hidden-line engine for the tests: build_sources -> area_sort ->
// intersection_lines -> classify_lines on the exact kernel, timed per stage. Every run also
// classifies the lines against the sources without the area sort (what hlr draw does) and fails
// the test where the two differ: each is the other's oracle.
#pragma once

#include "line_oracle.hpp"

#include <hlr/hidden_line/lines.hpp>
#include <hlr/hidden_line/visibility.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

namespace hlr::hltest {

struct LineRun {
  hidden_line::LineSet<ExactKernel> set;
  double sources_seconds = 0, sort_seconds = 0, intersections_seconds = 0, classify_seconds = 0;
  double seconds() const { return sources_seconds + sort_seconds + intersections_seconds + classify_seconds; }
};

// A LineSet as sorted text, exact: per line its kind, mesh, mesh edge (when `edges`), end points in
// a canonical order and its pieces along that order. Equal texts mean equal drawings.
inline std::vector<std::string> line_signature(const hidden_line::LineSet<ExactKernel>& set, bool edges = true) {
  std::vector<std::string> out;
  for (const auto& l : set.lines) {
    auto text = [](const ViewPoint<ExactKernel>& p) {
      std::ostringstream s;
      s << CGAL::exact(p.x) << ' ' << CGAL::exact(p.y) << ' ' << CGAL::exact(p.z);
      return s.str();
    };
    std::string a = text(l.a), b = text(l.b);
    const bool flip = b < a;
    std::ostringstream s;
    s << feature_kind_name(l.kind) << " mesh " << l.mesh;
    if (edges && l.kind != FeatureKind::intersection) s << " edge " << l.v0 << '-' << l.v1;
    s << " [" << (flip ? b : a) << "] [" << (flip ? a : b) << "]";
    std::vector<std::string> pieces;
    for (const auto& p : l.pieces) {
      std::ostringstream q;
      if (flip)
        q << CGAL::exact(1 - p.t1) << ' ' << CGAL::exact(1 - p.t0);
      else
        q << CGAL::exact(p.t0) << ' ' << CGAL::exact(p.t1);
      q << (p.visible ? " v" : " h");
      pieces.push_back(q.str());
    }
    if (flip) std::reverse(pieces.begin(), pieces.end());
    for (const auto& p : pieces) s << " (" << p << ')';
    out.push_back(s.str());
  }
  std::sort(out.begin(), out.end());
  return out;
}

inline LineRun run_lines(const std::vector<Mesh>& meshes, const View& view, const hidden_line::LineOptions& options = {},
                         bool remove_back_faces = true, const hidden_line::AreaSortOptions& sort = {}) {
  using clock = std::chrono::steady_clock;
  auto since = [](clock::time_point t) { return std::chrono::duration<double>(clock::now() - t).count(); };
  LineRun out;
  const ViewFrame<ExactKernel> frame(view, meshes);
  hidden_line::SourceOptions source_options;
  source_options.remove_back_faces = remove_back_faces;
  auto t = clock::now();
  auto sources = hidden_line::build_sources<ExactKernel>(meshes, frame, source_options);
  out.sources_seconds = since(t);
  t = clock::now();
  auto map = hidden_line::area_sort<ExactKernel>(sources, sort);
  out.sort_seconds = since(t);
  t = clock::now();
  const auto intersections = hidden_line::intersection_lines(meshes);
  out.intersections_seconds = since(t);
  t = clock::now();
  out.set = hidden_line::classify_lines<ExactKernel>(meshes, frame, sources, map, intersections, options);
  out.classify_seconds = since(t);
  const auto direct = hidden_line::classify_lines<ExactKernel>(meshes, frame, sources, intersections, options);
  if (line_signature(direct) != line_signature(out.set))
    ADD_FAILURE() << "the lines classified against the sources differ from those against the visible fragments";
  return out;
}

// The meshes with every face reversed, first corner kept (a fan from it stays the same fan).
inline std::vector<Mesh> reversed_meshes(std::vector<Mesh> meshes) {
  for (Mesh& m : meshes) {
    m.topology.reset();
    for (std::size_t f = 0; f < m.faces.size(); ++f) {
      auto& face = m.faces[f];
      const std::size_t n = face.size();
      std::reverse(face.begin() + 1, face.end());
      if (m.fan_edges.empty()) continue;
      std::uint8_t bits = 0;  // edge j of the reversed face is edge n - 1 - j of the original
      for (std::size_t j = 0; j < n; ++j) bits |= ((m.fan_edges[f] >> (n - 1 - j)) & 1u) << j;
      m.fan_edges[f] = bits;
    }
  }
  return meshes;
}

inline LineCheckOptions check_options_for(const hidden_line::LineOptions& options) {
  LineCheckOptions c;
  c.crease_degrees = options.features.crease_degrees;
  c.smooth_edges = options.features.smooth_edges;
  c.intersections = options.intersections;
  return c;
}

}  // namespace hlr::hltest
