// The hidden-surface solution on the inexact kernels (Epick, double): the same invariant checks as
// the exact tests (surface_checks.hpp), over the fixtures and the shared scenes in the seven named
// views, with failures counted by kind instead of asserted. Output coordinates are taken as the
// exact numbers they are (doubles) and judged by the exact oracle on the exact view of the input.
// Prints Markdown tables (docs/STABILITY.md, "Hidden-surface solution on inexact kernels").
//
//   hidden_line_stability [--kernels epick,double[,exact]] [--no-scenes] [--soak] [--smoke]
//                         [--region-max N]
//
// --smoke: one fixture in two views, for CTest; exits non-zero only if the exact control fails.
// Region checks (Polygon_set_2) run on maps with at most N sources (default 2000).
#include "surface_runs.hpp"

#include <hlr/clipper/clipper.hpp>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace hlr::hltest {
namespace {

struct Tally {
  std::size_t runs = 0, clean = 0, exactly_clean = 0, clip_errors = 0, other_errors = 0, nonfinite = 0, failed = 0;
  std::map<std::string, std::size_t> failure_runs;   // kind -> runs with at least one
  std::map<std::string, std::size_t> failure_count;  // kind -> total count
  std::map<std::string, std::size_t> error_messages;  // exception text -> runs
  std::map<std::string, std::size_t> notes;           // rounding and ties, total count
  std::size_t fragments = 0, bad_fragments = 0;       // checked fragments, and those failing (c)/(d)
  double seconds = 0;
};

struct Job {
  std::string set;  // "fixtures" or the scene file
  std::string file;
  std::string path;
};

template <class K>
void run_one(const Job& job, const View& view, std::size_t region_max, Tally& tally, std::vector<std::string>& examples) {
  const auto& meshes = scene_meshes(job.path);
  ++tally.runs;
  const auto t0 = std::chrono::steady_clock::now();
  Solved solved;
  try {
    solved = solve<K>(meshes, view, {});
  } catch (const NonFiniteOutput& e) {
    ++tally.nonfinite;
    ++tally.error_messages[e.what()];
    return;
  } catch (const clip::ClipError& e) {
    ++tally.clip_errors;
    ++tally.error_messages[std::string("ClipError: ") + e.what()];
    if (examples.size() < 40) examples.push_back(job.file + " " + view.name + ": ClipError: " + e.what());
    return;
  } catch (const std::exception& e) {
    ++tally.other_errors;
    ++tally.error_messages[std::string("exception: ") + e.what()];
    if (examples.size() < 40) examples.push_back(job.file + " " + view.name + ": exception: " + e.what());
    return;
  }
  tally.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const SceneOracle oracle(meshes, view);
  CheckOptions options;
  options.exact = std::is_same_v<K, ExactKernel>;
  options.region_checks = solved.map.sources.size() <= region_max;
  options.max_messages = 2;
  CheckReport report;
  try {
    report = check_map(oracle, solved.map, options);
  } catch (const std::exception& e) {
    report.failures["checker exception"] = 1;
    report.messages.push_back(std::string("checker exception: ") + e.what());
  }
  tally.fragments += solved.map.visible.size() + solved.map.hidden.size();
  for (const auto& [kind, count] : report.failures) {
    ++tally.failure_runs[kind];
    tally.failure_count[kind] += count;
    if (kind.rfind("(c)", 0) == 0 || kind.rfind("(d)", 0) == 0 || kind == "interior point") tally.bad_fragments += count;
  }
  bool rounding = false;
  for (const auto& [kind, count] : report.notes) rounding = rounding || kind.rfind("rounding", 0) == 0;
  for (const auto& [kind, count] : report.notes) tally.notes[kind] += count;
  if (report.ok()) {
    ++tally.clean;
    if (!rounding) ++tally.exactly_clean;
  } else {
    ++tally.failed;
    if (examples.size() < 40 && !report.messages.empty())
      examples.push_back(job.file + " " + view.name + ": " + report.messages.front().substr(0, 400));
  }
}

int main_impl(int argc, char** argv) {
  std::vector<std::string> kernels{"epick", "double"};
  bool scenes = true, soak = false, smoke = false;
  std::size_t region_max = 2000;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    if (a == "--no-scenes") scenes = false;
    else if (a == "--soak") soak = true;
    else if (a == "--smoke") smoke = true;
    else if (a == "--region-max" && i + 1 < argc) region_max = std::stoul(argv[++i]);
    else if (a == "--kernels" && i + 1 < argc) {
      kernels.clear();
      std::stringstream in(argv[++i]);
      std::string k;
      while (std::getline(in, k, ',')) kernels.push_back(k);
    } else {
      std::fprintf(stderr, "usage: %s [--kernels epick,double[,exact]] [--no-scenes] [--soak] [--smoke] [--region-max N]\n",
                   argv[0]);
      return 2;
    }
  }
  std::vector<Job> jobs;
  std::vector<View> views = named_views();
  if (smoke) {
    jobs.push_back({"fixtures", "penetrating_boxes.off", fixture_dir() + "/penetrating_boxes.off"});
    views = {views[0], views[6]};
    kernels = {"exact", "epick", "double"};
  } else {
    for (const auto& f : fixture_files()) jobs.push_back({"fixtures", f, fixture_dir() + "/" + f});
    if (scenes && shared_scenes_present()) {
      auto files = shared_scene_files();
      if (soak)
        for (const auto& f : soak_scene_files()) files.push_back(f);
      for (const auto& f : files) jobs.push_back({f, f, shared_scene_dir() + "/" + f});
    } else if (scenes) {
      std::printf("(no shared scenes at %s)\n", shared_scene_dir().c_str());
    }
  }

