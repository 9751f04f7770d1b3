#include "surface_runs.hpp"

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
  const ViewFrame<K> frame(view);
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
