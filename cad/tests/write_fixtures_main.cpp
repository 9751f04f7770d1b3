// cad_fixtures DIR: writes the test fixtures of cad_fixtures.hpp into DIR, for trying hlr on them
// and for benchmarks (they are made, never committed).
#include "cad_fixtures.hpp"

#include <cstdio>
#include <exception>

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: cad_fixtures DIR\n");
    return 2;
  }
  try {
    hlr::cad_test::write_fixtures(argv[1]);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "cad_fixtures: %s\n", e.what());
    return 1;
  }
  return 0;
}