  // tallies[kernel][set]
  std::map<std::string, std::map<std::string, Tally>> tallies;
  std::map<std::string, std::vector<std::string>> examples;
  std::vector<std::string> sets;
  for (const auto& job : jobs)
    if (sets.empty() || sets.back() != job.set) sets.push_back(job.set);
  for (const auto& kernel : kernels) {
    for (const auto& job : jobs) {
      for (const auto& view : views) {
        Tally& t = tallies[kernel][job.set];
        auto& ex = examples[kernel];
        if (kernel == "exact") run_one<ExactKernel>(job, view, region_max, t, ex);
        else if (kernel == "epick") run_one<EpickKernel>(job, view, region_max, t, ex);
        else if (kernel == "double") run_one<DoubleKernel>(job, view, region_max, t, ex);
        else {
          std::fprintf(stderr, "unknown kernel %s\n", kernel.c_str());
          return 2;
        }
      }
      std::fflush(stdout);
    }
  }

  std::printf("\n| kernel | meshes | runs (mesh x view) | all invariants hold | ... and exactly | ClipError | other exception | "
              "non-finite output | runs failing a check | fragments checked | fragments failing (c)/(d) | solve s |\n");
  std::printf("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  for (const auto& kernel : kernels) {
    Tally total;
    for (const auto& set : sets) {
      const Tally& t = tallies[kernel][set];
      std::printf("| %s | %s | %zu | %zu | %zu | %zu | %zu | %zu | %zu | %zu | %zu | %.2f |\n", kernel.c_str(), set.c_str(),
                  t.runs, t.clean, t.exactly_clean, t.clip_errors, t.other_errors, t.nonfinite, t.failed, t.fragments, t.bad_fragments,
                  t.seconds);
      total.runs += t.runs;
      total.clean += t.clean;
      total.exactly_clean += t.exactly_clean;
      total.clip_errors += t.clip_errors;
      total.other_errors += t.other_errors;
      total.nonfinite += t.nonfinite;
      total.failed += t.failed;
      total.fragments += t.fragments;
      total.bad_fragments += t.bad_fragments;
      total.seconds += t.seconds;
      for (const auto& [k, n] : t.failure_runs) total.failure_runs[k] += n;
      for (const auto& [k, n] : t.failure_count) total.failure_count[k] += n;
      for (const auto& [k, n] : t.error_messages) total.error_messages[k] += n;
      for (const auto& [k, n] : t.notes) total.notes[k] += n;
    }
    std::printf("| **%s** | **all** | **%zu** | **%zu** | **%zu** | **%zu** | **%zu** | **%zu** | **%zu** | **%zu** | **%zu** | **%.2f** |\n",
                kernel.c_str(), total.runs, total.clean, total.exactly_clean, total.clip_errors, total.other_errors, total.nonfinite,
                total.failed, total.fragments, total.bad_fragments, total.seconds);
    tallies[kernel]["*total"] = total;
  }
  std::printf("\nFailures by kind (runs with at least one / total count):\n\n| kernel | kind | runs | count |\n|---|---|---:|---:|\n");
  for (const auto& kernel : kernels) {
    const Tally& t = tallies[kernel]["*total"];
    for (const auto& [kind, runs] : t.failure_runs)
      std::printf("| %s | %s | %zu | %zu |\n", kernel.c_str(), kind.c_str(), runs, t.failure_count.at(kind));
  }
  std::printf("\nNot failures (total count): rounding = an area identity off by at most 1e-9 relative; ties = "
              "hidden fragments decided by a coplanar tie.\n\n| kernel | note | count |\n|---|---|---:|\n");
  for (const auto& kernel : kernels)
    for (const auto& [note, count] : tallies[kernel]["*total"].notes)
      std::printf("| %s | %s | %zu |\n", kernel.c_str(), note.c_str(), count);
  std::printf("\nExceptions (runs):\n\n| kernel | message | runs |\n|---|---|---:|\n");
  for (const auto& kernel : kernels)
    for (const auto& [message, runs] : tallies[kernel]["*total"].error_messages)
      std::printf("| %s | %s | %zu |\n", kernel.c_str(), message.c_str(), runs);
  std::printf("\nFirst examples:\n");
  for (const auto& kernel : kernels)
    for (const auto& e : examples[kernel]) std::printf("- %s: %s\n", kernel.c_str(), e.c_str());

  if (smoke) {
    const Tally& exact = tallies["exact"]["*total"];
    return exact.clean == exact.runs ? 0 : 1;
  }
  return 0;
}

}  // namespace
}  // namespace hlr::hltest

int main(int argc, char** argv) { return hlr::hltest::main_impl(argc, argv); }
