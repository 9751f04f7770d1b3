// draw_part MESH OUT.svg [VIEW]: the engineering drawing of a mesh in one view, as an A4 sheet.
//
// One call solves the view exactly (exporter::draw_lines); the writers make the documents.
#include <hlr/export/jobs.hpp>

#include <fstream>
#include <iostream>

int main(int argc, char** argv) {
  if (argc < 3) {
    std::cerr << "usage: draw_part MESH OUT.svg [front|back|top|bottom|left|right|iso]\n";
    return 2;
  }
  hlr::View view;
  if (!hlr::named_view(argc > 3 ? argv[3] : "iso", view)) {
    std::cerr << "draw_part: unknown view " << argv[3] << '\n';
    return 2;
  }
  try {
    const hlr::Scene scene = hlr::load_scene({argv[1]});
    hlr::exporter::DrawOptions options;  // the exact kernel, creases at 30 degrees
    options.progress.stage = [](std::string_view stage) { std::cerr << "draw_part: " << stage << '\n'; };
    const hlr::exporter::LineDrawing drawing = hlr::exporter::draw_lines(scene, view, options);

    hlr::exporter::DrawingStyle style;
    style.sheet = *hlr::exporter::sheet_by_name("A4");
    std::ofstream(argv[2], std::ios::binary) << hlr::exporter::lines_svg(drawing, style);
    std::cout << drawing.stats.lines << " feature lines: " << drawing.stats.visible_pieces << " visible and "
              << drawing.stats.hidden_pieces << " hidden pieces in " << drawing.times.total << " s; wrote " << argv[2]
              << '\n';
  } catch (const std::exception& e) {  // hlr::ImportError, hlr::UserError: one line, "FILE: problem"
    std::cerr << "draw_part: " << e.what() << '\n';
    return 1;
  }
  return 0;
}
