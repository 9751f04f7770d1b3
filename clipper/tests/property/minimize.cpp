// clipper_minimize: shrinks a failing clipper case to a small one that fails the same way.
//
//   clipper_minimize [--kernel exact|epick|double] [--same-message] [FILE]
//
// FILE (or standard input) holds hlr-polygons/1 JSON with two polygons, subject then clip (what a
// failing property test or clipper_stability prints). The case is shrunk greedily, keeping both
// polygons valid and the verdict unchanged: holes are dropped, vertices removed, coordinates
// replaced by simpler numbers (integers, halves, ...). Prints the minimal case as JSON and as C++.
#include "clip_harness.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <iostream>
#include <iterator>

namespace hlr::testing {
namespace {

RawContour read_contour(const nlohmann::json& j) {
  RawContour c;
  for (const auto& p : j) c.push_back({p.at(0).get<double>(), p.at(1).get<double>()});
  return c;
}

RawPolygon read_polygon(const nlohmann::json& j) {
  RawPolygon p;
  p.outer = read_contour(j.at("outer"));
  if (j.contains("holes"))
    for (const auto& h : j.at("holes")) p.holes.push_back(read_contour(h));
  return p;
}

struct Case {
  RawPolygon subject, clip;
  RawPolygon& get(int k) { return k == 0 ? subject : clip; }
};

template <class K>
int run_main(Case c, bool same_message) {
  const Evaluation first = evaluate<K>(c.subject, c.clip);
  if (first.ok()) {
    std::cerr << "the case passes; nothing to minimize\n";
    return 1;
  }
  std::cerr << "failure: " << verdict_name(first.verdict) << ": " << first.message << "\n";
  auto fails = [&](const Case& x) {
    if (!is_valid(x.subject) || !is_valid(x.clip)) return false;
    const Evaluation e = evaluate<K>(x.subject, x.clip);
    return e.verdict == first.verdict && (!same_message || e.message == first.message);
  };
  bool progress = true;
  while (progress) {
    progress = false;
    // Drop holes.
    for (int k = 0; k < 2; ++k)
      for (std::size_t h = 0; h < c.get(k).holes.size();) {
        Case t = c;
        t.get(k).holes.erase(t.get(k).holes.begin() + static_cast<long>(h));
        if (fails(t)) {
          c = std::move(t);
          progress = true;
        } else {
          ++h;
        }
      }
    // Remove vertices.
    for (int k = 0; k < 2; ++k)
      for (std::size_t ci = 0; ci <= c.get(k).holes.size(); ++ci)
        for (std::size_t i = 0;;) {
          RawContour& cont = ci == 0 ? c.get(k).outer : c.get(k).holes[ci - 1];
          if (i >= cont.size() || cont.size() <= 3) break;
          Case t = c;
          RawContour& tc = ci == 0 ? t.get(k).outer : t.get(k).holes[ci - 1];
          tc.erase(tc.begin() + static_cast<long>(i));
          if (fails(t)) {
            c = std::move(t);
            progress = true;
          } else {
            ++i;
          }
        }
    // Simpler coordinates: the nearest multiple of 2^-j, j = 0..8 (simplest first).
    for (int k = 0; k < 2; ++k)
      for (std::size_t ci = 0; ci <= c.get(k).holes.size(); ++ci) {
        const std::size_t n = (ci == 0 ? c.get(k).outer : c.get(k).holes[ci - 1]).size();
        for (std::size_t i = 0; i < n; ++i)
          for (int axis = 0; axis < 2; ++axis) {
            const double v = (ci == 0 ? c.get(k).outer : c.get(k).holes[ci - 1])[i][axis];
            for (int j = 0; j <= 8; ++j) {
              const double s = std::ldexp(1.0, j);
              const double r = std::round(v * s) / s;
              if (r == v) break;
              Case t = c;
              (ci == 0 ? t.get(k).outer : t.get(k).holes[ci - 1])[i][axis] = r;
              if (fails(t)) {
                c = std::move(t);
                progress = true;
                break;
              }
            }
          }
      }
  }
  ExactOutput out;
  const Evaluation last = evaluate<K>(c.subject, c.clip, &out);
  std::cout << "minimal case (" << c.subject.vertex_count() << " + " << c.clip.vertex_count()
            << " vertices): " << verdict_name(last.verdict) << ": " << last.message << "\n"
            << describe_case(c.subject, c.clip) << describe_output(out);
  return 0;
}

}  // namespace
}  // namespace hlr::testing

int main(int argc, char** argv) {
  using namespace hlr::testing;
  std::string kernel = "exact", file;
  bool same_message = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--kernel" && i + 1 < argc) kernel = argv[++i];
    else if (a == "--same-message") same_message = true;
    else file = a;
  }
  std::string text;
  if (file.empty()) {
    text.assign(std::istreambuf_iterator<char>(std::cin), {});
  } else {
    std::ifstream in(file);
    text.assign(std::istreambuf_iterator<char>(in), {});
  }
  const auto j = nlohmann::json::parse(text);
  const auto& polys = j.at("polygons");
  if (polys.size() != 2) {
    std::cerr << "need exactly two polygons: subject, clip\n";
    return 2;
  }
  Case c{read_polygon(polys[0]), read_polygon(polys[1])};
  hlr::KernelKind k;
  if (!hlr::parse_kernel_kind(kernel, k)) return 2;
  switch (k) {
    case hlr::KernelKind::exact: return run_main<hlr::ExactKernel>(c, same_message);
    case hlr::KernelKind::epick: return run_main<hlr::EpickKernel>(c, same_message);
    case hlr::KernelKind::floating: return run_main<hlr::DoubleKernel>(c, same_message);
  }
  return 2;
}
