// `hlr clip SUBJECT.json CLIP.json -o OUT.json [--exact] [--kernel exact|epick|double]`
#include "clip_run.hpp"
#include "errors.hpp"
#include "polygon_json.hpp"
#include "subcommand.hpp"

#include <iostream>
#include <memory>
#include <string>

namespace hlr::app {
namespace {

struct ClipOptions {
  std::string subject, clip, output;
  bool exact = false;
  std::string kernel = "exact";
};

int run(const ClipOptions& options) {
  ClipJob job;
  job.subject_path = options.subject;
  job.clip_path = options.clip;
  job.output_path = options.output;
  job.exact_output = options.exact;
  job.summary = &std::cout;
  job.subjects = read_polygons_file(options.subject);
  job.clips = read_polygons_file(options.clip);
  if (options.kernel == "epick") return run_clip_epick(job);
  if (options.kernel == "double") return run_clip_double(job);
  return run_clip_exact(job);
}

}  // namespace

Subcommand add_clip_command(CLI::App& parent) {
  auto options = std::make_shared<ClipOptions>();
  CLI::App* cmd = parent.add_subcommand(
      "clip",
      "Clip polygons with holes by polygons with holes, exactly (hlr-polygons/1 in, hlr-clip/1 out).");
  cmd->add_option("subject", options->subject, "hlr-polygons/1 file: the polygons to clip, each on its own")
      ->required()
      ->type_name("SUBJECT.json");
  cmd->add_option("clip", options->clip, "hlr-polygons/1 file: the clip region, the union of its polygons")
      ->required()
      ->type_name("CLIP.json");
  cmd->add_option("-o,--output", options->output, "hlr-clip/1 file to write (replaced atomically)")
      ->required()
      ->type_name("OUT.json");
  cmd->add_flag("--exact", options->exact,
                "also write every vertex as exact rationals: \"outer_exact\", \"holes_exact\" (\"p/q\" strings)");
  add_kernel_option(*cmd, options->kernel);
  cmd->footer(
      "Writes subject ∩ clip (\"inside\") and subject − clip (\"outside\"), each output edge tagged with\n"
      "the input edge it lies on, and prints the areas with the check area(inside) + area(outside) =\n"
      "area(subject) made in the kernel's own arithmetic.\n"
      "\n"
      "Example:\n"
      "  hlr clip fixtures/clip/subject.json fixtures/clip/clip.json -o out/clip-result.json --exact\n"
      "\n"
      "Input and output formats (hlr-polygons/1, hlr-clip/1): docs/FORMATS.md");
  return {cmd, [options] { return run(*options); }};
}

}  // namespace hlr::app
