// Runs the clipper on one case with kernel K and judges the result against the exact CGAL oracle.
// The template part (clip_harness.hpp) only calls the clipper and converts its output to exact
// polygons; the judging (clip_harness.cpp) is kernel-independent and exact.
#pragma once

#include <clip_conversions.hpp>
#include <oracle.hpp>
#include <polygon_generators.hpp>

#include <hlr/clipper/clipper.hpp>

#include <exception>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace hlr::testing {

enum class Verdict {
  pass,
  input_rejected,  // normalize_polygon refused an input that is_valid accepts
  clip_error,      // ClipError thrown
  exception,       // any other exception
  invalid_output,  // a contour not simple, wrong orientation, hole outside, bad line id, ...
  bad_provenance,  // an output edge is not on the input edge it names
  wrong_result,    // the output is not S ∩ C / S − C (cell oracle; CGAL's answer is reported too)
  bad_area,        // pieces of one list overlap, areas do not add up, or twice_area disagrees
};
const char* verdict_name(Verdict v);

struct Evaluation {
  Verdict verdict = Verdict::pass;
  std::string message;
  std::size_t inside_pieces = 0, outside_pieces = 0;
  // For inexact kernels: did the provenance hold only up to rounding? Was the symmetric difference
  // small enough to be explained by rounding the output vertices?
  bool provenance_rounded = false;
  bool xor_rounding_level = false;
  double xor_relative_area = 0;  // |xor(inside)| + |xor(outside)|, over |subject|
  // The output is right by the cell oracle, but CGAL's Boolean operations say otherwise (a CGAL
  // bug; `message` says what CGAL computed). Not a failure.
  bool oracle_disagreement = false;
  bool ok() const { return verdict == Verdict::pass; }
};

// A clipper result with exact coordinates (inexact kernels' doubles taken as they are).
struct ExactOutputPolygon {
  EPolygon polygon;
  std::vector<std::vector<clip::LineId>> lines;  // per contour: outer first, then the holes
  std::size_t point_counts_mismatch = 0;         // contours whose lines.size() != points.size()
  std::optional<EFT> kernel_twice_area;          // clip::twice_area, exact kernel only
};
struct ExactOutput {
  std::vector<ExactOutputPolygon> inside, outside;
  std::vector<std::pair<EPoint, EPoint>> lines;  // the line table
};

struct JudgeOptions {
  bool exact_kernel = true;  // provenance and areas must hold exactly
};

// Judges an output against the oracle: validity, provenance, CGAL equality, areas.
Evaluation judge(const RawPolygon& subject, const RawPolygon& clip, const ExactOutput& out, const JudgeOptions& options);

// Compares two results of the same subject (clip_list against clip_polygon): empty when they
// describe the same inside and outside sets with the same number of pieces.
std::optional<std::string> compare_results(const ExactOutput& a, const ExactOutput& b);

// Human-readable and machine-readable text of a case, for failure logs.
std::string describe_case(const RawPolygon& subject, const RawPolygon& clip);
std::string describe_output(const ExactOutput& out);

template <class K>
ExactOutputPolygon to_exact_output(const clip::Polygon<K>& p) {
  ExactOutputPolygon e;
  e.polygon = to_exact<K>(p);
  e.lines.push_back(p.outer.lines);
  e.point_counts_mismatch += p.outer.lines.size() != p.outer.points.size();
  for (const auto& h : p.holes) {
    e.lines.push_back(h.lines);
    e.point_counts_mismatch += h.lines.size() != h.points.size();
  }
  if constexpr (std::is_same_v<K, ExactKernel>) e.kernel_twice_area = clip::twice_area<K>(p);
  return e;
}

template <class K>
ExactOutput to_exact_output(const clip::ClipResult<K>& r, const clip::LineTable<K>& lines) {
  ExactOutput out;
  for (const auto& p : r.inside) out.inside.push_back(to_exact_output<K>(p));
  for (const auto& p : r.outside) out.outside.push_back(to_exact_output<K>(p));
  for (const auto& l : lines) out.lines.emplace_back(to_exact_point<K>(l.a), to_exact_point<K>(l.b));
  return out;
}

