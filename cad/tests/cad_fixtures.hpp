// Test fixtures for hlr_cad, made with OpenCASCADE at test time (never downloaded, never
// committed as binaries): boxes, cylinders, booleans and fillets written to STEP, IGES and BREP.
#pragma once

#include <array>
#include <string>
#include <vector>

namespace hlr::cad_test {

// Writes into `dir` (which must exist):
//   plate.step, plate.iges, plate.brep  100 x 60 x 10 plate, two through holes (d 10) and a
//                                        counterbored hole (d 12 through, d 20 x 4 deep);
//   plate_faces.igs                      the plate in IGES's faces mode (no shared edges)
//   flange.step                          disk d 100 x 12, bore d 30, six bolt holes d 8 on d 70
//   bracket.step                         L-bracket (60 x 40 x 8 base, 8 x 40 x 50 upright), inner
//                                        edge filleted r 6, outer corner filleted r 10
//   assembly.step                        XCAF assembly: "base" (box 80 x 80 x 10) and "peg"
//                                        (cylinder d 20 x 30 placed on the base's top)
//   two_solids.step                      two boxes in one compound, no product names
//   wire_only.step                       a model with an edge and no face
void write_fixtures(const std::string& dir);

// Faces, and the pairs of distinct faces that share a B-rep edge (seams and degenerate edges left
// out), all and tangent ones, of the fixture's solid, counted by OCC on the shape written.
struct BrepCounts {
  int faces = 0, face_pairs = 0, tangent_pairs = 0;
};
BrepCounts brep_counts(const std::string& fixture);  // "plate", "flange", "bracket"

// The circles and circular arcs among the B-rep edges between two faces of a STEP file, as OCC
// reads them (STEPControl_Reader, Geom's own circles), for the true-curve tests.
struct BrepCircle {
  std::array<double, 3> centre, normal;
  double radius;
};
std::vector<BrepCircle> brep_circles(const std::string& step_path);

// Larger parts for the benchmark (bench/cad/run.sh), into `dir`: grid_NxN.step, a 10 x 10 x 1
// plate per hole pitch with an n x n grid of through holes (d 0.5 on a pitch of 1), for n in `sizes`.
void write_bench_parts(const std::string& dir, const std::vector<int>& sizes);

}  // namespace hlr::cad_test
