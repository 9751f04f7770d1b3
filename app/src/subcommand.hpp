// How main.cpp dispatches: every subcommand registers itself on the top-level CLI11 app and hands
// back the function that runs it once the command line is parsed.
#pragma once

#include <CLI/CLI.hpp>

#include <functional>
#include <string>

namespace hlr::app {

struct Subcommand {
  CLI::App* app = nullptr;   // the parsed subcommand, owned by the top-level app
  std::function<int()> run;  // returns the exit code; may throw UserError
};

// The --kernel option every computing subcommand has: exact (the default), epick or double.
inline void add_kernel_option(CLI::App& cmd, std::string& kernel) {
  cmd.add_option("--kernel", kernel,
                 "number model: exact (exact predicates and constructions, the default), epick (exact "
                 "predicates, constructions rounded to double) or double (plain floating point)")
      ->check(CLI::IsMember({"exact", "epick", "double"}))
      ->capture_default_str()
      ->type_name("KERNEL");
}

// One per subcommand file.
Subcommand add_clip_command(CLI::App& parent);
Subcommand add_surfaces_command(CLI::App& parent);
Subcommand add_shadows_command(CLI::App& parent);
Subcommand add_draw_command(CLI::App& parent);
Subcommand add_sheet_command(CLI::App& parent);
Subcommand add_frames_command(CLI::App& parent);
Subcommand add_check_command(CLI::App& parent);
Subcommand add_batch_command(CLI::App& parent);
Subcommand add_mesh_command(CLI::App& parent);

}  // namespace hlr::app
