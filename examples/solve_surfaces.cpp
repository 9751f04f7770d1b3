// solve_surfaces MESH [VIEW]: which parts of every face are visible in a view (the polygon area
// sort, exactly), written to stdout as hlr-surfaces/1 JSON.
#include <hlr/export/jobs.hpp>

#include <iostream>

int main(int argc, char** argv) {
  if (argc < 2) {
    std::cerr << "usage: solve_surfaces MESH [VIEW] > OUT.json\n";
    return 2;
  }
  hlr::View view;
  if (!hlr::named_view(argc > 2 ? argv[2] : "iso", view)) {
    std::cerr << "solve_surfaces: unknown view " << argv[2] << '\n';
    return 2;
  }
  try {
    const hlr::Scene scene = hlr::load_scene({argv[1]});
    const hlr::exporter::SurfacesSolution solution = hlr::exporter::solve_surfaces(scene, view);
    std::cout << solution.json(/*exact=*/false);
    std::cerr << solution.summary().visible << " visible and " << solution.summary().hidden
              << " hidden polygons\n";
  } catch (const std::exception& e) {
    std::cerr << "solve_surfaces: " << e.what() << '\n';
    return 1;
  }
  return 0;
}
