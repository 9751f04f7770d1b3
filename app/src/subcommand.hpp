// How main.cpp dispatches: every subcommand registers itself on the top-level CLI11 app and hands
// back the function that runs it once the command line is parsed.
#pragma once

#include <CLI/CLI.hpp>

#include <functional>

namespace hlr::app {

struct Subcommand {
  CLI::App* app = nullptr;   // the parsed subcommand, owned by the top-level app
  std::function<int()> run;  // returns the exit code; may throw UserError
};

// One per subcommand file.
Subcommand add_clip_command(CLI::App& parent);
Subcommand add_surfaces_command(CLI::App& parent);

}  // namespace hlr::app