// Prepared inputs of one case on kernel K: subjects and clip share one line table, filled before
// the clip region is built.
template <class K>
struct PreparedCase {
  clip::LineTable<K> lines;
  std::vector<clip::Polygon<K>> subjects;
  clip::Polygon<K> clip;
  std::optional<std::string> defect;  // normalize_polygon's complaint, if any
};

template <class K>
void prepare_case(std::span<const RawPolygon> subjects, const RawPolygon& clip, PreparedCase<K>& pc) {
  pc.lines.clear();
  pc.subjects.assign(subjects.size(), {});
  for (std::size_t i = 0; i < subjects.size() && !pc.defect; ++i)
    if (auto d = to_clip_polygon<K>(subjects[i], pc.lines, pc.subjects[i])) pc.defect = "subject " + std::to_string(i) + ": " + *d;
  if (!pc.defect)
    if (auto d = to_clip_polygon<K>(clip, pc.lines, pc.clip)) pc.defect = "clip: " + *d;
}

// Clips subject against clip on kernel K and judges the result.
template <class K>
Evaluation evaluate(const RawPolygon& subject, const RawPolygon& clip, ExactOutput* output = nullptr) {
  Evaluation e;
  PreparedCase<K> pc;
  try {
    prepare_case<K>(std::span<const RawPolygon>(&subject, 1), clip, pc);
    if (pc.defect) {
      e.verdict = Verdict::input_rejected;
      e.message = "normalize_polygon rejected a valid input: " + *pc.defect;
      return e;
    }
    const clip::ClipRegion<K> region(pc.clip, pc.lines);
    const clip::ClipResult<K> result = clip::clip_polygon<K>(pc.subjects[0], region);
    ExactOutput out = to_exact_output<K>(result, pc.lines);
    JudgeOptions options;
    options.exact_kernel = std::is_same_v<K, ExactKernel>;
    e = judge(subject, clip, out, options);
    if (output) *output = std::move(out);
  } catch (const clip::ClipError& err) {
    e.verdict = Verdict::clip_error;
    e.message = std::string("ClipError: ") + err.what();
  } catch (const std::exception& err) {
    e.verdict = Verdict::exception;
    e.message = std::string("exception: ") + err.what();
  }
  return e;
}

// clip_list over several subjects against clip_polygon on each: empty when they agree.
template <class K>
std::optional<std::string> check_clip_list(std::span<const RawPolygon> subjects, const RawPolygon& clip,
                                           bool* identical = nullptr) {
  try {
    PreparedCase<K> pc;
    prepare_case<K>(subjects, clip, pc);
    if (pc.defect) return "normalize_polygon rejected a valid input: " + *pc.defect;
    const clip::ClipRegion<K> region(pc.clip, pc.lines);
    const std::vector<clip::ClipResult<K>> listed =
        clip::clip_list<K>(std::span<const clip::Polygon<K>>(pc.subjects), region);
    if (listed.size() != subjects.size())
      return "clip_list returned " + std::to_string(listed.size()) + " results for " + std::to_string(subjects.size()) +
             " subjects";
    bool all_identical = true;
    for (std::size_t i = 0; i < subjects.size(); ++i) {
      const clip::ClipResult<K> single = clip::clip_polygon<K>(pc.subjects[i], region);
      const ExactOutput a = to_exact_output<K>(listed[i], pc.lines), b = to_exact_output<K>(single, pc.lines);
      auto same_structure = [](const std::vector<ExactOutputPolygon>& x, const std::vector<ExactOutputPolygon>& y) {
        if (x.size() != y.size()) return false;
        for (std::size_t k = 0; k < x.size(); ++k) {
          if (x[k].lines != y[k].lines || x[k].polygon.outer != y[k].polygon.outer ||
              x[k].polygon.holes != y[k].polygon.holes)
            return false;
        }
        return true;
      };
      if (same_structure(a.inside, b.inside) && same_structure(a.outside, b.outside)) continue;
      all_identical = false;
      if (auto d = compare_results(a, b)) return "subject " + std::to_string(i) + ": clip_list and clip_polygon differ: " + *d;
    }
    if (identical) *identical = all_identical;
  } catch (const std::exception& err) {
    return std::string("exception: ") + err.what();
  }
  return std::nullopt;
}

}  // namespace hlr::testing
