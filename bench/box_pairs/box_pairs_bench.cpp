// box_pairs_bench: the overlapping pairs of a mesh's face boxes (the penetration search's candidate
// pairs), found by hlr's overlapping_box_pairs (hidden_line/src/box_index.hpp) along each axis and
// by CGAL's box_self_intersection_d (the segment tree with a cutoff of 1,000, what hlr used before),
// on one thread. Prints one line per mesh and method: the pairs found and the least time of RUNS.
//
// usage: box_pairs_bench [--runs N] MESH...
#include "box_index.hpp"

#include <hlr/kernel/scene.hpp>

#include <CGAL/box_intersection_d.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace {

using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 3, std::size_t>;

std::vector<Box> face_boxes(const hlr::Mesh& mesh) {
  std::vector<Box> boxes;
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    double lo[3], hi[3];
    for (int k = 0; k < 3; ++k) lo[k] = hi[k] = mesh.vertices[mesh.faces[f][0]][k];
    for (std::uint32_t v : mesh.faces[f])
      for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], mesh.vertices[v][k]), hi[k] = std::max(hi[k], mesh.vertices[v][k]);
    boxes.emplace_back(lo, hi, f);
  }
  return boxes;
}

// The least wall time of `runs` calls of search(count), in milliseconds, and the pairs counted.
template <class Search>
std::pair<double, std::size_t> least_of(int runs, Search&& search) {
  double best = 1e300;
  std::size_t pairs = 0;
  for (int r = 0; r < runs; ++r) {
    std::size_t count = 0;
    const auto start = std::chrono::steady_clock::now();
    search(count);
    best = std::min(best, std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    pairs = count;
  }
  return {best, pairs};
}

}  // namespace

int main(int argc, char** argv) {
  int runs = 5;
  std::vector<std::string> paths;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--runs" && i + 1 < argc) runs = std::max(1, std::atoi(argv[++i]));
    else paths.push_back(arg);
  }
  if (paths.empty()) {
    std::fprintf(stderr, "usage: box_pairs_bench [--runs N] MESH...\n");
    return 2;
  }
  const tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
  std::printf("mesh,faces,method,pairs,ms\n");
  for (const std::string& path : paths) {
    hlr::ImportReport report;
    const hlr::Mesh mesh = hlr::load_mesh(path, report);
    const std::vector<Box> boxes = face_boxes(mesh);
    const std::string name = path.substr(path.find_last_of('/') + 1);
    auto print = [&](const std::string& method, std::pair<double, std::size_t> result) {
      std::printf("%s,%zu,%s,%zu,%.3f\n", name.c_str(), boxes.size(), method.c_str(), result.second, result.first);
    };
    print("cgal_box_self_intersection_d", least_of(runs, [&](std::size_t& count) {
            std::vector<Box> copy = boxes;
            CGAL::box_self_intersection_d<CGAL::Sequential_tag>(
                copy.begin(), copy.end(), [&](const Box&, const Box&) { ++count; }, std::ptrdiff_t(1000));
          }));
    for (int axis = 0; axis < 3; ++axis)
      print("hlr_axis_" + std::to_string(axis), least_of(runs, [&](std::size_t& count) {
              hlr::hidden_line::detail::overlapping_box_pairs(boxes, axis, [&](const Box&, const Box&) { ++count; });
            }));
  }
  return 0;
}
