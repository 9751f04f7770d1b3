#include "batch_manifest.hpp"

#include "errors.hpp"
#include "scene_options.hpp"  // has_extension

#include <hlr/export/polygons.hpp>  // read_text_file, number_text

#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <map>
#include <vector>

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

// An output a command names with an option: by extension ("" for any), as check does with
// --diff OUT.png and --json OUT.json (then one file of each), or -o for every output.
struct OutputOption {
  const char* extension;
  const char* option;
};

// How a command's job is spelled in a manifest, and how that becomes its command line.
struct CommandShape {
  const char* name;
  const char* inputs_key;     // "meshes", or clip's "inputs" (polygon files)
  std::size_t inputs_count;   // 0: one or more
  const char* inputs_names;   // what they are, for a wrong count
  const char* view_option;    // "view" becomes it; nullptr: the command has no view
  bool threads;               // the command has --threads
  std::vector<OutputOption> outputs;
  std::size_t outputs_count;  // 0: one or more
  std::vector<const char*> output_options;  // the options that name outputs: refused in "options"
};

const std::vector<CommandShape>& command_shapes() {
  static const std::vector<CommandShape> shapes = {
      {"draw", "meshes", 0, "", "--view", true, {{"", "-o"}}, 0, {"-o", "--output"}},
      {"sheet", "meshes", 0, "", "--views", true, {{"", "-o"}}, 0, {"-o", "--output"}},
      {"surfaces", "meshes", 0, "", "--view", true, {{"", "-o"}}, 0, {"-o", "--output"}},
      {"check", "meshes", 0, "", "--view", true, {{".png", "--diff"}, {".json", "--json"}}, 0, {"--diff", "--json"}},
      {"shadows", "meshes", 0, "", nullptr, true, {{"", "-o"}}, 0, {"-o", "--output"}},
      {"mesh", "meshes", 0, "", nullptr, false, {{"", "-o"}}, 1, {"-o", "--output"}},
      {"clip", "inputs", 2, "SUBJECT.json and CLIP.json", nullptr, false, {{"", "-o"}}, 1, {"-o", "--output"}},
  };
  return shapes;
}

// "draw, sheet, surfaces, check, shadows, mesh or clip"
std::string command_list() {
  std::string list;
  const auto& shapes = command_shapes();
  for (std::size_t i = 0; i < shapes.size(); ++i)
    list += (i == 0 ? "" : i + 1 == shapes.size() ? " or " : ", ") + std::string(shapes[i].name);
  return list;
}

// The keys a job of `shape` has, in the order the documentation gives them.
std::vector<std::string> job_keys(const CommandShape& shape) {
  std::vector<std::string> keys = {"command", shape.inputs_key};
  if (shape.view_option) keys.push_back("view");
  keys.insert(keys.end(), {"options", "outputs"});
  return keys;
}

// Whether a command-line word sets `option`: "--threads" (its value follows) or "--threads=2".
bool sets_option(const std::string& word, const std::string& option) {
  return word == option || (option.rfind("--", 0) == 0 && word.rfind(option + "=", 0) == 0);
}

