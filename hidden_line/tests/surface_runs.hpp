// Shared by the hidden-surface tests and the stability run: where the meshes are, the views, and
// one run of the engine (build_sources + area_sort) copied into exact form for the checks.
#pragma once

#include "surface_checks.hpp"

#include <hlr/hidden_line/visibility.hpp>
#include <hlr/kernel/scene.hpp>
#include <hlr/kernel/view.hpp>

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

namespace hlr::hltest {

// fixtures/scenes (this repository) and ../shared/scenes (beside the checkout; may be absent).
std::string fixture_dir();
std::string shared_scene_dir();
bool shared_scenes_present();

// *.off in fixtures/scenes, sorted by name (file names without the directory).
std::vector<std::string> fixture_files();
// The shared scenes the tests use (set in hidden_line/tests/CMakeLists.txt), and the subset that
// only runs under the `soak` label.
std::vector<std::string> shared_scene_files();
std::vector<std::string> soak_scene_files();

// front, back, top, bottom, left, right, iso (named_view).
std::vector<View> named_views();
View direction_view(const Vec3& direction, const Vec3& up = {0, 0, 1});

// Perspective views of a scene, from eyes placed by its bounding sphere (centre c, radius r):
// "persp_far" (3.1 r from c), "persp_close" and "persp_close2" (1.27 r and 1.13 r: strong
// perspective, nothing behind the near plane), "persp_near" (0.55 r from c, looking at c: the
// near plane cuts the scene) and "persp_inside" (an eye inside, looking past the centre).
inline constexpr int kPerspectiveViews = 5;
View perspective_view(const std::vector<Mesh>& meshes, int which);

// One mesh file as the only mesh of a scene; loaded once per process.
const std::vector<Mesh>& scene_meshes(const std::string& path);

// "cube.off" -> "cube"; characters other than letters and digits become '_'.
std::string test_name(const std::string& file);

struct Solved {
  XMap map;
  double sources_seconds = 0, sort_seconds = 0;
};

template <class K>
Solved solve(const std::vector<Mesh>& meshes, const View& view, const hidden_line::SourceOptions& options,
             const hidden_line::AreaSortOptions& sort = {});

extern template Solved solve<ExactKernel>(const std::vector<Mesh>&, const View&, const hidden_line::SourceOptions&,
                                  const hidden_line::AreaSortOptions&);
extern template Solved solve<EpickKernel>(const std::vector<Mesh>&, const View&, const hidden_line::SourceOptions&,
                                  const hidden_line::AreaSortOptions&);
extern template Solved solve<DoubleKernel>(const std::vector<Mesh>&, const View&, const hidden_line::SourceOptions&,
                                  const hidden_line::AreaSortOptions&);

// Faces of the sources, per mesh, as the multiset of their face lists (for the consolidation
// checks): each list restricted to the faces for which keep(mesh, face) holds, empty lists dropped.
template <class Keep>
std::vector<std::pair<std::uint32_t, std::vector<std::uint32_t>>> face_groups(const XMap& map, Keep keep) {
  std::vector<std::pair<std::uint32_t, std::vector<std::uint32_t>>> out;
  for (const auto& s : map.sources) {
    std::vector<std::uint32_t> faces;
    for (std::uint32_t f : s.faces)
      if (keep(s.mesh, f)) faces.push_back(f);
    std::sort(faces.begin(), faces.end());
    if (!faces.empty()) out.push_back({s.mesh, std::move(faces)});
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace hlr::hltest
