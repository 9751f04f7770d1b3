// One run of the hidden-line engine for the tests: build_sources -> area_sort ->
// intersection_lines -> classify_lines on the exact kernel, timed per stage.
#pragma once

#include "line_oracle.hpp"

#include <hlr/hidden_line/lines.hpp>
#include <hlr/hidden_line/visibility.hpp>

#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

namespace hlr::hltest {

struct LineRun {
  hidden_line::LineSet<ExactKernel> set;
  double sources_seconds = 0, sort_seconds = 0, intersections_seconds = 0, classify_seconds = 0;
  double seconds() const { return sources_seconds + sort_seconds + intersections_seconds + classify_seconds; }
};

inline LineRun run_lines(const std::vector<Mesh>& meshes, const View& view, const hidden_line::LineOptions& options = {},
                         bool remove_back_faces = true) {
  using clock = std::chrono::steady_clock;
  auto since = [](clock::time_point t) { return std::chrono::duration<double>(clock::now() - t).count(); };
  LineRun out;
  const ViewFrame<ExactKernel> frame(view);
  hidden_line::SourceOptions source_options;
  source_options.remove_back_faces = remove_back_faces;
  auto t = clock::now();
  auto sources = hidden_line::build_sources<ExactKernel>(meshes, frame, source_options);
  out.sources_seconds = since(t);
  t = clock::now();
  auto map = hidden_line::area_sort<ExactKernel>(sources);
  out.sort_seconds = since(t);
  t = clock::now();
  const auto intersections = hidden_line::intersection_lines(meshes);
  out.intersections_seconds = since(t);
  t = clock::now();
  out.set = hidden_line::classify_lines<ExactKernel>(meshes, frame, sources, map, intersections, options);
  out.classify_seconds = since(t);
  return out;
}

inline LineCheckOptions check_options_for(const hidden_line::LineOptions& options) {
  LineCheckOptions c;
  c.crease_degrees = options.features.crease_degrees;
  c.intersections = options.intersections;
  return c;
}

}  // namespace hlr::hltest
