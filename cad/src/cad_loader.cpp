// load_cad through hlr_cad_occ, the module that holds OpenCASCADE (occ_module.hpp), loaded on the
// first CAD file of the run and kept until the process ends.
#include "file_names.hpp"
#include "occ_module.hpp"

#include <hlr/cad/cad.hpp>
#include <hlr/kernel/scene_import.hpp>

#include <dlfcn.h>
#include <unistd.h>

#include <climits>
#include <cstdlib>
#include <mutex>

namespace hlr::cad {
namespace {

std::string executable_folder() {
  char buffer[PATH_MAX];
  const ssize_t n = readlink("/proc/self/exe", buffer, sizeof buffer - 1);
  if (n <= 0) return "";
  const std::string exe(buffer, static_cast<std::size_t>(n));
  return exe.substr(0, exe.find_last_of('/'));
}

// Where the module is looked for, in order: $HLR_CAD_MODULE; beside an installed program
// (bin/../lib/hlr/); the build tree's copy (HLR_CAD_MODULE_BUILD_PATH), for the programs and tests
// that run from the build folder.
std::vector<std::string> module_candidates() {
  std::vector<std::string> paths;
  if (const char* forced = std::getenv("HLR_CAD_MODULE"); forced && *forced) return {forced};
  if (const std::string folder = executable_folder(); !folder.empty())
    paths.push_back(folder + "/" HLR_CAD_MODULE_FROM_BINDIR);
  paths.push_back(HLR_CAD_MODULE_BUILD_PATH);
  return paths;
}

detail::ReadModelFunction* read_model_function(const std::string& path) {
  static std::once_flag once;
  static detail::ReadModelFunction* function = nullptr;
  static std::string failure;
  std::call_once(once, [] {
    for (const std::string& candidate : module_candidates()) {
      // RTLD_LOCAL: OpenCASCADE's symbols stay out of the program's scope.
      void* handle = dlopen(candidate.c_str(), RTLD_NOW | RTLD_LOCAL);
      if (!handle) {
        failure += (failure.empty() ? "" : "; ") + std::string(dlerror());
        continue;
      }
      function = reinterpret_cast<detail::ReadModelFunction*>(dlsym(handle, detail::kReadModelSymbol));
      if (function) return;
      failure += (failure.empty() ? "" : "; ") + candidate + " has no " + detail::kReadModelSymbol;
    }
  });
  if (!function)
    throw ImportError(path + ": CAD input needs hlr's OpenCASCADE module (hlr_cad_occ.so), which did not load: " +
                      failure);
  return function;
}

}  // namespace

bool is_cad_extension(const std::string& extension) {
  const std::string ext = detail::lower(extension);
  return ext == ".step" || ext == ".stp" || ext == ".iges" || ext == ".igs" || ext == ".brep";
}

std::vector<CadPart> load_cad(const std::string& path, const CadOptions& options) {
  std::vector<CadPart> parts;
  read_model_function(path)(path, options, parts);
  return parts;
}

Scene load_scene(const std::vector<std::string>& paths, const CadOptions& options) {
  Scene scene;
  for (const auto& path : paths) {
    if (is_cad_extension(detail::extension_of(path))) {
      for (CadPart& part : load_cad(path, options)) scene.add(std::move(part.mesh), part.report);
    } else {
      add_mesh_file(scene, path);
    }
  }
  return scene;
}

}  // namespace hlr::cad
