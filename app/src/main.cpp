// hlr: the command-line program. A dispatcher: every subcommand lives in its own file
// (clip_command.cpp, ...) and registers itself through subcommand.hpp.
//
// Exit codes: 0 success, 1 bad input or unwritable output (one line on stderr, "hlr: FILE: problem"),
// 2 bad command line, 3 internal error (a broken promise of the engine), 124 --timeout, 128 + N
// stopped by signal N (interrupt.hpp).
#include "errors.hpp"
#include "interrupt.hpp"
#include "program_allocator.hpp"
#include "program_code.hpp"
#include "subcommand.hpp"

#include <hlr/kernel/kernel.hpp>
#include <hlr/kernel/scene.hpp>

#include <CLI/CLI.hpp>

#include <csignal>
#include <cstdio>
#include <iostream>
#include <new>
#include <string>
#include <vector>

#ifndef HLR_VERSION
#define HLR_VERSION "unknown"
#endif

namespace {

// Messages are one line: a file name or a library's message must not break that.
std::string one_line(std::string text) {
  for (char& c : text)
    if (c == '\n' || c == '\r') c = ' ';
  return text;
}

int report(const std::string& message) {
  std::cerr << "hlr: " << one_line(message) << std::endl;
  return hlr::app::kExitInputError;
}

// With HLR_PREDICATE_STATS set: one line per predicate family of the exact kernel, how many
// decisions took no arithmetic, intervals, exact arithmetic on doubles, or exact rational
// arithmetic (bench/predicates reads them).
void print_predicate_stats() {
  using hlr::PredicateStats;
  if (!PredicateStats::enabled) return;
  const char* families[] = {"orientation", "comparison", "sign"};
  for (int f = 0; f < int(hlr::PredicateFamily::count); ++f) {
    const auto& c = PredicateStats::counts[f];
    std::cerr << "hlr: predicates " << families[f] << ": identity " << c[0].load() << ", interval " << c[1].load()
              << ", doubles " << c[2].load() << ", exact " << c[3].load() << "\n";
  }
}

}  // namespace

// The one line of a run stopped by a signal or by --timeout, and its exit code.
int report_stop() {
  using namespace hlr::app;
  const std::string stage = current_stage();
  const std::string where = stage.empty() ? "" : " while " + stage;
  if (const int signo = stop_signal()) {
    const char* name = signo == SIGINT ? "interrupted (SIGINT)" : signo == SIGTERM ? "terminated (SIGTERM)" : "hung up (SIGHUP)";
    std::cerr << "hlr: " << name << where << "; no file written" << std::endl;
    return 128 + signo;
  }
  char seconds[32];
  std::snprintf(seconds, sizeof seconds, "%g", timeout_reached());
  std::cerr << "hlr: --timeout " << seconds << ": the run stopped after " << seconds << " s" << where
            << "; no file written" << std::endl;
  return kExitTimeout;
}

int main(int argc, char** argv) {
  using namespace hlr::app;
  map_program_code();
  install_signal_handlers();
  keep_freed_pages();
  use_huge_pages();

  CLI::App app{"hlr: an exact hidden-line engine for CAD drawings.", "hlr"};
  app.set_version_flag("--version", "hlr " HLR_VERSION);
  app.require_subcommand(1);
  app.fallthrough(false);

  std::vector<Subcommand> commands;
  commands.push_back(add_draw_command(app));
  commands.push_back(add_sheet_command(app));
  commands.push_back(add_frames_command(app));
  commands.push_back(add_check_command(app));
  commands.push_back(add_surfaces_command(app));
  commands.push_back(add_shadows_command(app));
  commands.push_back(add_mesh_command(app));
  commands.push_back(add_clip_command(app));
  commands.push_back(add_batch_command(app));

  app.footer(
      "Examples:\n"
      "  hlr draw fixtures/scenes/l_bracket.off --view iso -o out/bracket.svg -o out/bracket.dxf\n"
      "  hlr sheet fixtures/parts/flange.off --views front,top,right,iso -o out/flange.pdf\n"
      "  hlr frames fixtures/scenes/l_bracket.off --orbit 36 -o out/orbit/frame_%03d.svg\n"
      "  hlr surfaces fixtures/scenes/l_bracket.off --view iso -o out/bracket.svg\n"
      "  hlr shadows fixtures/shadows/box_on_ground.off --sun 1,2,-4 -o out/box_shadows.json\n"
      "  hlr draw part.step --view front --deflection 0.05 -o out/part.dxf\n"
      "  hlr mesh part.step -o out/part.off\n"
      "  hlr clip fixtures/clip/subject.json fixtures/clip/clip.json -o out/clip-result.json\n"
      "  hlr batch catalogue.json --jobs 4\n"
      "\n"
      "Run 'hlr SUBCOMMAND --help' for a subcommand's options; formats are in docs/FORMATS.md.\n"
      "Exit status: 0 success, 1 bad input or unwritable output, 2 bad command line, 3 internal error,\n"
      "124 --timeout reached, 128 + N stopped by signal N (130: SIGINT); a stopped run writes no file.");

  // The first word that is not an option names the subcommand (the top level has no option that
  // takes a value). CLI11 would call an unknown one an unexpected argument, or say that a
  // subcommand is required: name it, and the ones there are.
  std::string expected;
  for (std::size_t i = 0; i < commands.size(); ++i)
    expected += (i == 0 ? "" : i + 1 == commands.size() ? " or " : ", ") + commands[i].app->get_name();
  for (int i = 1; i < argc; ++i) {
    const std::string word = argv[i];
    if (!word.empty() && word[0] == '-') continue;
    bool known = false;
    for (const auto& command : commands) known |= command.app->get_name() == word;
    if (known) break;
    std::cerr << "hlr: unknown subcommand '" << one_line(word) << "' (expected " << expected
              << "; see 'hlr --help')" << std::endl;
    return kExitUsage;
  }
  if (argc == 1) {
    std::cerr << "hlr: a subcommand is required (" << expected << "; see 'hlr --help')" << std::endl;
    return kExitUsage;
  }

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help, --version: print, exit 0
    std::string help = "hlr --help";
    for (const auto& command : commands)
      if (command.app->parsed()) help = "hlr " + command.app->get_name() + " --help";
    std::cerr << "hlr: " << one_line(e.what()) << " (see '" << help << "')" << std::endl;
    return kExitUsage;
  }

  for (const auto& command : commands) {
    if (!command.app->parsed()) continue;
    try {
      const JobScope job;  // from here a signal stops the work through the library's stop flag
      const int status = command.run();
      print_predicate_stats();
      return status;
    } catch (const hlr::Cancelled&) {
      return report_stop();
    } catch (const UsageError& e) {
      std::cerr << "hlr: " << one_line(e.what()) << std::endl;
      return kExitUsage;
    } catch (const UserError& e) {
      return report(e.what());
    } catch (const hlr::ImportError& e) {
      return report(e.what());
    } catch (const std::bad_alloc&) {
      return report("out of memory");
    } catch (const std::exception& e) {
      std::cerr << "hlr: internal error: " << one_line(e.what()) << std::endl;
      return kExitContract;
    }
  }
  return kExitUsage;  // unreachable: require_subcommand(1)
}
