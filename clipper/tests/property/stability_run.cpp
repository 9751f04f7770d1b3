// clipper_stability: how the clipper fares on inexact kernels (EpickKernel, DoubleKernel), with
// the exact kernel as the control. Not an assertion test: it counts, per kernel and input family,
// passes and each kind of failure, and prints a Markdown table (docs/STABILITY.md).
//
// Every case runs in a forked child with an alarm() timeout, so that a crash or an endless loop
// is counted, not fatal. Results are judged exactly (clip_harness.cpp): output coordinates are
// taken as exact numbers and compared with CGAL's Boolean operations on Epeck.
//
//   clipper_stability [--cases N] [--timeout SECONDS] [--seed S] [--examples N] [--inputs]
//                     [--families a,b,...] [--kernels exact,epick,double]
//
// --examples N prints the first N failures of each kind per kernel and family; --inputs adds
// their input polygons as hlr-polygons/1 JSON (subject, clip), ready for clipper_minimize.
//
// Exit status: 0 when the exact kernel (the control) passed every case, 1 otherwise.
#include "clip_cases.hpp"
#include "clip_harness.hpp"

#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <iostream>
#include <map>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

namespace hlr::testing {
namespace {

// ---- running one case in a child ----

enum Outcome {
  o_pass,
  o_wrong_rounding,  // xor non-empty, but no larger than rounding the output vertices explains
  o_wrong_gross,
  o_invalid,
  o_provenance,
  o_area,
  o_clip_error,
  o_exception,
  o_rejected,
  o_crash,
  o_timeout,
  o_count
};
const char* outcome_name(int o) {
  static const char* names[] = {"pass", "wrong (rounding)", "wrong (gross)", "invalid output", "bad provenance",
                                "bad area", "ClipError", "exception", "input rejected", "crash", "timeout"};
  return names[o];
}

struct ChildReport {
  int outcome = o_crash;
  int provenance_rounded = 0;
  int oracle_disagreement = 0;
  double xor_relative_area = 0;
  char message[400] = {0};
};

template <class K>
ChildReport run_here(const ClipCase& c) {
  ChildReport r;
  const Evaluation e = evaluate<K>(c.subject, c.clip);
  switch (e.verdict) {
    case Verdict::pass: r.outcome = o_pass; break;
    case Verdict::wrong_result: r.outcome = e.xor_rounding_level ? o_wrong_rounding : o_wrong_gross; break;
    case Verdict::invalid_output: r.outcome = o_invalid; break;
    case Verdict::bad_provenance: r.outcome = o_provenance; break;
    case Verdict::bad_area: r.outcome = o_area; break;
    case Verdict::clip_error: r.outcome = o_clip_error; break;
    case Verdict::exception: r.outcome = o_exception; break;
    case Verdict::input_rejected: r.outcome = o_rejected; break;
  }
  r.provenance_rounded = e.provenance_rounded;
  r.oracle_disagreement = e.oracle_disagreement;
  r.xor_relative_area = e.xor_relative_area;
  std::snprintf(r.message, sizeof r.message, "%s", e.message.c_str());
  return r;
}

ChildReport run_forked(KernelKind kernel, const ClipCase& c, unsigned timeout) {
  int fd[2];
  if (pipe(fd) != 0) {
    std::perror("pipe");
    std::exit(2);
  }
  std::cout.flush();
  const pid_t pid = fork();
  if (pid < 0) {
    std::perror("fork");
    std::exit(2);
  }
  if (pid == 0) {
    close(fd[0]);
    alarm(timeout);
    ChildReport r;
    switch (kernel) {
      case KernelKind::exact: r = run_here<ExactKernel>(c); break;
      case KernelKind::epick: r = run_here<EpickKernel>(c); break;
      case KernelKind::floating: r = run_here<DoubleKernel>(c); break;
    }
    const char* p = reinterpret_cast<const char*>(&r);
    std::size_t left = sizeof r;
    while (left > 0) {
      const ssize_t w = write(fd[1], p, left);
      if (w <= 0) break;
      p += w;
      left -= static_cast<std::size_t>(w);
    }
    _exit(0);
  }
  close(fd[1]);
  ChildReport r;
  char* p = reinterpret_cast<char*>(&r);
  std::size_t got = 0;
  while (got < sizeof r) {
    const ssize_t n = read(fd[0], p + got, sizeof r - got);
    if (n <= 0) break;
    got += static_cast<std::size_t>(n);
  }
  close(fd[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  if (WIFSIGNALED(status)) {
    ChildReport bad;
    bad.outcome = WTERMSIG(status) == SIGALRM ? o_timeout : o_crash;
    std::snprintf(bad.message, sizeof bad.message, "child killed by signal %d (%s)", WTERMSIG(status),
                  strsignal(WTERMSIG(status)));
    return bad;
  }
  if (got != sizeof r || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    ChildReport bad;
    bad.outcome = o_crash;
    std::snprintf(bad.message, sizeof bad.message, "child exited with status %d without a report",
                  WIFEXITED(status) ? WEXITSTATUS(status) : -1);
    return bad;
  }
  return r;
}

struct Tally {
  int counts[o_count] = {0};
  int cases = 0;
  int provenance_rounded = 0;
  int oracle_disagreement = 0;
  double worst_rounding_xor = 0;
  std::map<int, std::vector<std::string>> examples;  // per outcome
};

// A failure message with its numbers taken out, to group failures of one kind.
std::string failure_kind(const std::string& message) {
  std::string k;
  for (std::size_t i = 0; i < message.size() && k.size() < 120; ++i) {
    const char ch = message[i];
    if ((ch >= '0' && ch <= '9') || ch == '.' || ch == '-' || ch == '+' || ch == 'e') {
      if (ch == 'e' && !(i > 0 && message[i - 1] >= '0' && message[i - 1] <= '9')) {
        k += ch;
        continue;
      }
      if (k.empty() || k.back() != '#') k += '#';
      continue;
    }
    if (ch == ';' || ch == '(') break;
    k += ch;
  }
  return k;
}

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream in(s);
  std::string item;
  while (std::getline(in, item, ',')) out.push_back(item);
  return out;
}

int main_impl(int argc, char** argv) {
  int cases = 200;
  unsigned timeout = 20;
  std::uint64_t seed = 1;
  int examples = 1;
  bool inputs = false;
  std::vector<std::string> family_filter, kernel_names{"exact", "epick", "double"};
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) {
        std::cerr << a << " needs a value\n";
        std::exit(2);
      }
      return argv[++i];
    };
    if (a == "--cases") cases = std::stoi(value());
    else if (a == "--timeout") timeout = static_cast<unsigned>(std::stoul(value()));
    else if (a == "--seed") seed = std::stoull(value());
    else if (a == "--examples") examples = std::stoi(value());
    else if (a == "--inputs") inputs = true;
    else if (a == "--families") family_filter = split(value());
    else if (a == "--kernels") kernel_names = split(value());
    else {
      std::cerr << "usage: clipper_stability [--cases N] [--timeout S] [--seed S] [--examples N] [--inputs] "
                   "[--families a,b] [--kernels exact,epick,double]\n";
      return 2;
    }
  }
  std::vector<KernelKind> kernels;
  for (const auto& n : kernel_names) {
    KernelKind k;
    if (!parse_kernel_kind(n, k)) {
      std::cerr << "unknown kernel " << n << "\n";
      return 2;
    }
    kernels.push_back(k);
  }
  std::vector<Family> fams;
  for (auto& f : stability_families())
    if (family_filter.empty() || std::find(family_filter.begin(), family_filter.end(), f.name) != family_filter.end())
      fams.push_back(f);

