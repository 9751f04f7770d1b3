#include "batch_manifest.hpp"

#include "errors.hpp"

#include <hlr/export/polygons.hpp>

#include <nlohmann/json.hpp>

#include <filesystem>
#include <map>
#include <set>

namespace hlr::app {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

inline constexpr const char* kBatchFormat = "hlr-batch/1";

std::string type_name(const json& value) {
  switch (value.type()) {
    case json::value_t::object: return "an object";
    case json::value_t::array: return "an array";
    case json::value_t::string: return "a string";
    case json::value_t::boolean: return "a boolean";
    case json::value_t::null: return "null";
    default: return "a number";
  }
}

class ManifestReader {
 public:
  explicit ManifestReader(const std::string& path) : path_(path) {}

  [[noreturn]] void fail(const std::string& problem) const { throw UserError(path_, problem); }

  // An array of non-empty strings at `key` of `job`; empty allowed only when `optional`.
  std::vector<std::string> strings(const json& job, const std::string& where, const char* key, bool optional) const {
    std::vector<std::string> out;
    const auto it = job.find(key);
    if (it == job.end()) {
      if (optional) return out;
      fail(where + ": \"" + key + "\" is missing");
    }
    if (!it->is_array()) fail(where + ": \"" + key + "\" is " + type_name(*it) + ", expected an array of strings");
    if (it->empty() && !optional) fail(where + ": \"" + key + "\" is empty");
    for (std::size_t i = 0; i < it->size(); ++i) {
      const json& s = (*it)[i];
      if (!s.is_string())
        fail(where + ": \"" + key + "\" item " + std::to_string(i) + " is " + type_name(s) + ", expected a string");
      if (s.get<std::string>().empty() && std::string(key) != "options")
        fail(where + ": \"" + key + "\" item " + std::to_string(i) + " is an empty path");
      out.push_back(s.get<std::string>());
    }
    return out;
  }

  BatchJob job(const json& entry, std::size_t index) const {
    const std::string where = "job " + std::to_string(index);
    if (!entry.is_object()) fail(where + " is " + type_name(entry) + ", expected an object");
    static const std::set<std::string> keys = {"command", "meshes", "view", "options", "outputs"};
    for (const auto& [key, value] : entry.items())
      if (!keys.count(key)) fail(where + ": unknown key \"" + key + "\" (a job has command, meshes, view, options and outputs)");

    const auto command = entry.find("command");
    if (command == entry.end()) fail(where + ": \"command\" is missing");
    if (!command->is_string()) fail(where + ": \"command\" is " + type_name(*command) + ", expected a string");
    const std::string name = command->get<std::string>();
    if (name != "draw" && name != "sheet" && name != "surfaces")
      fail(where + ": unknown command \"" + name + "\" (a job is draw, sheet or surfaces)");

    BatchJob job;
    job.arguments.push_back(name);
    for (auto& mesh : strings(entry, where, "meshes", false)) {
      job.mesh_arguments.push_back(job.arguments.size());
      job.arguments.push_back(std::move(mesh));
    }
    if (const auto view = entry.find("view"); view != entry.end()) {
      if (!view->is_string()) fail(where + ": \"view\" is " + type_name(*view) + ", expected a string");
      job.arguments.push_back(name == "sheet" ? "--views" : "--view");
      job.arguments.push_back(view->get<std::string>());
    }
    for (auto& option : strings(entry, where, "options", true)) {
      // Outputs are named in "outputs", where the batch knows them (to make their folders, to keep
      // two jobs from writing one file, to report them).
      if (option == "-o" || option == "--output" || option.rfind("--output=", 0) == 0)
        fail(where + ": \"options\" name an output (" + option + "): list outputs in \"outputs\"");
      job.sets_threads |= option == "--threads" || option.rfind("--threads=", 0) == 0;
      job.arguments.push_back(std::move(option));
    }
    for (auto& output : strings(entry, where, "outputs", false)) {
      job.arguments.push_back("-o");
      job.output_arguments.push_back(job.arguments.size());
      job.arguments.push_back(std::move(output));
    }
    return job;
  }

 private:
  const std::string& path_;
};

}  // namespace

BatchManifest read_batch_manifest(const std::string& path) {
  const ManifestReader reader(path);
  const std::string text = exporter::read_text_file(path);
  if (text.find_first_not_of(" \t\r\n") == std::string::npos)
    reader.fail("file is empty, expected an hlr-batch/1 JSON document");
  json doc;
  try {
    doc = json::parse(text);
  } catch (const json::parse_error& e) {
    reader.fail("not valid JSON at byte " + std::to_string(e.byte) + " (expected an hlr-batch/1 document)");
  }
  if (!doc.is_object()) reader.fail("top level is " + type_name(doc) + ", expected an object");
  const auto format = doc.find("format");
  if (format == doc.end()) reader.fail("\"format\" is missing (expected \"" + std::string(kBatchFormat) + "\")");
  if (!format->is_string() || format->get<std::string>() != kBatchFormat)
    reader.fail("format is " + format->dump() + ", expected \"" + kBatchFormat + "\"");
  for (const auto& [key, value] : doc.items())
    if (key != "format" && key != "jobs") reader.fail("unknown key \"" + key + "\" (a manifest has format and jobs)");
  const auto jobs = doc.find("jobs");
  if (jobs == doc.end()) reader.fail("\"jobs\" is missing");
  if (!jobs->is_array()) reader.fail("\"jobs\" is " + type_name(*jobs) + ", expected an array");

  BatchManifest manifest;
  const fs::path folder = fs::path(path).parent_path();
  manifest.folder = folder.empty() ? "." : folder.string();
  std::map<fs::path, std::size_t> writers;  // every output, as the path it resolves to, and its job
  for (std::size_t i = 0; i < jobs->size(); ++i) {
    BatchJob job = reader.job((*jobs)[i], i);
    for (std::size_t a : job.output_arguments) {
      const std::string& output = job.arguments[a];
      const fs::path resolved = (fs::path(output).is_absolute() ? fs::path(output) : folder / output).lexically_normal();
      const auto [it, added] = writers.emplace(resolved, i);
      if (!added)
        reader.fail("job " + std::to_string(i) + ": output \"" + output + "\" is written by job " +
                    std::to_string(it->second) + " too");
    }
    manifest.jobs.push_back(std::move(job));
  }
  return manifest;
}

}  // namespace hlr::app