std::string paths(std::size_t n) { return std::to_string(n) + (n == 1 ? " path" : " paths"); }

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

  // strings(), and exactly `count` of them when count is not 0.
  std::vector<std::string> paths_at(const json& job, const std::string& where, const char* key, std::size_t count,
                                    const std::string& names) const {
    std::vector<std::string> out = strings(job, where, key, false);
    if (count != 0 && out.size() != count)
      fail(where + ": \"" + key + "\" has " + paths(out.size()) + ", expected " + std::to_string(count) +
           (names.empty() ? "" : " (" + names + ")"));
    return out;
  }

  const CommandShape& command(const json& entry, const std::string& where) const {
    const auto command = entry.find("command");
    if (command == entry.end()) fail(where + ": \"command\" is missing");
    if (!command->is_string()) fail(where + ": \"command\" is " + type_name(*command) + ", expected a string");
    const std::string name = command->get<std::string>();
    for (const CommandShape& shape : command_shapes())
      if (name == shape.name) return shape;
    fail(where + ": unknown command \"" + name + "\" (a job is " + command_list() + ")");
  }

  // Every key is one the job's command has; a misspelt one would be silently left out.
  void check_keys(const json& entry, const std::string& where, const CommandShape& shape) const {
    const std::vector<std::string> keys = job_keys(shape);
    for (const auto& [key, value] : entry.items()) {
      if (std::find(keys.begin(), keys.end(), key) != keys.end()) continue;
      if (key == "meshes" || key == "inputs")  // the other commands' inputs
        fail(where + ": a " + shape.name + " job reads \"" + shape.inputs_key + "\"" +
             (shape.inputs_count ? std::string(" (") + shape.inputs_names + ")" : "") + ", not \"" + key + "\"");
      std::string list;
      for (std::size_t i = 0; i < keys.size(); ++i) list += (i == 0 ? "" : i + 1 == keys.size() ? " and " : ", ") + keys[i];
      fail(where + ": unknown key \"" + key + "\" (a " + shape.name + " job has " + list + ")");
    }
  }

  // The option that names `output` on the command line; check's by extension, one file each.
  const char* output_option(const std::string& where, const CommandShape& shape, const std::string& output,
                            std::vector<std::string>& named) const {
    for (std::size_t i = 0; i < shape.outputs.size(); ++i) {
      const OutputOption& o = shape.outputs[i];
      if (*o.extension == '\0') return o.option;
      if (!has_extension(output, o.extension)) continue;
      named.resize(shape.outputs.size());
      if (!named[i].empty())
        fail(where + ": outputs \"" + named[i] + "\" and \"" + output + "\" are both " + o.extension + " (" + o.option +
             "): a " + shape.name + " job writes one");
      named[i] = output;
      return o.option;
    }
    std::string kinds;
    for (std::size_t i = 0; i < shape.outputs.size(); ++i)
      kinds += std::string(i == 0 ? "" : " or ") + shape.outputs[i].extension + " (" + shape.outputs[i].option + ")";
    fail(where + ": output \"" + output + "\" is not " + kinds + ", what a " + shape.name + " job writes");
  }

  BatchJob job(const json& entry, std::size_t index) const {
    const std::string where = "job " + std::to_string(index);
    if (!entry.is_object()) fail(where + " is " + type_name(entry) + ", expected an object");
    const CommandShape& shape = command(entry, where);
    check_keys(entry, where, shape);

    BatchJob job;
    job.arguments.push_back(shape.name);
    for (auto& input : paths_at(entry, where, shape.inputs_key, shape.inputs_count, shape.inputs_names)) {
      job.input_arguments.push_back(job.arguments.size());
      job.arguments.push_back(std::move(input));
    }
    if (const auto view = entry.find("view"); view != entry.end()) {
      if (!view->is_string()) fail(where + ": \"view\" is " + type_name(*view) + ", expected a string");
      job.arguments.push_back(shape.view_option);
      job.arguments.push_back(view->get<std::string>());
    }
    job.takes_threads = shape.threads;
    job.takes_timeout = true;  // every command has --timeout
    for (auto& option : strings(entry, where, "options", true)) {
      // Outputs are named in "outputs", where the batch knows them (to make their folders, to keep
      // two jobs from writing one file, to report them).
      for (const char* named : shape.output_options)
        if (sets_option(option, named))
          fail(where + ": \"options\" name an output (" + option + "): list outputs in \"outputs\"");
      job.takes_threads &= !sets_option(option, "--threads");
      job.takes_timeout &= !sets_option(option, "--timeout");
      job.arguments.push_back(std::move(option));
    }
    std::vector<std::string> named;  // check's output of each extension
    for (auto& output : paths_at(entry, where, "outputs", shape.outputs_count, "")) {
      job.arguments.push_back(output_option(where, shape, output, named));
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

std::vector<std::string> job_command_line(const BatchJob& job, int threads, double job_timeout) {
  std::vector<std::string> arguments = job.arguments;
  if (threads > 0 && job.takes_threads) arguments.insert(arguments.end(), {"--threads", std::to_string(threads)});
  if (job_timeout > 0 && job.takes_timeout) arguments.insert(arguments.end(), {"--timeout", exporter::number_text(job_timeout)});
  return arguments;
}

}  // namespace hlr::app

