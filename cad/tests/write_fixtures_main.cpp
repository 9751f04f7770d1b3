// cad_fixtures DIR [--bench N...]: writes the test fixtures of cad_fixtures.hpp into DIR, for
// trying hlr on them and for benchmarks (they are made, never committed); with --bench, also the
// benchmark's grid plates with N x N holes.
#include "cad_fixtures.hpp"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <vector>

int main(int argc, char** argv) {
  std::vector<int> sizes;
  bool usage = argc < 2 || (argc > 2 && std::strcmp(argv[2], "--bench") != 0);
  for (int i = 3; i < argc && !usage; ++i) {
    sizes.push_back(std::atoi(argv[i]));
    usage = sizes.back() <= 0;
  }
  if (usage) {
    std::fprintf(stderr, "usage: cad_fixtures DIR [--bench N...]\n");
    return 2;
  }
  try {
    hlr::cad_test::write_fixtures(argv[1]);
    if (!sizes.empty()) hlr::cad_test::write_bench_parts(argv[1], sizes);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "cad_fixtures: %s\n", e.what());
    return 1;
  }
  return 0;
}
