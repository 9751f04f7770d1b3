// The whole drawing pipeline on tiny meshes built from bytes (a structured fuzzer): vertices on a
// 4 x 4 x 4 grid, so that coincident points, collinear edges, coplanar and edge-on faces and
// touching or penetrating faces are the rule, not the exception; faces of 3 or 4 of them (4 bytes
// a face: bit 0 of the first says a quad, its other bits the 4th corner); one of the seven named
// views. Drawn exactly, with every line's pieces checked to cover it once.
#include "harness.hpp"

#include <hlr/export/jobs.hpp>

#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 4) return 0;
  static const char* const views[] = {"front", "back", "top", "bottom", "left", "right", "iso"};
  hlr::View view;
  hlr::named_view(views[data[0] % 7], view);
  const std::size_t vertex_count = 3 + data[1] % 10;
  if (size < 2 + vertex_count * 2) return 0;
  std::vector<std::array<double, 3>> vertices;
  for (std::size_t v = 0; v < vertex_count; ++v) {
    const unsigned bits = data[2 + 2 * v] | (data[3 + 2 * v] << 8);
    vertices.push_back({double(bits & 3), double((bits >> 2) & 3), double((bits >> 4) & 3)});
  }
  std::vector<std::vector<std::uint32_t>> faces;
  for (std::size_t i = 2 + vertex_count * 2; i + 4 <= size && faces.size() < 16; i += 4) {
    const std::size_t corners = 3 + (data[i] & 1);
    std::vector<std::uint32_t> face;
    for (std::size_t k = 0; k < 3; ++k) face.push_back(data[i + 1 + k] % vertex_count);
    if (corners == 4) face.push_back((data[i] >> 1) % vertex_count);
    faces.push_back(face);
  }
  return hlr::fuzz::refused_or_done([&] {
    hlr::Scene scene;
    hlr::ImportReport report;
    scene.add(hlr::make_mesh("fuzz.off", vertices, faces, report), report);
    const hlr::exporter::LineDrawing drawing = hlr::exporter::draw_lines(scene, view);
    // A line's pieces run from 0 to 1, each beginning where the one before it ends.
    auto finding = [](const char* what, unsigned line) {
      std::fprintf(stderr, "finding: the pieces of line %u %s\n", line, what);
      std::abort();
    };
    const auto& pieces = drawing.pieces;
    for (std::size_t i = 0; i < pieces.size(); ++i) {
      const bool first = i == 0 || pieces[i - 1].line != pieces[i].line;
      const bool last = i + 1 == pieces.size() || pieces[i + 1].line != pieces[i].line;
      if (first && pieces[i].t0 != 0) finding("do not begin at its start", pieces[i].line);
      if (!first && pieces[i - 1].t1 != pieces[i].t0) finding("leave a gap or overlap", pieces[i].line);
      if (last && pieces[i].t1 != 1) finding("do not reach its end", pieces[i].line);
    }
  });
}