  const auto start = std::chrono::steady_clock::now();
  std::map<std::pair<int, std::string>, Tally> tallies;  // (kernel, family)
  std::map<std::pair<int, std::string>, int> kinds;      // (kernel, kind of failure)
  for (std::size_t fi = 0; fi < fams.size(); ++fi) {
    const Family& f = fams[fi];
    Rng rng(seed * 1000003u + fi);
    for (int n = 0; n < cases; ++n) {
      // Draw until both polygons are valid inputs (the near-degenerate transforms can break them).
      ClipCase c = f.make(rng);
      for (int attempt = 0; attempt < 100 && !(is_valid(c.subject) && is_valid(c.clip)); ++attempt) c = f.make(rng);
      for (KernelKind k : kernels) {
        const ChildReport r = run_forked(k, c, timeout);
        Tally& t = tallies[{static_cast<int>(k), f.name}];
        ++t.cases;
        ++t.counts[r.outcome];
        t.provenance_rounded += r.provenance_rounded;
        t.oracle_disagreement += r.oracle_disagreement;
        if (r.outcome == o_wrong_rounding) t.worst_rounding_xor = std::max(t.worst_rounding_xor, r.xor_relative_area);
        if (r.outcome != o_pass) {
          ++kinds[{static_cast<int>(k), std::string(outcome_name(r.outcome)) + ": " + failure_kind(r.message)}];
          auto& ex = t.examples[r.outcome];
          if (static_cast<int>(ex.size()) < examples) {
            std::string m = r.message;
            if (m.size() > 300) m = m.substr(0, 300) + "...";
            if (inputs) m += "\n    input (subject, clip): " + to_json({c.subject, c.clip});
            ex.push_back(m);
          }
        }
      }
    }
    std::cerr << "family " << f.name << " done\n";
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  // The table.
  std::cout << "| kernel | family | cases |";
  for (int o = 0; o < o_count; ++o) std::cout << " " << outcome_name(o) << " |";
  std::cout << " failure rate | edges on their line only up to rounding | CGAL wrong |\n|---|---|---:|";
  for (int o = 0; o < o_count; ++o) std::cout << "---:|";
  std::cout << "---:|---:|---:|\n";
  bool control_ok = true;
  for (KernelKind k : kernels) {
    Tally total;
    for (const auto& f : fams) {
      const Tally& t = tallies[{static_cast<int>(k), f.name}];
      total.cases += t.cases;
      total.provenance_rounded += t.provenance_rounded;
      total.oracle_disagreement += t.oracle_disagreement;
      for (int o = 0; o < o_count; ++o) total.counts[o] += t.counts[o];
      auto row = [&](const char* family, const Tally& x) {
        std::cout << "| " << kernel_name(k) << " | " << family << " | " << x.cases << " |";
        for (int o = 0; o < o_count; ++o) std::cout << " " << x.counts[o] << " |";
        char rate[32];
        std::snprintf(rate, sizeof rate, "%.1f%%", x.cases ? 100.0 * (x.cases - x.counts[o_pass]) / x.cases : 0.0);
        std::cout << " " << rate << " | " << x.provenance_rounded << " | " << x.oracle_disagreement << " |\n";
      };
      row(f.name, t);
    }
    auto row_total = [&]() {
      std::cout << "| " << kernel_name(k) << " | **all** | " << total.cases << " |";
      for (int o = 0; o < o_count; ++o) std::cout << " " << total.counts[o] << " |";
      char rate[32];
      std::snprintf(rate, sizeof rate, "%.1f%%",
                    total.cases ? 100.0 * (total.cases - total.counts[o_pass]) / total.cases : 0.0);
      std::cout << " **" << rate << "** | " << total.provenance_rounded << " | " << total.oracle_disagreement << " |\n";
    };
    row_total();
    if (k == KernelKind::exact && total.counts[o_pass] != total.cases) control_ok = false;
  }
  std::cout << "\nworst relative area of a rounding-level symmetric difference:\n";
  for (KernelKind k : kernels)
    for (const auto& f : fams) {
      const Tally& t = tallies[{static_cast<int>(k), f.name}];
      if (t.counts[o_wrong_rounding]) std::cout << "  " << kernel_name(k) << " / " << f.name << ": " << t.worst_rounding_xor << "\n";
    }
  std::cout << "\nkinds of failure (all families):\n\n| kernel | failure | cases |\n|---|---|---:|\n";
  for (const auto& [key, count] : kinds)
    std::cout << "| " << kernel_name(static_cast<KernelKind>(key.first)) << " | " << key.second << " | " << count << " |\n";
  if (examples > 0) {
    std::cout << "\nexamples (first " << examples << " of each outcome per kernel and family):\n";
    for (KernelKind k : kernels)
      for (const auto& f : fams)
        for (const auto& [outcome, list] : tallies[{static_cast<int>(k), f.name}].examples)
          for (const auto& ex : list)
            std::cout << "- " << kernel_name(k) << " / " << f.name << " / " << outcome_name(outcome) << ": " << ex << "\n";
  }
  std::cout << "\nfamilies:\n";
  for (const auto& f : fams) std::cout << "- " << f.name << ": " << f.what << "\n";
  std::printf("\n%d cases per family, %zu families, %zu kernels, seed %llu, %.1f s\n", cases, fams.size(),
              kernels.size(), static_cast<unsigned long long>(seed), seconds);
  if (!control_ok) std::cout << "CONTROL FAILED: the exact kernel did not pass every case\n";
  return control_ok ? 0 : 1;
}

}  // namespace
}  // namespace hlr::testing

int main(int argc, char** argv) { return hlr::testing::main_impl(argc, argv); }
