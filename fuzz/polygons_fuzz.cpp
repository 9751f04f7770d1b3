// The hlr-polygons/1 reader, and the exact clipper on what it accepts: the document's first half
// of polygons clipped by the second, with the area identity checked exactly.
#include "harness.hpp"

#include <hlr/export/polygons.hpp>

#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  return hlr::fuzz::refused_or_done([&] {
    const auto polygons = hlr::exporter::parse_polygons(text, "fuzz.json");
    if (polygons.size() > 16) return;  // keep every run short
    const std::size_t half = polygons.size() / 2;
    const std::vector<hlr::exporter::RawPolygon> subjects(polygons.begin(), polygons.begin() + half),
        clips(polygons.begin() + half, polygons.end());
    const auto outcome = hlr::exporter::clip_polygons(subjects, clips);
    if (!outcome.identity_holds) {
      std::fprintf(stderr, "finding: area(inside) + area(outside) != area(subject) exactly\n");
      std::abort();
    }
  });
}
