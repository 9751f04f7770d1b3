// clip_squares: one square with a hole clipped by another square, exactly, as a program would
// call the clipper (exporter::clip_polygons) without files.
#include <hlr/export/polygons.hpp>

#include <iostream>

int main() {
  using hlr::exporter::RawPolygon;
  const RawPolygon subject{{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {{{1, 1}, {1, 2}, {2, 2}, {2, 1}}}};
  const RawPolygon clip{{{2, 0.1}, {6, 0.1}, {6, 6}, {2, 6}}, {}};
  hlr::exporter::ClipOptions options;
  options.exact_values = true;  // keep the exact areas as "p/q" strings too
  const hlr::exporter::ClipOutcome outcome = hlr::exporter::clip_polygons({subject}, {clip}, options);
  std::cout << outcome.inside.size() << " inside, " << outcome.outside.size() << " outside; areas "
            << outcome.inside_area_exact << " + " << outcome.outside_area_exact << " = " << outcome.subject_area_exact
            << " (" << outcome.identity_text << ")\n";
  return outcome.identity_holds ? 0 : 3;
}
