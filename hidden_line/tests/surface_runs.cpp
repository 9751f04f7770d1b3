#include "surface_runs.hpp"

#include <cmath>
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <map>
#include <mutex>
#include <sstream>

namespace hlr::hltest {

namespace fs = std::filesystem;

std::string fixture_dir() { return HLR_SCENE_FIXTURES_DIR; }
std::string shared_scene_dir() { return HLR_SHARED_SCENES; }
bool shared_scenes_present() { return fs::is_directory(shared_scene_dir()); }

std::vector<std::string> fixture_files() {
  std::vector<std::string> out;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(fixture_dir(), ec))
    if (entry.path().extension() == ".off") out.push_back(entry.path().filename().string());
  std::sort(out.begin(), out.end());
  return out;
}

namespace {
std::vector<std::string> split_list(const std::string& list) {
  std::vector<std::string> out;
  std::stringstream in(list);
  std::string item;
  while (std::getline(in, item, ','))
    if (!item.empty()) out.push_back(item);
  return out;
}
}  // namespace

std::vector<std::string> shared_scene_files() { return split_list(HLR_HL_SCENES); }
std::vector<std::string> soak_scene_files() { return split_list(HLR_HL_SOAK_SCENES); }

std::vector<View> named_views() {
  std::vector<View> out;
  for (const char* name : {"front", "back", "top", "bottom", "left", "right", "iso"}) {
    View v;
    named_view(name, v);
    out.push_back(v);
  }
  return out;
}

View direction_view(const Vec3& direction, const Vec3& up) {
  View v;
  v.name = "custom";
  v.direction = direction;
  v.up = up;
  return v;
}

View perspective_view(const std::vector<Mesh>& meshes, int which) {
  double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
  for (const Mesh& m : meshes)
    for (const auto& v : m.vertices)
      for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], v[k]), hi[k] = std::max(hi[k], v[k]);
  double c[3], r2 = 0;
  for (int k = 0; k < 3; ++k) {
    c[k] = (lo[k] + hi[k]) / 2;
    r2 += (hi[k] - lo[k]) * (hi[k] - lo[k]) / 4;
  }
  const double r = std::max(std::sqrt(r2), 1e-3);
  static const char* names[kPerspectiveViews] = {"persp_far", "persp_close", "persp_close2", "persp_near", "persp_inside"};
  static const double along[kPerspectiveViews][3] = {
      {0.62, -0.71, 0.33}, {-0.53, -0.64, 0.56}, {0.28, 0.81, -0.51}, {0.62, -0.71, 0.33}, {-0.53, -0.64, 0.56}};
  static const double distance[kPerspectiveViews] = {3.1, 1.27, 1.13, 0.55, 0.17};
  View v;
  v.name = names[which];
  Vec3 eye, target;
  for (int k = 0; k < 3; ++k) {
    eye[k] = c[k] + distance[which] * r * along[which][k];
    // The eye inside looks away from the centre's far side, past it.
    target[k] = which == 4 ? c[k] - r * along[2][k] : c[k];
    v.direction[k] = target[k] - eye[k];
  }
  v.eye = eye;
  v.up = {0, 0, 1};
  return v;
}

const std::vector<Mesh>& scene_meshes(const std::string& path) {
  static std::mutex mutex;
  static std::map<std::string, std::vector<Mesh>> cache;
  std::lock_guard lock(mutex);
  auto it = cache.find(path);
  if (it == cache.end()) {
    ImportReport report;
    std::vector<Mesh> meshes{load_mesh(path, report)};
    it = cache.emplace(path, std::move(meshes)).first;
  }
  return it->second;
}

std::string test_name(const std::string& file) {
  std::string stem = fs::path(file).stem().string();
  for (char& c : stem)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return stem;
}

template <class K>
Solved solve(const std::vector<Mesh>& meshes, const View& view, const hidden_line::SourceOptions& options,
             const hidden_line::AreaSortOptions& sort) {
  using clock = std::chrono::steady_clock;
  Solved out;
  const ViewFrame<K> frame(view, meshes);
  auto t0 = clock::now();
  auto sources = hidden_line::build_sources<K>(meshes, frame, options);
  auto t1 = clock::now();
  auto map = hidden_line::area_sort<K>(sources, sort);
  auto t2 = clock::now();
  out.sources_seconds = std::chrono::duration<double>(t1 - t0).count();
  out.sort_seconds = std::chrono::duration<double>(t2 - t1).count();
  out.map = to_xmap<K>(sources, map);
  return out;
}

template Solved solve<ExactKernel>(const std::vector<Mesh>&, const View&, const hidden_line::SourceOptions&,
                           const hidden_line::AreaSortOptions&);
template Solved solve<EpickKernel>(const std::vector<Mesh>&, const View&, const hidden_line::SourceOptions&,
                           const hidden_line::AreaSortOptions&);
template Solved solve<DoubleKernel>(const std::vector<Mesh>&, const View&, const hidden_line::SourceOptions&,
                           const hidden_line::AreaSortOptions&);

}  // namespace hlr::hltest
