// `hlr clip SUBJECT.json CLIP.json -o OUT.json [--exact] [--kernel exact|epick|double]`
#include "atomic_file.hpp"
#include "errors.hpp"
#include "run_scope.hpp"
#include "scene_options.hpp"
#include "subcommand.hpp"

#include <hlr/export/polygons.hpp>

#include <iostream>
#include <memory>
#include <string>

namespace hlr::app {
namespace {

struct ClipOptions {
  std::string subject, clip, output;
  bool exact = false;
  std::string kernel = "exact";
  RunLimits limits;
};

std::string plural(std::size_t n, const char* one, const char* many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

int run(const ClipOptions& options) {
  RunScope run(options.limits);
  const auto subjects = exporter::read_polygons_file(options.subject);
  const auto clips = exporter::read_polygons_file(options.clip);
  exporter::ClipOptions job;
  parse_kernel_kind(options.kernel, job.kernel);
  job.subject_name = options.subject;
  job.clip_name = options.clip;
  job.exact_values = options.exact;
  job.stop = stop_token();
  // Fail early on an output that cannot be written, before the clipping work.
  AtomicFile output(options.output);
  run.stage("clipping " + plural(subjects.size(), "subject polygon", "subject polygons") + " by " +
                plural(clips.size(), "clip polygon", "clip polygons"));
  const exporter::ClipOutcome outcome = exporter::clip_polygons(subjects, clips, job);
  output.write(exporter::clip_json(outcome));
  output.commit();
  run.finish();

  using exporter::number_text;
  std::cout << "hlr clip: " << plural(outcome.subjects, "subject polygon", "subject polygons") << ", "
            << plural(outcome.clips, "clip polygon", "clip polygons") << ", kernel " << kernel_name(job.kernel) << "\n"
            << "inside: " << plural(outcome.inside.size(), "polygon", "polygons") << ", area "
            << number_text(outcome.inside_area) << "; outside: " << plural(outcome.outside.size(), "polygon", "polygons")
            << ", area " << number_text(outcome.outside_area) << "; subject area " << number_text(outcome.subject_area)
            << " (" << outcome.identity_text << ")\n"
            << "wrote " << options.output << "\n";
  std::cout.flush();
  if (!outcome.identity_holds && job.kernel == KernelKind::exact) {
    std::cerr << "hlr: " << options.subject << ": internal error: area(inside) + area(outside) != area(subject) for polygon "
              << outcome.identity_failure << " with the exact kernel (a clipper bug; the result was written for inspection)\n";
    return kExitContract;
  }
  return kExitOk;
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
  add_limit_options(*cmd, options->limits, /*faces=*/false);
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
