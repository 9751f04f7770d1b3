// End-to-end tests of `hlr clip` and `hlr surfaces`: the program is run as a user runs it, and its exit code, stdout,
// stderr and output file are checked. Results are checked exactly, with GMP rationals read from the
// output's "outer_exact" / "holes_exact" strings, not with the program's own arithmetic.
#include "cli_support.hpp"
#include "svg_reader.hpp"

#include <gmpxx.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <array>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <sys/stat.h>
#include <unistd.h>


namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const std::string kBinary = HLR_BINARY;
const fs::path kFixtures = HLR_CLIP_FIXTURES;

using namespace hlr::cli_test;

// ---- exact arithmetic on the output ---------------------------------------------------------------

using Q = mpq_class;
struct QPoint {
  Q x, y;
};
using QContour = std::vector<QPoint>;

bool is_rational_text(const std::string& s) {
  static const std::regex pattern("-?(0|[1-9][0-9]*)(/[1-9][0-9]*)?");
  return std::regex_match(s, pattern);
}

Q rational(const std::string& s) {
  Q q(s, 10);
  q.canonicalize();
  return q;
}

QContour exact_contour(const json& a) {
  QContour c;
  for (const auto& p : a) c.push_back({rational(p.at(0).get<std::string>()), rational(p.at(1).get<std::string>())});
  return c;
}

QContour double_contour(const json& a) {  // input coordinates are doubles, taken exactly
  QContour c;
  for (const auto& p : a) c.push_back({Q(p.at(0).get<double>()), Q(p.at(1).get<double>())});
  return c;
}

Q twice_signed_area(const QContour& c) {
  Q sum = 0;
  for (std::size_t i = 0; i < c.size(); ++i) {
    const QPoint& a = c[i];
    const QPoint& b = c[(i + 1) % c.size()];
    sum += a.x * b.y - a.y * b.x;
  }
  return sum;
}

Q cross(const QPoint& o, const QPoint& a, const QPoint& b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); }

// Does p lie on the closed segment ab?
bool on_segment(const QPoint& p, const QPoint& a, const QPoint& b) {
  if (cross(a, b, p) != 0) return false;
  Q dot = (p.x - a.x) * (b.x - a.x) + (p.y - a.y) * (b.y - a.y);
  Q len2 = (b.x - a.x) * (b.x - a.x) + (b.y - a.y) * (b.y - a.y);
  return dot >= 0 && dot <= len2;
}

// Input contours by [role][polygon][contour], contour 0 = outer, h + 1 = hole h.
using InputContours = std::vector<std::vector<QContour>>;

InputContours input_contours(const json& doc) {
  InputContours result;
  for (const auto& poly : doc.at("polygons")) {
    std::vector<QContour> contours{double_contour(poly.at("outer"))};
    if (poly.contains("holes"))
      for (const auto& h : poly.at("holes")) contours.push_back(double_contour(h));
    result.push_back(std::move(contours));
  }
  return result;
}

// Checks one output contour against its provenance and returns twice its signed area.
Q check_contour(const json& exact, const json& doubles, const json& edges, const InputContours& subject,
                const InputContours& clip, const std::string& where) {
  EXPECT_EQ(exact.size(), doubles.size()) << where;
  EXPECT_EQ(edges.size(), doubles.size()) << where;
  EXPECT_GE(doubles.size(), 3u) << where;
  for (const auto& p : exact) {
    EXPECT_TRUE(p.is_array() && p.size() == 2) << where;
    for (const auto& v : p) EXPECT_TRUE(v.is_string() && is_rational_text(v.get<std::string>())) << where << ": " << v;
  }
  QContour c = exact_contour(exact);
  for (std::size_t i = 0; i < c.size() && i < doubles.size(); ++i) {
    double x = doubles[i].at(0).get<double>(), y = doubles[i].at(1).get<double>();
    EXPECT_NEAR(x, c[i].x.get_d(), 1e-12 * (1 + std::abs(x))) << where << " vertex " << i;
    EXPECT_NEAR(y, c[i].y.get_d(), 1e-12 * (1 + std::abs(y))) << where << " vertex " << i;
    // No zero-length edges.
    const QPoint& next = c[(i + 1) % c.size()];
    EXPECT_FALSE(c[i].x == next.x && c[i].y == next.y) << where << " edge " << i << " has zero length";
  }
  for (std::size_t i = 0; i < c.size() && i < edges.size(); ++i) {
    const json& e = edges[i];
    EXPECT_TRUE(e.is_array() && e.size() == 4) << where << " edge " << i;
    if (!e.is_array() || e.size() != 4) continue;
    const std::string role = e[0].get<std::string>();
    EXPECT_TRUE(role == "subject" || role == "clip") << where;
    const InputContours& in = role == "subject" ? subject : clip;
    std::size_t p = e[1].get<std::size_t>(), k = e[2].get<std::size_t>(), n = e[3].get<std::size_t>();
    EXPECT_LT(p, in.size()) << where;
    if (p >= in.size()) continue;
    EXPECT_LT(k, in[p].size()) << where;
    if (k >= in[p].size()) continue;
    const QContour& source = in[p][k];
    EXPECT_LT(n, source.size()) << where;
    if (n >= source.size()) continue;
    const QPoint& a = source[n];
    const QPoint& b = source[(n + 1) % source.size()];
    EXPECT_TRUE(on_segment(c[i], a, b) && on_segment(c[(i + 1) % c.size()], a, b))
        << where << " edge " << i << " does not lie on input edge " << e;
  }
  return twice_signed_area(c);
}

// Checks every polygon of an --exact result; returns twice the total area of the list.
Q check_list(const json& list, const InputContours& subject, const InputContours& clip, const std::string& name) {
  Q total = 0;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const json& poly = list[i];
    const std::string where = name + " " + std::to_string(i);
    for (const char* key : {"subject", "outer", "holes", "outer_edges", "holes_edges", "outer_exact", "holes_exact"})
      EXPECT_TRUE(poly.contains(key)) << where << " lacks " << key;
    if (name == "inside") {
      EXPECT_TRUE(poly.contains("clip")) << where;
    }
    Q outer = check_contour(poly.at("outer_exact"), poly.at("outer"), poly.at("outer_edges"), subject, clip, where + " outer");
    EXPECT_GT(outer, 0) << where << ": outer contour is not counter-clockwise";
    Q area = outer;
    EXPECT_EQ(poly.at("holes").size(), poly.at("holes_exact").size()) << where;
    EXPECT_EQ(poly.at("holes").size(), poly.at("holes_edges").size()) << where;
    for (std::size_t h = 0; h < poly.at("holes_exact").size(); ++h) {
      Q hole = check_contour(poly.at("holes_exact")[h], poly.at("holes")[h], poly.at("holes_edges")[h], subject, clip,
                             where + " hole " + std::to_string(h));
      EXPECT_LT(hole, 0) << where << " hole " << h << " is not clockwise";
      area += hole;
    }
    EXPECT_GT(area, 0) << where << " has no area";
    total += area;
  }
  return total;
}

Q twice_input_area(const InputContours& polygons) {
  Q total = 0;
  for (const auto& poly : polygons) {
    total += abs(twice_signed_area(poly[0]));
    for (std::size_t h = 1; h < poly.size(); ++h) total -= abs(twice_signed_area(poly[h]));
  }
  return total;
}

// ---- the fixture ---------------------------------------------------------------------------------

class CliClip : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = make_temp_dir("hlr-cli-test", {"in", "out", "logs"});
    ASSERT_FALSE(dir_.empty());
  }
  void TearDown() override {
    std::error_code ec;
    for (const auto& e : fs::recursive_directory_iterator(dir_, ec))
      fs::permissions(e.path(), fs::perms::owner_all, fs::perm_options::add, ec);
    fs::remove_all(dir_, ec);
  }

  fs::path in(const std::string& name) const { return dir_ / "in" / name; }
  fs::path out(const std::string& name = "result.json") const { return dir_ / "out" / name; }

  fs::path write_input(const std::string& name, const std::string& text) const {
    spit(in(name), text);
    return in(name);
  }

  Outcome hlr(const std::vector<std::string>& args) const {
    std::vector<std::string> argv_strings{kBinary};
    argv_strings.insert(argv_strings.end(), args.begin(), args.end());
    return spawn(argv_strings);
  }

  // hlr with its stack limited to `kb` KiB (through the shell's ulimit).
  Outcome hlr_with_stack(int kb, const std::vector<std::string>& args) const {
    std::vector<std::string> argv_strings{"/bin/sh", "-c", "ulimit -s " + std::to_string(kb) + " && exec \"$0\" \"$@\"",
                                          kBinary};
    argv_strings.insert(argv_strings.end(), args.begin(), args.end());
    return spawn(argv_strings);
  }

  Outcome spawn(std::vector<std::string> argv_strings) const { return run_process(std::move(argv_strings), dir_ / "logs"); }

  Outcome clip(const fs::path& subject, const fs::path& clip, const std::vector<std::string>& extra = {}) const {
    std::vector<std::string> args{"clip", subject.string(), clip.string(), "-o", out().string()};
    args.insert(args.end(), extra.begin(), extra.end());
    return hlr(args);
  }

  // A failed run: exit code 1, one line on stderr "hlr: FILE: ..." that contains `needle`, and
  // nothing left in the output directory (no result, no temporary file).
  void expect_user_error(const Outcome& run, const fs::path& file, const std::string& needle) const {
    EXPECT_EQ(run.exit_code, 1) << run.err;
    EXPECT_EQ(count_lines(run.err), 1u) << "stderr: " << run.err;
    EXPECT_FALSE(run.err.empty() || run.err.back() != '\n') << run.err;
    const std::string prefix = "hlr: " + file.string() + ": ";
    EXPECT_EQ(run.err.rfind(prefix, 0), 0u) << "stderr: " << run.err << "expected prefix: " << prefix;
    EXPECT_NE(run.err.find(needle), std::string::npos) << "stderr: " << run.err << "expected: " << needle;
    EXPECT_TRUE(entries(dir_ / "out").empty()) << "left behind in the output directory: " << ::testing::PrintToString(entries(dir_ / "out"));
  }

  // The bad subject as the subject and as the clip: both must name it.
  void expect_bad_input(const std::string& text, const std::string& needle) const {
    const fs::path bad = write_input("bad.json", text);
    SCOPED_TRACE(text);
    {
      SCOPED_TRACE("as subject");
      expect_user_error(clip(bad, kFixtures / "clip.json"), bad, needle);
    }
    {
      SCOPED_TRACE("as clip");
      expect_user_error(clip(kFixtures / "subject.json", bad), bad, needle);
    }
  }

  fs::path dir_;
};

std::string polygons(const std::string& body) { return R"({"format": "hlr-polygons/1", "polygons": [)" + body + "]}"; }

// ---- the bundled sample ----------------------------------------------------------------------------

TEST_F(CliClip, SampleSucceedsAndTheResultIsExactlyRight) {
  Outcome run = clip(kFixtures / "subject.json", kFixtures / "clip.json", {"--exact"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.err, "");
  EXPECT_NE(run.out.find("inside: "), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("outside: "), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("(exact identity holds)"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("wrote " + out().string()), std::string::npos) << run.out;
  EXPECT_EQ(entries(dir_ / "out"), std::vector<std::string>{"result.json"});

  json result = json::parse(slurp(out()));
  EXPECT_EQ(result.at("format"), "hlr-clip/1");
  EXPECT_EQ(result.at("kernel"), "exact");
  ASSERT_TRUE(result.at("inside").is_array());
  ASSERT_TRUE(result.at("outside").is_array());
  EXPECT_FALSE(result.at("inside").empty());
  EXPECT_FALSE(result.at("outside").empty());

  InputContours subject = input_contours(json::parse(slurp(kFixtures / "subject.json")));
  InputContours clip_region = input_contours(json::parse(slurp(kFixtures / "clip.json")));
  Q inside = check_list(result.at("inside"), subject, clip_region, "inside");
  Q outside = check_list(result.at("outside"), subject, clip_region, "outside");
  EXPECT_EQ(inside + outside, twice_input_area(subject)) << "area(inside) + area(outside) != area(subject)";

  const json& stats = result.at("stats");
  EXPECT_EQ(stats.at("area_identity"), true);
  EXPECT_EQ(rational(stats.at("inside_area_exact").get<std::string>()), inside / 2);
  EXPECT_EQ(rational(stats.at("outside_area_exact").get<std::string>()), outside / 2);
  EXPECT_EQ(stats.at("inside_polygons"), result.at("inside").size());
  EXPECT_EQ(stats.at("outside_polygons"), result.at("outside").size());
}

TEST_F(CliClip, SampleExercisesHolesAndRationalVertices) {
  // The sample is meant to show the interesting cases: an output hole, and a vertex that is not a
  // double (an intersection of a slanted clip edge with a hole edge).
  Outcome run = clip(kFixtures / "subject.json", kFixtures / "clip.json", {"--exact"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  json result = json::parse(slurp(out()));
  bool any_hole = false, any_fraction = false, any_clip_edge = false, any_subject_edge = false;
  for (const char* list : {"inside", "outside"})
    for (const auto& poly : result.at(list)) {
      any_hole |= !poly.at("holes").empty();
      for (const auto& p : poly.at("outer_exact"))
        for (const auto& v : p) any_fraction |= v.get<std::string>().find('/') != std::string::npos;
      for (const auto& e : poly.at("outer_edges")) {
        any_clip_edge |= e.at(0) == "clip";
        any_subject_edge |= e.at(0) == "subject";
      }
    }
  EXPECT_TRUE(any_hole);
  EXPECT_TRUE(any_fraction);
  EXPECT_TRUE(any_clip_edge);
  EXPECT_TRUE(any_subject_edge);
}

TEST_F(CliClip, WithoutExactThereAreNoExactFields) {
  Outcome run = clip(kFixtures / "subject.json", kFixtures / "clip.json");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  json result = json::parse(slurp(out()));
  EXPECT_EQ(result.at("kernel"), "exact");  // the default
  for (const char* list : {"inside", "outside"})
    for (const auto& poly : result.at(list)) {
      EXPECT_FALSE(poly.contains("outer_exact"));
      EXPECT_FALSE(poly.contains("holes_exact"));
      EXPECT_EQ(poly.at("outer_edges").size(), poly.at("outer").size());
    }
}

TEST_F(CliClip, EveryKernelRunsTheSample) {
  for (const std::string kernel : {"exact", "epick", "double"}) {
    SCOPED_TRACE(kernel);
    Outcome run = clip(kFixtures / "subject.json", kFixtures / "clip.json", {"--kernel", kernel, "--exact"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_NE(run.out.find("subject area"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("kernel " + kernel), std::string::npos) << run.out;
    json result = json::parse(slurp(out()));
    EXPECT_EQ(result.at("format"), "hlr-clip/1");
    EXPECT_EQ(result.at("kernel"), kernel);
    EXPECT_FALSE(result.at("inside").empty());
    EXPECT_FALSE(result.at("outside").empty());
    for (const char* list : {"inside", "outside"})
      for (const auto& poly : result.at(list))
        for (const auto& p : poly.at("outer_exact"))
          for (const auto& v : p) EXPECT_TRUE(is_rational_text(v.get<std::string>())) << v;
    EXPECT_EQ(entries(dir_ / "out"), std::vector<std::string>{"result.json"});
  }
}

TEST_F(CliClip, SeveralClipPolygonsActAsTheirUnion) {
  // Subject [0,4]^2; clip polygons [1,3]^2 and [2,5]^2 overlap. Inside = subject ∩ union, area 7.
  const fs::path subject = write_input("s.json", polygons(R"({"outer": [[0,0],[4,0],[4,4],[0,4]]})"));
  const fs::path clips = write_input("c.json", polygons(R"({"outer": [[1,1],[3,1],[3,3],[1,3]]},
                                                            {"outer": [[5,5],[2,5],[2,2],[5,2]]})"));
  Outcome run = clip(subject, clips, {"--exact"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("area 7;"), std::string::npos) << run.out;
  json result = json::parse(slurp(out()));
  InputContours s = input_contours(json::parse(slurp(subject)));
  InputContours c = input_contours(json::parse(slurp(clips)));
  Q inside = check_list(result.at("inside"), s, c, "inside");
  Q outside = check_list(result.at("outside"), s, c, "outside");
  EXPECT_EQ(inside, 14);
  EXPECT_EQ(outside, 18);
  bool from_first = false, from_second = false;
  for (const auto& poly : result.at("inside")) {
    EXPECT_EQ(poly.at("subject"), 0);
    from_first |= poly.at("clip") == 0;
    from_second |= poly.at("clip") == 1;
  }
  EXPECT_TRUE(from_first && from_second);
}

TEST_F(CliClip, EmptyClipLeavesEverySubjectOutside) {
  const fs::path empty = write_input("empty.json", polygons(""));
  Outcome run = clip(kFixtures / "subject.json", empty, {"--exact"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  json result = json::parse(slurp(out()));
  EXPECT_TRUE(result.at("inside").empty());
  ASSERT_EQ(result.at("outside").size(), 1u);
  EXPECT_EQ(result.at("outside")[0].at("holes").size(), 2u);
  InputContours subject = input_contours(json::parse(slurp(kFixtures / "subject.json")));
  EXPECT_EQ(check_list(result.at("outside"), subject, {}, "outside"), twice_input_area(subject));

  Outcome none = clip(empty, kFixtures / "clip.json");
  ASSERT_EQ(none.exit_code, 0) << none.err;
  json nothing = json::parse(slurp(out()));
  EXPECT_TRUE(nothing.at("inside").empty());
  EXPECT_TRUE(nothing.at("outside").empty());
}

TEST_F(CliClip, ReplacesAnExistingOutputFile) {
  spit(out(), "old");
  Outcome run = clip(kFixtures / "subject.json", kFixtures / "clip.json");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(json::parse(slurp(out())).at("format"), "hlr-clip/1");
  EXPECT_EQ(entries(dir_ / "out"), std::vector<std::string>{"result.json"});
}

TEST_F(CliClip, NearDegenerateInputNeedsTheExactKernel) {
  // Clip vertices one ulp away from subject vertices. The exact kernel gets it right; the inexact
  // kernels may fail (today they do, with a ClipError), and when they fail they must fail cleanly:
  // one line, exit 1, and no output or temporary file (the temporary file exists by then).
  const fs::path subject = kFixtures / "near-degenerate-subject.json", clip_file = kFixtures / "near-degenerate-clip.json";
  Outcome exact = clip(subject, clip_file, {"--exact"});
  ASSERT_EQ(exact.exit_code, 0) << exact.err;
  EXPECT_NE(exact.out.find("(exact identity holds)"), std::string::npos) << exact.out;
  json result = json::parse(slurp(out()));
  InputContours s = input_contours(json::parse(slurp(subject)));
  InputContours c = input_contours(json::parse(slurp(clip_file)));
  EXPECT_EQ(check_list(result.at("inside"), s, c, "inside") + check_list(result.at("outside"), s, c, "outside"),
            twice_input_area(s));
  fs::remove(out());

  for (const std::string kernel : {"epick", "double"}) {
    SCOPED_TRACE(kernel);
    Outcome run = clip(subject, clip_file, {"--kernel", kernel});
    if (run.exit_code == 0) {
      EXPECT_EQ(json::parse(slurp(out())).at("format"), "hlr-clip/1");
      fs::remove(out());
    } else {
      expect_user_error(run, subject, "failed with kernel " + kernel);
    }
  }
}

TEST_F(CliClip, ManyPiecesDoNotExhaustTheStack) {
  // A comb of 5000 teeth cut by a slanted band: 5000 inside and 5001 outside pieces, with
  // non-dyadic vertices. Summing their exact areas as one chain of lazy numbers needs a recursion
  // as deep as the chain when it is compared; with 512 KiB of stack that crashed.
  const int teeth = 5000;
  std::ostringstream comb;
  comb << R"({"format": "hlr-polygons/1", "polygons": [{"outer": [[0,0],[)" << teeth << ",0]";
  for (int i = teeth - 1; i >= 0; --i)
    comb << ",[" << i << ".75,1],[" << i << ".75,10],[" << i << ".25,10],[" << i << ".25,1]";
  comb << ",[0,1]]}]}";
  const fs::path subject = write_input("comb.json", comb.str());
  const fs::path band = write_input("band.json", polygons("{\"outer\": [[-1,4],[" + std::to_string(teeth + 1) + ",5],[" +
                                                         std::to_string(teeth + 1) + ",7],[-1,6]]}"));
  Outcome run = hlr_with_stack(512, {"clip", subject.string(), band.string(), "-o", out().string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("inside: 5000 polygons, area 5000; outside: 5001 polygons"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("(exact identity holds)"), std::string::npos) << run.out;
}

// ---- help and usage ---------------------------------------------------------------------------------

TEST_F(CliClip, HelpShowsAnExample) {
  for (const std::vector<std::string>& args : {std::vector<std::string>{"--help"}, std::vector<std::string>{"clip", "--help"}}) {
    Outcome run = hlr(args);
    EXPECT_EQ(run.exit_code, 0) << args.size();
    EXPECT_NE(run.out.find("Example"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("hlr clip fixtures/clip/subject.json fixtures/clip/clip.json -o"), std::string::npos) << run.out;
  }
  EXPECT_NE(hlr({"clip", "--help"}).out.find("--kernel"), std::string::npos);
}

TEST_F(CliClip, UsageErrorsExitWithTwo) {
  const std::string subject = (kFixtures / "subject.json").string(), clip_file = (kFixtures / "clip.json").string();
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{}, {"clip"}, {"clip", subject, clip_file}, {"clip", subject, "-o", out().string()},
        {"clip", subject, clip_file, "-o", out().string(), "--kernel", "quad"},
        {"clip", subject, clip_file, "-o", out().string(), "--bogus"}, {"frobnicate"}}) {
    Outcome run = hlr(args);
    EXPECT_EQ(run.exit_code, 2) << ::testing::PrintToString(args) << run.err;
    EXPECT_EQ(run.err.rfind("hlr: ", 0), 0u) << run.err;
    EXPECT_EQ(count_lines(run.err), 1u) << run.err;
    EXPECT_TRUE(entries(dir_ / "out").empty());
  }
}

// ---- bad input ----------------------------------------------------------------------------------------

TEST_F(CliClip, MalformedJson) {
  expect_bad_input(R"({"format": "hlr-polygons/1", "polygons": [}])", "not valid JSON at byte 43");
}

TEST_F(CliClip, TruncatedFile) {
  std::string sample = slurp(kFixtures / "subject.json");
  expect_bad_input(sample.substr(0, sample.size() / 2), "unexpected end of input");
}

TEST_F(CliClip, EmptyFile) {
  expect_bad_input("", "file is empty");
  expect_bad_input(" \n\t\n", "only white space");
}

TEST_F(CliClip, WrongFormatTag) {
  expect_bad_input(R"({"format": "hlr-clip/1", "polygons": []})", R"(format is "hlr-clip/1", expected "hlr-polygons/1")");
  expect_bad_input(R"({"polygons": []})", R"("format" is missing)");
  expect_bad_input(R"([1, 2])", "top level is an array, expected an object");
}

TEST_F(CliClip, MissingPolygons) {
  expect_bad_input(R"({"format": "hlr-polygons/1"})", R"("polygons" is missing)");
  expect_bad_input(R"({"format": "hlr-polygons/1", "polygons": {}})", R"("polygons" is an object, expected an array)");
  expect_bad_input(polygons(R"({"holes": []})"), R"(polygon 0 has no "outer" contour)");
}

TEST_F(CliClip, FewerThanThreeVertices) {
  expect_bad_input(polygons(R"({"outer": [[0,0],[1,0],[1,1]]}, {"outer": [[0,0],[1,0]]})"),
                   "polygon 1 outer contour has 2 distinct vertices, at least 3 are needed");
  expect_bad_input(polygons(R"({"outer": [[0,0],[4,0],[0,4]], "holes": [[[1,1],[2,1],[1,1],[2,1]]]})"),
                   "polygon 0 hole 0 contour has 2 distinct vertices");
}

TEST_F(CliClip, CoordinateIsNotANumber) {
  expect_bad_input(polygons(R"({"outer": [[0,0],["1",0],[1,1]]})"), "polygon 0 outer vertex 1: x is a string, expected a number");
  expect_bad_input(polygons(R"({"outer": [[0,0],[1,null],[1,1]]})"), "polygon 0 outer vertex 1: y is null, expected a number");
  expect_bad_input(polygons(R"({"outer": [[0,0],[1],[1,1]]})"), "polygon 0 outer vertex 1 is an array of 1 values, expected [x, y]");
}

TEST_F(CliClip, NonFiniteAndHugeCoordinates) {
  expect_bad_input(polygons(R"({"outer": [[0,0],[4,0],[0,4]], "holes": [[[1,1],[1e400,1],[1,2]]]})"),
                   "polygon 0 hole 0 vertex 1: x coordinate is not a finite number");
  expect_bad_input(polygons(R"({"outer": [[0,0],[4,0],[0,-1E+999]]})"), "polygon 0 outer vertex 2: y coordinate is not a finite number");
  expect_bad_input(polygons(R"({"outer": [[0,0],[1e101,0],[0,4]]})"), "polygon 0 outer vertex 1: x coordinate 1e+101 is out of range");
}

TEST_F(CliClip, SelfIntersectingContour) {
  // A bow-tie: edges 0 ((0,0)-(2,2)) and 2 ((2,0)-(0,2)) cross.
  expect_bad_input(polygons(R"({"outer": [[0,0],[4,0],[0,4]]}, {"outer": [[0,0],[2,2],[2,0],[0,2]]})"),
                   "polygon 1 outer contour edges 0 and 2 intersect");
}

TEST_F(CliClip, HoleOutsideTheOuterContour) {
  expect_bad_input(polygons(R"({"outer": [[0,0],[4,0],[4,4],[0,4]], "holes": [[[5,5],[6,5],[6,6]]]})"),
                   "polygon 0 hole 0 lies outside the outer contour");
}

TEST_F(CliClip, MissingInput) {
  const fs::path missing = in("missing.json");
  expect_user_error(clip(missing, kFixtures / "clip.json"), missing, "cannot open (No such file or directory)");
  expect_user_error(clip(kFixtures / "subject.json", missing), missing, "cannot open (No such file or directory)");
}

TEST_F(CliClip, InputIsADirectory) {
  expect_user_error(clip(dir_ / "in", kFixtures / "clip.json"), dir_ / "in", "cannot read (Is a directory)");
}

TEST_F(CliClip, UnreadableInput) {
  if (::geteuid() == 0) GTEST_SKIP() << "root reads files regardless of their permissions";
  const fs::path locked = write_input("locked.json", slurp(kFixtures / "subject.json"));
  fs::permissions(locked, fs::perms::none);
  expect_user_error(clip(locked, kFixtures / "clip.json"), locked, "cannot open (Permission denied)");
}

TEST_F(CliClip, OutputDirectoryDoesNotExist) {
  const fs::path target = dir_ / "out" / "no" / "such" / "dir.json";
  Outcome run = hlr({"clip", (kFixtures / "subject.json").string(), (kFixtures / "clip.json").string(), "-o", target.string()});
  expect_user_error(run, target, "cannot write (No such file or directory)");
}

TEST_F(CliClip, OutputIsADirectory) {
  fs::create_directories(dir_ / "target");
  const fs::path target = dir_ / "target";
  Outcome run = hlr({"clip", (kFixtures / "subject.json").string(), (kFixtures / "clip.json").string(), "-o", target.string()});
  expect_user_error(run, target, "cannot write (Is a directory)");
  EXPECT_TRUE(entries(target).empty());
  EXPECT_TRUE(entries(dir_).size() == 4u) << ::testing::PrintToString(entries(dir_));  // in, out, logs, target
}

TEST_F(CliClip, OutputDirectoryIsReadOnly) {
  if (::geteuid() == 0) GTEST_SKIP() << "root writes regardless of permissions";
  fs::permissions(dir_ / "out", fs::perms::owner_read | fs::perms::owner_exec);
  expect_user_error(clip(kFixtures / "subject.json", kFixtures / "clip.json"), out(), "cannot write (Permission denied)");
}

TEST_F(CliClip, FailedRunKeepsTheOldOutput) {
  spit(out(), "old");
  const fs::path bad = write_input("bad.json", "{");
  Outcome run = clip(bad, kFixtures / "clip.json");
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_EQ(slurp(out()), "old");
  EXPECT_EQ(entries(dir_ / "out"), std::vector<std::string>{"result.json"});
}

}  // namespace

// ---- hlr surfaces ---------------------------------------------------------------------------------
namespace {

const fs::path kScenes = HLR_SCENE_FIXTURES;
const fs::path kBundledParts = HLR_PART_FIXTURES;

class CliSurfaces : public CliClip {};

TEST_F(CliSurfaces, SolvesTheBundledBracketIntoJsonAndSvg) {
  const std::string mesh = (kScenes / "l_bracket.off").string();
  Outcome run = hlr({"surfaces", mesh, "--view", "iso", "-o", out("b.json").string(), "-o", out("b.svg").string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.err, "");
  const std::string text = slurp(out("b.json"));
  const json doc = json::parse(text);
  EXPECT_EQ(text, doc.dump(1) + "\n") << "written member by member, as one tree dumps";
  EXPECT_EQ(doc.at("format"), "hlr-surfaces/1");
  EXPECT_EQ(doc.at("view").at("name"), "iso");
  // The seconds are the stages' sum (each timed on its own clock), the write stage (this document
  // and the SVG) among them.
  const json& stages = doc.at("stats").at("stage_seconds");
  EXPECT_GT(stages.at("write").get<double>(), 0);
  EXPECT_NEAR(doc.at("stats").at("seconds").get<double>(),
              stages.at("read").get<double>() + stages.at("sources").get<double>() +
                  stages.at("sort").get<double>() + stages.at("write").get<double>(),
              1e-3);
  EXPECT_EQ(doc.at("input").at("files").at(0), mesh);
  EXPECT_GT(doc.at("visible").size(), 0u);
  for (const auto& h : doc.at("hidden")) EXPECT_GE(h.at("occluder").get<int>(), 0);
  EXPECT_GT(doc.at("stats").at("back_faces_removed").get<int>(), 0);
  const std::string svg = slurp(out("b.svg"));
  EXPECT_EQ(svg.rfind("<?xml", 0), 0u);
  EXPECT_NE(svg.find("</svg>"), std::string::npos);
  EXPECT_EQ(entries(dir_ / "out"), (std::vector<std::string>{"b.json", "b.svg"}));
}

TEST_F(CliSurfaces, OneThreadAndTwoWriteTheSameDocumentInChunks) {
  // A part large enough for its arrays to be written in many chunks (of 512 polygons or sources),
  // which two threads write side by side: the same document as one tree dumps, the timings aside.
  const fs::path mesh = fs::path(HLR_SHARED_SCENES) / "fandisk.off";
  if (!fs::exists(mesh)) GTEST_SKIP() << "no shared scenes at " << HLR_SHARED_SCENES;
  json docs[2];
  for (int k = 0; k < 2; ++k) {
    const std::string file = out("f" + std::to_string(k + 1) + ".json").string();
    Outcome run = hlr({"surfaces", mesh.string(), "--view", "iso", "--threads", std::to_string(k + 1), "-o", file});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const std::string text = slurp(file);
    docs[k] = json::parse(text);
    EXPECT_EQ(text, docs[k].dump(1) + "\n");
    EXPECT_GT(docs[k].at("hidden").size(), 2048u);
    EXPECT_GT(docs[k].at("sources").size(), 2048u);
    docs[k].at("stats").erase("seconds");
    docs[k].at("stats").erase("stage_seconds");
  }
  EXPECT_EQ(docs[0], docs[1]);
}

TEST_F(CliSurfaces, EveryNamedViewAndADirectionWork) {
  const std::string mesh = (kScenes / "cube.off").string();
  for (const char* view : {"front", "back", "top", "bottom", "left", "right", "iso"}) {
    Outcome run = hlr({"surfaces", mesh, "--view", view, "-o", out("c.json").string()});
    EXPECT_EQ(run.exit_code, 0) << view << ": " << run.err;
  }
  Outcome run = hlr({"surfaces", mesh, "--dir", "1,2,-3", "--up", "0,0,1", "--exact", "-o", out("c.json").string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const json doc = json::parse(slurp(out("c.json")));
  EXPECT_TRUE(is_rational_text(doc.at("visible").at(0).at("outer_exact").at(0).at(0).get<std::string>()));
  // With holes, hidden polygons and the exact values, the bytes are still what one tree dumps.
  const std::string part = (kBundledParts / "anchor.off").string();
  run = hlr({"surfaces", part, "--view", "top", "--exact", "-o", out("d.json").string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const std::string text = slurp(out("d.json"));
  const json anchor = json::parse(text);
  EXPECT_EQ(text, anchor.dump(1) + "\n");
  std::size_t holes = 0;
  for (const auto& p : anchor.at("visible")) holes += p.at("holes_exact").size();
  EXPECT_GT(holes, 0u);
  EXPECT_GT(anchor.at("hidden").size(), 0u);
}

TEST_F(CliSurfaces, BadViewsAreUsageErrors) {
  const std::string mesh = (kScenes / "cube.off").string();
  for (const std::vector<std::string>& view : {std::vector<std::string>{"--view", "sideways"},
                                                std::vector<std::string>{"--dir", "0,0,0"},
                                                std::vector<std::string>{"--dir", "0,0,1", "--up", "0,0,-2"}}) {
    std::vector<std::string> args{"surfaces", mesh, "-o", out("v.json").string()};
    args.insert(args.end(), view.begin(), view.end());
    Outcome run = hlr(args);
    EXPECT_EQ(run.exit_code, 2) << view.back();
    EXPECT_EQ(count_lines(run.err), 1u) << run.err;
    EXPECT_EQ(run.err.rfind("hlr: ", 0), 0u) << run.err;
    EXPECT_TRUE(entries(dir_ / "out").empty());
  }
}

TEST_F(CliSurfaces, BadMeshesAndOutputsGiveOneLineAndNoFile) {
  const std::string truncated = write_input("truncated.off", "OFF\n8 6 0\n0 0 0\n1 0 0\n").string();
  const std::string missing = in("missing.off").string();
  const std::string cube = (kScenes / "cube.off").string();
  struct Case {
    std::string mesh, output, named;
  };
  for (const Case& c : {Case{truncated, out("t.json").string(), truncated}, Case{missing, out("m.json").string(), missing},
                        Case{cube, out("x.txt").string(), out("x.txt").string()},
                        Case{cube, (dir_ / "no" / "dir" / "x.svg").string(), (dir_ / "no" / "dir" / "x.svg").string()}}) {
    // A good output beside the bad one: every output is opened before the solve, and a failed run
    // writes none of them.
    Outcome run = hlr({"surfaces", c.mesh, "-o", out("good.json").string(), "-o", c.output});
    EXPECT_EQ(run.exit_code, 1) << c.mesh << " -> " << c.output;
    EXPECT_EQ(count_lines(run.err), 1u) << run.err;
    EXPECT_EQ(run.err.rfind("hlr: " + c.named + ": ", 0), 0u) << run.err;
    EXPECT_TRUE(entries(dir_ / "out").empty()) << run.err;
  }
}

}  // namespace

// ---- hlr draw -------------------------------------------------------------------------------------
namespace {

class CliDraw : public CliClip {
 protected:
  // A failed draw of `mesh` into `output`: exit `code`, one line on stderr starting with `prefix`,
  // and nothing in the output directory.
  void expect_failure(const std::vector<std::string>& args, int code, const std::string& prefix) const {
    std::vector<std::string> all{"draw"};
    all.insert(all.end(), args.begin(), args.end());
    expect_failed_run(all, code, prefix);
  }
  // The same for any command line.
  void expect_failed_run(const std::vector<std::string>& all, int code, const std::string& prefix) const {
    Outcome run = hlr(all);
    SCOPED_TRACE(::testing::PrintToString(all));
    EXPECT_EQ(run.exit_code, code) << run.err;
    EXPECT_EQ(count_lines(run.err), 1u) << run.err;
    EXPECT_EQ(run.err.rfind(prefix, 0), 0u) << run.err;
    EXPECT_TRUE(entries(dir_ / "out").empty()) << run.err;
  }
  // An hlr-lines/1 document but for its timings.
  static json without_times(json doc) {
    doc.at("stats").erase("seconds");
    doc.at("stats").erase("stage_seconds");
    return doc;
  }
};

TEST_F(CliDraw, OneThreadAndTwoDrawTheSameBytes) {
  // Every fixture in two views: the SVG and DXF byte for byte, the JSON but for its timings.
  std::size_t files = 0;
  for (const auto& entry : fs::directory_iterator(kScenes)) {
    if (entry.path().extension() != ".off") continue;
    for (const char* view : {"iso", "front"}) {
      const std::string stem = entry.path().stem().string() + "_" + view;
      for (const char* threads : {"1", "2"}) {
        const std::string base = stem + "_" + threads;
        Outcome run = hlr({"draw", entry.path().string(), "--view", view, "--threads", threads, "-o",
                           out(base + ".svg").string(), "-o", out(base + ".dxf").string(), "-o", out(base + ".json").string()});
        ASSERT_EQ(run.exit_code, 0) << stem << ": " << run.err;
      }
      for (const char* ext : {".svg", ".dxf"})
        EXPECT_EQ(slurp(out(stem + "_1" + ext)), slurp(out(stem + "_2" + ext))) << stem << ext;
      EXPECT_EQ(without_times(json::parse(slurp(out(stem + "_1.json")))),
                without_times(json::parse(slurp(out(stem + "_2.json")))))
          << stem;
      ++files;
    }
  }
  EXPECT_GE(files, 40u);
}

TEST_F(CliDraw, ALargeDrawingTakesItsMemoryPathAndIsTheSameOnOneThreadAndTwo) {
  // 106,722 faces: past the 100,000 from which draw_command.cpp grows the heap in 4 KB pages,
  // hands freed pages back and frees the solution once drawn (program_allocator.hpp).
  const fs::path grid = write_bumpy_grid(out("grid.off"), 232);
  for (const char* threads : {"1", "2"}) {
    Outcome run = hlr({"draw", grid.string(), "--view", "iso", "--threads", threads, "-o",
                       out(std::string("g") + threads + ".svg").string(), "-o", out(std::string("g") + threads + ".json").string()});
    ASSERT_EQ(run.exit_code, 0) << run.err;
  }
  EXPECT_EQ(slurp(out("g1.svg")), slurp(out("g2.svg")));
  const json doc = json::parse(slurp(out("g1.json")));
  EXPECT_EQ(doc.at("input").at("faces").get<std::size_t>(), 106722u);
  EXPECT_EQ(without_times(doc), without_times(json::parse(slurp(out("g2.json")))));
}

TEST_F(CliDraw, OneThreadAndTwoDrawTheSameBytesInStrips) {
  // A scene large enough for the area sort to cut the image into strips (AreaSortOptions), which
  // two threads sort side by side.
  const fs::path mesh = fs::path(HLR_SHARED_SCENES) / "refined_elephant.off";
  if (!fs::exists(mesh)) GTEST_SKIP() << "no shared scenes at " << HLR_SHARED_SCENES;
  for (const char* threads : {"1", "2"}) {
    Outcome run = hlr({"draw", mesh.string(), "--view", "iso", "--threads", threads, "-o",
                       out(std::string("e") + threads + ".svg").string()});
    ASSERT_EQ(run.exit_code, 0) << run.err;
  }
  EXPECT_EQ(slurp(out("e1.svg")), slurp(out("e2.svg")));
}

TEST_F(CliDraw, AnotherMachineDrawsTheSameBytes) {
  // What changes between two machines of one architecture: the number of cores (so the default
  // --threads), the locale, the time zone, the folder a command runs in. Addresses change from run
  // to run anyway. The views: a general direction and a perspective write view matrices of their
  // own (world_to_view), the double kernel decides precedence in double.
  const fs::path elephant = fs::path(HLR_SHARED_SCENES) / "refined_elephant.off";
  const std::string bracket = (kScenes / "l_bracket.off").string();
  std::vector<std::pair<std::string, std::vector<std::string>>> cases = {
      {"perspective", {bracket, "--eye", "8,-6,5", "--target", "1.5,1,1.5"}},
      {"general", {bracket, "--dir", "0.3,-1.7,0.9"}}};
  if (fs::exists(elephant)) {
    cases.push_back({"elephant_general", {elephant.string(), "--dir", "0.3,-1.7,0.9"}});
    cases.push_back({"elephant_double", {elephant.string(), "--view", "iso", "--kernel", "double"}});
  }
  const fs::path elsewhere = dir_ / "elsewhere";
  fs::create_directories(elsewhere);
  for (const auto& [name, args] : cases) {
    SCOPED_TRACE(name);
    auto outputs = [&](const std::string& tag) {
      std::vector<std::string> o;
      for (const char* ext : {".svg", ".dxf", ".json"}) o.insert(o.end(), {"-o", out(name + tag + ext).string()});
      return o;
    };
    std::vector<std::string> here{"draw"};
    here.insert(here.end(), args.begin(), args.end());
    here.insert(here.end(), {"--threads", "2"});
    for (const auto& o : outputs("_here")) here.push_back(o);
    const Outcome a = hlr(here);
    ASSERT_EQ(a.exit_code, 0) << a.err;
    // The other machine: one core and the default thread count, another locale and time zone,
    // another working folder.
    std::vector<std::string> there{"/bin/sh", "-c",
                                   "cd \"$1\" && shift && exec taskset -c 0 env LC_ALL=C.UTF-8 LANG=C.UTF-8 "
                                   "TZ=Pacific/Chatham \"$@\"",
                                   "sh", elsewhere.string(), kBinary, "draw"};
    there.insert(there.end(), args.begin(), args.end());
    for (const auto& o : outputs("_there")) there.push_back(o);
    const Outcome b = spawn(there);
    ASSERT_EQ(b.exit_code, 0) << b.err;
    for (const char* ext : {".svg", ".dxf"})
      EXPECT_EQ(slurp(out(name + "_here" + ext)), slurp(out(name + "_there" + ext))) << ext;
    EXPECT_EQ(without_times(json::parse(slurp(out(name + "_here.json")))),
              without_times(json::parse(slurp(out(name + "_there.json")))));
  }
}

TEST_F(CliDraw, PredicateStatsCountTheExactKernelsDecisionsOnlyWhenAsked) {
  // HLR_PREDICATE_STATS=1 adds one stderr line per predicate family and changes no line drawn.
  const std::string mesh = (kScenes / "edge_on.off").string();
  auto draw = [&](bool stats, const std::string& name) {
    std::vector<std::string> argv{"/bin/sh", "-c", std::string(stats ? "HLR_PREDICATE_STATS=1 " : "") + "exec \"$0\" \"$@\"",
                                  kBinary, "draw", mesh, "--view", "front", "-o", out(name).string()};
    return spawn(argv);
  };
  const Outcome plain = draw(false, "plain.json"), counted = draw(true, "counted.json");
  ASSERT_EQ(plain.exit_code, 0) << plain.err;
  ASSERT_EQ(counted.exit_code, 0) << counted.err;
  EXPECT_EQ(plain.err.find("predicates"), std::string::npos) << plain.err;
  const std::regex line(R"(hlr: predicates (orientation|comparison|sign): identity (\d+), interval (\d+), doubles (\d+), exact (\d+))");
  std::size_t families = 0, orientations = 0;
  for (auto it = std::sregex_iterator(counted.err.begin(), counted.err.end(), line); it != std::sregex_iterator(); ++it) {
    ++families;
    if ((*it)[1] == "orientation") orientations = std::stoull((*it)[2]) + std::stoull((*it)[3]) + std::stoull((*it)[4]) + std::stoull((*it)[5]);
  }
  EXPECT_EQ(families, 3u) << counted.err;
  EXPECT_GT(orientations, 0u) << counted.err;
  EXPECT_EQ(json::parse(slurp(out("plain.json"))).at("lines"), json::parse(slurp(out("counted.json"))).at("lines"));
}

TEST_F(CliDraw, DrawsTheBundledBracketIntoSvgDxfAndJson) {
  const std::string mesh = (kScenes / "l_bracket.off").string();
  Outcome run = hlr({"draw", mesh, "--view", "iso", "-o", out("b.svg").string(), "-o", out("b.dxf").string(), "-o",
                     out("b.json").string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.err, "");
  const json doc = json::parse(slurp(out("b.json")));
  EXPECT_EQ(doc.at("format"), "hlr-lines/1");
  EXPECT_EQ(doc.at("view").at("direction"), json({-1, 1, -1}));
  EXPECT_EQ(doc.at("input").at("files").at(0), mesh);
  std::size_t visible = 0, hidden = 0;
  for (const auto& line : doc.at("lines")) {
    ++(line.at("visible").get<bool>() ? visible : hidden);
    EXPECT_EQ(line.at("a").size(), 3u);
    EXPECT_TRUE(line.at("edge").is_array()) << line;  // the bracket has no penetrations
    const std::string kind = line.at("kind");
    EXPECT_TRUE(kind == "silhouette" || kind == "crease") << kind;
  }
  EXPECT_GT(visible, 0u);
  EXPECT_GT(hidden, 0u);  // the inner corner and the back edges
  const std::string svg = slurp(out("b.svg"));
  EXPECT_EQ(svg.rfind("<?xml", 0), 0u);
  EXPECT_NE(svg.find("mm\""), std::string::npos);
  EXPECT_NE(svg.find("stroke-dasharray"), std::string::npos);
  const std::string dxf = slurp(out("b.dxf"));
  EXPECT_NE(dxf.find("AC1015"), std::string::npos);
  EXPECT_NE(dxf.find("LWPOLYLINE"), std::string::npos);
  EXPECT_EQ(entries(dir_ / "out"), (std::vector<std::string>{"b.dxf", "b.json", "b.svg"}));
}

TEST_F(CliDraw, ViewsAndOptionsWork) {
  const std::string mesh = (kScenes / "penetrating_boxes.off").string();
  for (const char* view : {"front", "back", "top", "bottom", "left", "right", "iso"}) {
    Outcome run = hlr({"draw", mesh, "--view", view, "-o", out("p.svg").string()});
    EXPECT_EQ(run.exit_code, 0) << view << ": " << run.err;
  }
  Outcome run = hlr({"draw", mesh, "--dir", "1,2,-3", "--crease", "60", "--sheet", "a3", "--scale", "1:2", "-o",
                     out("p.json").string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  bool intersection = false;
  const json doc = json::parse(slurp(out("p.json")));
  for (const auto& line : doc.at("lines"))
    if (line.at("kind") == "intersection") {
      intersection = true;
      EXPECT_TRUE(line.at("edge").is_null());
    }
  EXPECT_TRUE(intersection) << "the bar penetrates the cube";
}

TEST_F(CliDraw, HiddenNoneDrawsNoDashedLineButKeepsThemInJson) {
  const std::string mesh = (kScenes / "l_bracket.off").string();
  Outcome run = hlr({"draw", mesh, "--hidden", "none", "-o", out("b.svg").string(), "-o", out("b.json").string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(slurp(out("b.svg")).find("stroke-dasharray"), std::string::npos);
  bool hidden = false;
  const json doc = json::parse(slurp(out("b.json")));
  for (const auto& line : doc.at("lines")) hidden |= !line.at("visible").get<bool>();
  EXPECT_TRUE(hidden);
}

TEST_F(CliDraw, HelpShowsAnExample) {
  Outcome run = hlr({"draw", "--help"});
  EXPECT_EQ(run.exit_code, 0);
  EXPECT_NE(run.out.find("hlr draw fixtures/scenes/l_bracket.off"), std::string::npos) << run.out;
}

TEST_F(CliDraw, BadOptionsAreUsageErrors) {
  const std::string mesh = (kScenes / "cube.off").string();
  const std::string o = out("c.svg").string();
  for (const std::vector<std::string>& bad :
       {std::vector<std::string>{"--view", "sideways"}, {"--dir", "0,0,0"}, {"--dir", "0,0,1", "--up", "0,0,-2"},
        {"--sheet", "B9"}, {"--scale", "0"}, {"--scale", "1:0"}, {"--scale", "half"}, {"--crease", "200"},
        {"--hidden", "dotted"}}) {
    std::vector<std::string> args{mesh, "-o", o};
    args.insert(args.end(), bad.begin(), bad.end());
    expect_failure(args, 2, "");
  }
}

// Perspective views (--eye with --target or --dir).

// The written coordinates of a model point: world_to_view applied to (x, y, z, 1), divided by the
// fourth component (docs/FORMATS.md).
std::array<double, 3> perspective_point(const json& view, const std::array<double, 3>& p) {
  double h[4];
  for (int r = 0; r < 4; ++r) {
    const auto& row = view.at("world_to_view").at(r);
    h[r] = row.at(0).get<double>() * p[0] + row.at(1).get<double>() * p[1] + row.at(2).get<double>() * p[2] +
           row.at(3).get<double>();
  }
  return {h[0] / h[3], h[1] / h[3], h[2] / h[3]};
}

TEST_F(CliDraw, PerspectiveViewWritesItsProjectiveMap) {
  const std::string mesh = (kScenes / "cube.off").string();
  Outcome run = hlr({"draw", mesh, "--eye", "3,-4,2.5", "--target", "0.5,0.5,0.5", "-o", out("p.json").string(), "-o",
                     out("p.svg").string(), "-o", out("p.dxf").string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const json doc = json::parse(slurp(out("p.json")));
  const json& view = doc.at("view");
  EXPECT_EQ(view.at("projection"), "perspective");
  EXPECT_EQ(view.at("eye"), json({3, -4, 2.5}));
  EXPECT_EQ(view.at("direction"), json({-2.5, 4.5, -2}));
  EXPECT_EQ(view.at("world_to_view").at(2), json({0, 0, 0, 1}));
  // Every line end is the image of a cube corner, by the matrix as FORMATS.md says to apply it.
  std::vector<std::array<double, 3>> corners;
  for (double x : {0, 1})
    for (double y : {0, 1})
      for (double z : {0, 1}) corners.push_back(perspective_point(view, {x, y, z}));
  std::size_t ends = 0;
  for (const auto& line : doc.at("lines"))
    for (const char* end : {"a", "b"}) {
      const auto p = line.at(end).get<std::array<double, 3>>();
      ++ends;
      for (const auto& c : corners)
        if (std::abs(c[0] - p[0]) < 1e-12 && std::abs(c[1] - p[1]) < 1e-12 && std::abs(c[2] - p[2]) < 1e-12) {
          --ends;
          break;
        }
    }
  EXPECT_GT(doc.at("lines").size(), 8u);
  EXPECT_EQ(ends, 0u) << "line ends that are no corner's image";
  // Three faces toward the eye: their nine edges visible, the other three hidden.
  std::size_t visible = 0;
  for (const auto& line : doc.at("lines")) visible += line.at("visible").get<bool>();
  EXPECT_EQ(visible, 9u);
  EXPECT_EQ(entries(dir_ / "out"), (std::vector<std::string>{"p.dxf", "p.json", "p.svg"}));
  // A perspective image has no one scale, and its title block says so.
  EXPECT_NE(slurp(out("p.svg")).find("NTS (perspective)"), std::string::npos);
  // The same view as --dir, and through hlr surfaces and hlr check.
  Outcome dir = hlr({"draw", mesh, "--eye", "3,-4,2.5", "--dir", "-2.5,4.5,-2", "-o", out("d.json").string()});
  ASSERT_EQ(dir.exit_code, 0) << dir.err;
  EXPECT_EQ(json::parse(slurp(out("d.json"))).at("lines"), doc.at("lines"));
  Outcome surfaces = hlr({"surfaces", mesh, "--eye", "3,-4,2.5", "--target", "0.5,0.5,0.5", "-o", out("s.json").string()});
  ASSERT_EQ(surfaces.exit_code, 0) << surfaces.err;
  EXPECT_EQ(json::parse(slurp(out("s.json"))).at("view").at("projection"), "perspective");
  Outcome check = hlr({"check", mesh, "--eye", "3,-4,2.5", "--target", "0.5,0.5,0.5", "--raster", "256"});
  EXPECT_EQ(check.exit_code, 0) << check.out << check.err;
}

TEST_F(CliDraw, PerspectiveNearPlaneCutsTheScene) {
  // The eye between the bracket's arms, looking along the upper one: the near plane cuts the faces
  // of the lower arm that reach behind the eye. The cut draws no line; every line end lies in front.
  const std::string mesh = (kScenes / "l_bracket.off").string();
  for (const std::string& out_name : {"n.json", "n.svg", "n.dxf"}) {
    Outcome run = hlr({"draw", mesh, "--eye", "2.1,1.3,2.2", "--target", "0.2,1.0,2.5", "--near", "0.01", "-o",
                       out(out_name).string()});
    ASSERT_EQ(run.exit_code, 0) << run.err;
  }
  const json doc = json::parse(slurp(out("n.json")));
  EXPECT_FALSE(doc.at("lines").empty());
  for (const auto& line : doc.at("lines"))
    for (const char* end : {"a", "b"}) EXPECT_GT(line.at(end).at(2).get<double>(), 0) << line;
  Outcome raster = hlr({"draw", mesh, "--eye", "2.1,1.3,2.2", "--target", "0.2,1.0,2.5", "--raster", "128", "-o",
                        out("n.png").string()});
  EXPECT_EQ(raster.exit_code, 0) << raster.err;
}

TEST_F(CliDraw, BadPerspectiveViewsGiveOneLineAndNoFile) {
  const std::string cube = (kScenes / "cube.off").string();
  const std::string o = out("c.json").string();
  auto bad = [&](std::vector<std::string> extra, const std::string& prefix) {
    std::vector<std::string> args{cube, "-o", o};
    args.insert(args.end(), extra.begin(), extra.end());
    expect_failure(args, 2, prefix);
  };
  bad({"--eye", "1,2,3", "--target", "1,2,3"}, "hlr: --eye/--target: the eye is at the target");
  bad({"--eye", "0.5,0.5,0", "--target", "0.5,0.5,3"}, "hlr: --eye 0.5,0.5,0: the eye lies on face 0 of ");
  bad({"--eye", "0.5,0.5,10", "--dir", "0,0,1"}, "hlr: --eye 0.5,0.5,10: the whole scene is behind the eye");
  bad({"--eye", "inf,0,0", "--target", "0,0,0"}, "hlr: --eye/--target: eye is not finite");
  bad({"--eye", "3,3,3", "--target", "0,0,nan"}, "hlr: --eye/--target: target is not finite");
  bad({"--eye", "3,3,3"}, "hlr: --eye: give --target");
  bad({"--eye", "3,3,3", "--target", "0,0,0", "--near", "1"}, "hlr: --near:");
  bad({"--eye", "3,3,3", "--target", "0,0,0", "--view", "front"}, "");
  bad({"--eye", "3,3,3", "--target", "0,0,0", "--sun", "1,1,-1"}, "hlr: --sun 1,1,-1: shadows are not supported with --eye");
  bad({"--eye", "3,3,3", "--target", "0,0,0", "--point-light", "0,0,9"},
      "hlr: --point-light 0,0,9: shadows are not supported with --eye");
  expect_failed_run({"sheet", cube, "--eye", "3,3,3", "-o", out("s.svg").string()}, 2,
                    "hlr: --eye is not supported by hlr sheet yet");
}

TEST_F(CliDraw, BadMeshesAndOutputsGiveOneLineAndNoFile) {
  const std::string cube = (kScenes / "cube.off").string();
  const std::vector<std::pair<std::string, std::string>> meshes{
      {"truncated.off", "OFF\n8 6 0\n0 0 0\n1 0 0\n"},
      {"empty.off", ""},
      {"nan.off", "OFF\n3 1 0\n0 0 0\nnan 0 0\n0 1 0\n3 0 1 2\n"},
      {"huge.off", "OFF\n3 1 0\n0 0 0\n1e300 0 0\n0 1 0\n3 0 1 2\n"},
      {"index.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n"},
      {"flat.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n2 0 0\n3 0 1 2\n"},  // no face left
      {"garbage.obj", "v 0 0 0\nv 1 0\nf 1 2 3\n"},
      {"short.stl", "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n"},
      {"mesh.xyz", "0 0 0\n"},
  };
  for (const auto& [name, text] : meshes) {
    const std::string path = write_input(name, text).string();
    expect_failure({path, "-o", out("m.svg").string()}, 1, "hlr: " + path + ": ");
  }
  expect_failure({in("missing.off").string(), "-o", out("m.svg").string()}, 1, "hlr: " + in("missing.off").string());
  expect_failure({dir_.string(), "-o", out("m.svg").string()}, 1, "hlr: " + dir_.string());
  // Outputs: unknown extension, missing directory, a directory; a bad second output keeps the first
  // from being written too.
  for (const std::string& bad : {out("x.txt").string(), (dir_ / "no" / "dir" / "x.svg").string(), (dir_ / "out").string()})
    expect_failure({cube, "-o", out("good.svg").string(), "-o", bad}, 1, "hlr: " + bad + ": ");
}

TEST_F(CliDraw, NonManifoldMeshIsDrawnWithAWarning) {
  // Three triangles on one edge.
  const std::string fin =
      write_input("fin.off", "OFF\n5 3 0\n0 0 0\n1 0 0\n0 1 0\n0 -1 0\n0 0 1\n3 0 1 2\n3 1 0 3\n3 0 1 4\n").string();
  Outcome run = hlr({"draw", fin, "-o", out("f.json").string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.err.find("warning"), std::string::npos) << run.err;
  EXPECT_EQ(count_lines(run.err), 1u) << run.err;
  bool shared_edge = false;
  const json doc = json::parse(slurp(out("f.json")));
  for (const auto& line : doc.at("lines"))
    shared_edge |= line.at("edge") == json({0, 1}) && line.at("kind") == "crease";
  EXPECT_TRUE(shared_edge) << "the non-manifold edge is a crease";
}

}  // namespace

// ---- hlr draw --raster and hlr check --------------------------------------------------------------
namespace {

bool is_png(const std::string& bytes) { return bytes.rfind("\x89PNG\r\n\x1a\n", 0) == 0; }

TEST_F(CliDraw, RasterDrawsPngAndLinesJson) {
  const std::string mesh = (kScenes / "l_bracket.off").string();
  for (const char* dash : {"arc", "paper"}) {
    Outcome run = hlr({"draw", mesh, "--view", "iso", "--raster", "512", "--dash", dash, "-o", out("b.png").string(),
                       "-o", out("b.json").string(), "-o", out("b.svg").string()});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_TRUE(is_png(slurp(out("b.png"))));
    EXPECT_NE(run.out.find("raster 512 px"), std::string::npos) << run.out;
  }
  // The raster JSON holds the exact drawing's lines, in its order, with its own pieces.
  Outcome exact = hlr({"draw", mesh, "--view", "iso", "-o", out("e.json").string()});
  ASSERT_EQ(exact.exit_code, 0) << exact.err;
  const json raster = json::parse(slurp(out("b.json")));
  const json reference = json::parse(slurp(out("e.json")));
  EXPECT_EQ(raster.at("format"), "hlr-lines/1");
  EXPECT_EQ(raster.at("kernel"), "raster");
  EXPECT_EQ(raster.at("raster").at("resolution"), 512);
  EXPECT_EQ(raster.at("stats").at("lines"), reference.at("stats").at("lines"));
  EXPECT_TRUE(raster.at("stats").at("stage_seconds").contains("zbuffer"));
  std::set<std::vector<int>> edges_raster, edges_exact;
  for (const auto& l : raster.at("lines")) edges_raster.insert(l.at("edge").get<std::vector<int>>());
  for (const auto& l : reference.at("lines")) edges_exact.insert(l.at("edge").get<std::vector<int>>());
  EXPECT_EQ(edges_raster, edges_exact);
}

TEST_F(CliDraw, RasterOptionMistakesAreErrors) {
  const std::string cube = (kScenes / "cube.off").string();
  // A PNG needs the raster path; --raster and an inexact kernel exclude each other; bad sizes.
  expect_failure({cube, "-o", out("c.svg").string(), "-o", out("c.png").string()}, 1,
                 "hlr: " + out("c.png").string() + ": a PNG is drawn by the raster path");
  expect_failure({cube, "--raster", "256", "--kernel", "epick", "-o", out("c.png").string()}, 2, "hlr: --raster");
  for (const char* bad : {"8", "100000", "big"}) expect_failure({cube, "--raster", bad, "-o", out("c.png").string()}, 2, "");
  expect_failure({cube, "--raster", "256", "--dash", "dotted", "-o", out("c.png").string()}, 2, "");
}

// Two parts (tests/cli/parts/): a cube, and behind it a box whose left and top edges lie 1e-7 inside
// the cube's outline in the front view. The JSON keeps both lines; the SVG and DXF draw one.
const fs::path kParts = HLR_CLI_PARTS;

TEST_F(CliDraw, NearlyCoincidentEdgesOfTwoPartsAreDrawnOnceInTheirPartGroups) {
  const std::string front = (kParts / "front_box.off").string(), back = (kParts / "back_box.off").string();
  Outcome run = hlr({"draw", front, back, "--view", "front", "-o", out("p.svg").string(), "-o", out("p.json").string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("2 segments merged on the sheet"), std::string::npos) << run.out;

  // The JSON: the cube's left edge visible at x = 0, the box's hidden at x = 1e-7, both there.
  const json doc = json::parse(slurp(out("p.json")));
  bool cube_left = false, box_left = false;
  for (const auto& line : doc.at("lines")) {
    const double ax = line.at("a").at(0), bx = line.at("b").at(0);
    if (ax != bx) continue;  // vertical lines only
    if (ax == 0 && line.at("mesh") == 0 && line.at("visible") == true) cube_left = true;
    if (ax == 1e-7 && line.at("mesh") == 1 && line.at("visible") == false) box_left = true;
  }
  EXPECT_TRUE(cube_left && box_left) << doc.at("lines");
  EXPECT_EQ(doc.at("stats").at("merged_segments"), 2);
  EXPECT_EQ(doc.at("stats").at("merge_distance_mm"), 0.01);

  // The SVG: each part in its group; the box has no hidden line left (its left and top edges are
  // under the cube's visible outline), so one solid line is drawn at the left, not a dashed one too.
  const auto svg = hlr::test::parse_svg(slurp(out("p.svg")));
  ASSERT_TRUE(svg.well_formed) << svg.error;
  ASSERT_TRUE(svg.find("g", "part-front_box-visible"));
  ASSERT_TRUE(svg.find("g", "part-back_box-visible"));
  EXPECT_EQ(svg.find("g", "part-front_box-visible")->group, "visible");
  EXPECT_EQ(svg.in_group("path", "part-front_box-visible").size(), 1u);  // the square
  EXPECT_EQ(svg.in_group("path", "part-back_box-visible").size(), 1u);   // what sticks out on the right
  EXPECT_TRUE(svg.in_group("path", "hidden").empty());

  // Merging off: the box's hidden edges come back, dashed, in its hidden group.
  run = hlr({"draw", front, back, "--view", "front", "--merge-distance", "0", "-o", out("p0.svg").string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto unmerged = hlr::test::parse_svg(slurp(out("p0.svg")));
  ASSERT_TRUE(unmerged.find("g", "part-back_box-hidden"));
  EXPECT_EQ(unmerged.find("g", "part-back_box-hidden")->group, "hidden");
  EXPECT_EQ(unmerged.in_group("path", "part-back_box-hidden").size(), 1u);  // left and top edges, chained
  EXPECT_FALSE(unmerged.find("g", "part-front_box-hidden"));
}

// A closed prism along z over the regular n-gon of radius r (an OFF file's text).
std::string cylinder_off(int n, double r, double z0, double z1) {
  std::ostringstream off;
  off.precision(17);
  off << "OFF\n" << 2 * n << ' ' << n + 2 << " 0\n";
  for (double z : {z0, z1})
    for (int i = 0; i < n; ++i) off << r * std::cos(2 * M_PI * i / n) << ' ' << r * std::sin(2 * M_PI * i / n) << ' ' << z << '\n';
  off << n;
  for (int i = n - 1; i >= 0; --i) off << ' ' << i;
  off << '\n' << n;
  for (int i = 0; i < n; ++i) off << ' ' << n + i;
  off << '\n';
  for (int i = 0; i < n; ++i) off << "4 " << i << ' ' << (i + 1) % n << ' ' << n + (i + 1) % n << ' ' << n + i << '\n';
  return off.str();
}

TEST_F(CliDraw, ContactLinesOfNearlyTangentSurfacesAreLeftOffTheSheet) {
  // A shaft (64 sides) in a bore of the same radius tessellated with 72 sides: their facets cut
  // each other all along the contact, at a few degrees. The JSON has those intersection lines; the
  // sheet leaves them out unless --contact-angle 0.
  const std::string shaft = write_input("shaft.off", cylinder_off(64, 10, -5, 25)).string();
  const std::string bore = write_input("bore.off", cylinder_off(72, 10, 0, 20)).string();
  Outcome run = hlr({"draw", shaft, bore, "--view", "front", "-o", out("s.svg").string(), "-o", out("s.json").string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("intersection segments left off the sheet"), std::string::npos) << run.out;
  const json doc = json::parse(slurp(out("s.json")));
  EXPECT_GT(doc.at("stats").at("lines_by_kind").at("intersection").get<int>(), 50);
  EXPECT_GT(doc.at("stats").at("contact_segments").get<int>(), 50);
  EXPECT_EQ(doc.at("stats").at("contact_degrees"), 10);
  run = hlr({"draw", shaft, bore, "--view", "front", "--contact-angle", "0", "-o", out("s0.svg").string(), "-o",
             out("s0.json").string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(json::parse(slurp(out("s0.json"))).at("stats").at("contact_segments"), 0);
  const auto with = hlr::test::parse_svg(slurp(out("s0.svg"))), without = hlr::test::parse_svg(slurp(out("s.svg")));
  EXPECT_GT(with.in_group("path", "visible").size() + with.in_group("path", "hidden").size(),
            without.in_group("path", "visible").size() + without.in_group("path", "hidden").size() + 50);
}

TEST_F(CliDraw, EntirelyHiddenPartIsStillDrawnDashed) {
  // A small cube behind the box, entirely hidden by it: all of its lines are dashed, in its hidden
  // group.
  const std::string small = write_input("small.off", "OFF\n8 6 0\n2 40 2\n2 40 8\n2 45 2\n2 45 8\n8 40 2\n8 40 8\n8 45 2\n8 45 8\n"
                                                     "4 0 2 6 4\n4 1 5 7 3\n4 0 4 5 1\n4 2 3 7 6\n4 0 1 3 2\n4 4 6 7 5\n").string();
  const std::string back = (kParts / "back_box.off").string();
  Outcome run = hlr({"draw", small, back, "--view", "front", "-o", out("h.svg").string(), "-o", out("h.dxf").string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto svg = hlr::test::parse_svg(slurp(out("h.svg")));
  EXPECT_FALSE(svg.find("g", "part-back_box-hidden"));
  EXPECT_FALSE(svg.find("g", "part-small-visible"));
  ASSERT_TRUE(svg.find("g", "part-small-hidden"));
  EXPECT_EQ(svg.in_group("path", "part-small-hidden").size(), 1u);  // its outline, closed
  const std::string dxf = slurp(out("h.dxf"));
  for (const char* layer : {"SMALL-VISIBLE", "SMALL-HIDDEN", "BACK_BOX-VISIBLE", "BACK_BOX-HIDDEN"})
    EXPECT_NE(dxf.find(std::string("\n") + layer + "\n"), std::string::npos) << layer;
}

TEST_F(CliDraw, BadMergeDistanceIsAUsageError) {
  const std::string cube = (kScenes / "cube.off").string();
  for (const char* bad : {"-0.01", "2", "fine"}) expect_failure({cube, "--merge-distance", bad, "-o", out("c.svg").string()}, 2, "hlr: ");
  for (const char* bad : {"-1", "91", "steep"}) expect_failure({cube, "--contact-angle", bad, "-o", out("c.svg").string()}, 2, "hlr: ");
  for (const char* bad : {"-1", "many"}) expect_failure({cube, "--threads", bad, "-o", out("c.svg").string()}, 2, "hlr: ");
}

TEST_F(CliDraw, UnknownSubcommandIsNamed) {
  Outcome run = hlr({"drwa", (kScenes / "cube.off").string(), "-o", out("c.svg").string()});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(run.err, "hlr: unknown subcommand 'drwa' (expected draw, sheet, frames, check, surfaces, shadows, mesh, clip or batch; see 'hlr --help')\n");
  EXPECT_TRUE(entries(dir_ / "out").empty());
  run = hlr({});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(run.err, "hlr: a subcommand is required (draw, sheet, frames, check, surfaces, shadows, mesh, clip or batch; see 'hlr --help')\n");
  // Options before the subcommand still work; --help and --version too.
  EXPECT_EQ(hlr({"--version"}).exit_code, 0);
  EXPECT_EQ(hlr({"--help"}).exit_code, 0);
  EXPECT_EQ(hlr({"draw", "--help"}).exit_code, 0);
}

TEST_F(CliDraw, PdfSheetAndAScaleThatDoesNotFit) {
  const std::string mesh = (kBundledParts / "flange.off").string();
  Outcome run = hlr({"draw", mesh, "--view", "top", "--line-group", "0.7", "--units", "cm", "-o", out("f.pdf").string(),
                     "-o", out("f.json").string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(slurp(out("f.pdf")).rfind("%PDF-", 0), 0u);
  EXPECT_NE(run.out.find("6 circles and 0 arcs drawn as such"), std::string::npos) << run.out;
  const json doc = json::parse(slurp(out("f.json")));
  EXPECT_EQ(doc.at("stats").at("circles"), 6);
  EXPECT_EQ(doc.at("stats").at("arcs"), 0);
  fs::remove(out("f.pdf")), fs::remove(out("f.json"));
  // 120 cm is 1.2 m: 1:5 on A4 (240 mm).
  run = hlr({"draw", mesh, "--view", "top", "--units", "cm", "-o", out("f.svg").string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(slurp(out("f.svg")).find("<title>hlr drawing, A4, 1:5</title>"), std::string::npos);
  fs::remove(out("f.svg"));
  // A given scale at which the drawing runs off the sheet: exit 2, one line, no file.
  expect_failure({mesh, "--view", "top", "--scale", "5:1", "-o", out("f.svg").string()}, 2,
                 "hlr: --scale 5:1: the drawing needs 600 x 400 mm at 5:1; the drawing area of A4 is 257 x 160 mm");
  // With only JSON there is no sheet to overflow.
  EXPECT_EQ(hlr({"draw", mesh, "--view", "top", "--scale", "5:1", "-o", out("f.json").string()}).exit_code, 0);
  fs::remove(out("f.json"));
  for (const std::vector<std::string>& bad : {std::vector<std::string>{"--line-group", "0.6"}, {"--units", "ft"}})
    expect_failure({mesh, bad[0], bad[1], "-o", out("f.svg").string()}, 2, "hlr: ");
}

// --smooth-edges off|thin|full on the filleted bracket (fixtures/parts/): thin draws the fillets'
// four tangent lines as kind smooth, the visible ones in a thin group and on a layer THIN, the
// hidden ones nowhere on the sheet; full draws them as creases; bare --smooth-edges is full.
TEST_F(CliDraw, SmoothEdgesThinAndFull) {
  const std::string mesh = (kBundledParts / "filleted_bracket.off").string();
  auto lines_of = [&](const std::vector<std::string>& options) {
    std::vector<std::string> args{"draw", mesh, "--view", "iso", "-o", out("f.json").string(), "-o", out("f.svg").string(),
                                  "-o", out("f.dxf").string()};
    args.insert(args.end(), options.begin(), options.end());
    Outcome run = hlr(args);
    EXPECT_EQ(run.exit_code, 0) << run.err;
    return json::parse(slurp(out("f.json")));
  };
  auto count = [](const json& doc, const std::string& kind, bool visible) {
    std::size_t n = 0;
    for (const auto& l : doc.at("lines")) n += l.at("kind") == kind && l.at("visible") == visible;
    return n;
  };
  const json off = lines_of({});
  EXPECT_EQ(off.at("stats").at("lines_by_kind").at("smooth"), 0);
  EXPECT_EQ(slurp(out("f.svg")).find("thin"), std::string::npos);
  EXPECT_EQ(slurp(out("f.dxf")).find("THIN"), std::string::npos);
  const std::string off_svg = slurp(out("f.svg"));

  const json thin = lines_of({"--smooth-edges", "thin"});
  EXPECT_EQ(thin.at("stats").at("lines_by_kind").at("smooth"), 4);
  EXPECT_EQ(thin.at("stats").at("lines"), off.at("stats").at("lines").get<int>() + 4);
  // In the iso view the inner fillet (facing +x, +z) is seen, the outer one (under the part) not.
  EXPECT_EQ(count(thin, "smooth", true), 2u);
  EXPECT_EQ(count(thin, "smooth", false), 2u);
  const auto svg = hlr::test::parse_svg(slurp(out("f.svg")));
  ASSERT_TRUE(svg.well_formed) << svg.error;
  const auto* group = svg.find("g", "thin");
  ASSERT_TRUE(group);
  EXPECT_EQ(group->attributes.at("class"), "thin");
  EXPECT_EQ(group->attributes.at("stroke-width"), "0.25");  // narrow, line group 0.5
  EXPECT_EQ(group->attributes.count("stroke-dasharray"), 0u);
  EXPECT_EQ(svg.in_group("path", "thin").size(), 2u);  // the two visible tangent lines
  EXPECT_TRUE(svg.find("g", "part-filleted_bracket-thin"));
  // The hidden group is the same as without smooth edges: the hidden tangent lines are not drawn.
  auto hidden_paths = [](const hlr::test::SvgDocument& doc) {
    std::vector<std::string> d;
    for (const auto* p : doc.in_group("path", "hidden")) d.push_back(p->attributes.at("d"));
    return d;
  };
  EXPECT_EQ(hidden_paths(svg), hidden_paths(hlr::test::parse_svg(off_svg)));
  const std::string dxf = slurp(out("f.dxf"));
  EXPECT_NE(dxf.find("\nTHIN\n"), std::string::npos);

  const json full = lines_of({"--smooth-edges", "full"});
  EXPECT_EQ(full.at("stats").at("lines_by_kind").at("smooth"), 0);
  EXPECT_EQ(full.at("stats").at("lines_by_kind").at("crease"), off.at("stats").at("lines_by_kind").at("crease").get<int>() + 4);
  const json bare = lines_of({"--smooth-edges"});
  EXPECT_EQ(bare.at("lines"), full.at("lines"));
  EXPECT_EQ(lines_of({"--smooth-edges", "off"}).at("lines"), off.at("lines"));
  // A bare --smooth-edges before the meshes takes the mesh for its value (README: meshes first),
  // and says so; a bare one before another option is full.
  Outcome run = hlr({"draw", mesh, "--smooth-edges", "--view", "iso", "-o", out("g.json").string()});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(json::parse(slurp(out("g.json"))).at("lines"), full.at("lines"));
  fs::remove(out("g.json"));
  run = hlr({"draw", "--smooth-edges", mesh, "--view", "iso", "-o", out("g.json").string()});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("put meshes before a bare --smooth-edges"), std::string::npos) << run.err;
  EXPECT_FALSE(fs::exists(out("g.json")));
}

TEST_F(CliDraw, SmoothEdgesBadModeIsAUsageError) {
  const std::string mesh = (kBundledParts / "filleted_bracket.off").string();
  expect_failure({mesh, "--smooth-edges", "dotted", "-o", out("f.svg").string()}, 2,
                 "hlr: --smooth-edges: 'dotted' is not off, thin or full");
  // A second mesh after a bare --smooth-edges is taken for its value, and refused by name.
  expect_failure({mesh, "--smooth-edges", mesh, "-o", out("f.svg").string()}, 2,
                 "hlr: --smooth-edges: '" + mesh + "' is not off, thin or full");
  expect_failed_run({"sheet", mesh, "--smooth-edges", "thick", "-o", out("s.svg").string()}, 2,
                    "hlr: --smooth-edges: 'thick' is not off, thin or full");
}

// hlr sheet --smooth-edges thin: each view's visible smooth lines in its thin group, the DXF's
// layer THIN.
TEST_F(CliDraw, SmoothEdgesOnASheet) {
  const std::string mesh = (kBundledParts / "filleted_bracket.off").string();
  Outcome run = hlr({"sheet", mesh, "--smooth-edges", "thin", "-o", out("s.svg").string(), "-o", out("s.pdf").string(), "-o",
                     out("s.dxf").string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto svg = hlr::test::parse_svg(slurp(out("s.svg")));
  ASSERT_TRUE(svg.well_formed) << svg.error;
  // The front view sees the tangent lines end-on. The top view sees the inner fillet's two lines,
  // but the one at the wall (x = 8) lies under the wall's top edge, a visible line, which takes
  // precedence; in the right view the one on the base (z = 8) lies under the base's end edge.
  EXPECT_FALSE(svg.find("g", "view-front-thin"));
  EXPECT_EQ(svg.in_group("path", "view-top-thin").size(), 1u);
  EXPECT_EQ(svg.in_group("path", "view-right-thin").size(), 1u);
  EXPECT_EQ(svg.in_group("path", "view-iso-thin").size(), 2u);
  EXPECT_NE(slurp(out("s.dxf")).find("\nTHIN\n"), std::string::npos);
  EXPECT_EQ(slurp(out("s.pdf")).rfind("%PDF-", 0), 0u);
}

class CliSheet : public CliDraw {
 protected:
  void expect_sheet_failure(const std::vector<std::string>& args, int code, const std::string& prefix) const {
    std::vector<std::string> all{"sheet", (kBundledParts / "flange.off").string()};
    all.insert(all.end(), args.begin(), args.end());
    expect_failed_run(all, code, prefix);
  }
};

TEST_F(CliSheet, WritesEveryFormatAndSummarisesTheViews) {
  Outcome run = hlr({"sheet", (kBundledParts / "flange.off").string(), "--views", "front,top", "--dir", "1,2,-3", "--projection",
                     "first", "--sheet", "a2", "--title", "Flange <1> & co", "-o", out("s.svg").string(), "-o",
                     out("s.pdf").string(), "-o", out("s.dxf").string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.err, "");
  EXPECT_NE(run.out.find("3 views, first angle, A2 at "), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("  top: "), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("  custom: "), std::string::npos) << run.out;
  const auto doc = hlr::test::parse_svg(slurp(out("s.svg")));
  ASSERT_TRUE(doc.well_formed) << doc.error;
  for (const char* id : {"view-front", "view-top", "view-custom", "projection-symbol", "title-block"})
    EXPECT_TRUE(doc.find("g", id)) << id;
  bool title = false;
  for (const auto* t : doc.in_group("text", "title-text")) title |= t->text == "Flange <1> & co";
  EXPECT_TRUE(title);
  EXPECT_EQ(slurp(out("s.pdf")).rfind("%PDF-", 0), 0u);
  EXPECT_NE(slurp(out("s.dxf")).find("VIEW_CUSTOM"), std::string::npos);
  EXPECT_EQ(entries(dir_ / "out"), (std::vector<std::string>{"s.dxf", "s.pdf", "s.svg"}));
}

TEST_F(CliSheet, MistakesAreOneLineAndNoFile) {
  const std::string o = out("s.svg").string();
  expect_sheet_failure({"--views", "front,sideways", "-o", o}, 2, "hlr: --views: unknown view \"sideways\"");
  expect_sheet_failure({"--views", "front,top,front", "-o", o}, 2, "hlr: --views: view \"front\" is listed twice");
  expect_sheet_failure({"--projection", "second", "-o", o}, 2, "hlr: ");
  expect_sheet_failure({"--sheet", "B9", "-o", o}, 2, "hlr: --sheet: unknown sheet");
  expect_sheet_failure({"--dir", "0,0,0", "-o", o}, 2, "hlr: --dir/--up: ");
  expect_sheet_failure({"--scale", "20:1", "-o", o}, 2, "hlr: --scale 20:1: the views need ");
  expect_sheet_failure({"-o", out("s.json").string()}, 1, "hlr: " + out("s.json").string() + ": unknown output format");
  expect_sheet_failure({"-o", o, "-o", (dir_ / "missing" / "s.pdf").string()}, 1, "hlr: " + (dir_ / "missing" / "s.pdf").string());
}

TEST_F(CliSheet, HelpShowsAnExample) {
  Outcome run = hlr({"sheet", "--help"});
  EXPECT_EQ(run.exit_code, 0);
  EXPECT_NE(run.out.find("hlr sheet fixtures/parts/flange.off"), std::string::npos) << run.out;
}

class CliCheck : public CliDraw {};

TEST_F(CliCheck, ReportsAgreementWithASummaryLineLast) {
  const std::string mesh = (kScenes / "l_bracket.off").string();
  Outcome run = hlr({"check", mesh, "--dir", "1,2,-3", "--raster", "256,1024", "--kernels", "epick,double", "--json",
                     out("r.json").string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.err, "");
  const std::string last = run.out.substr(run.out.rfind('\n', run.out.size() - 2) + 1);
  EXPECT_EQ(last.rfind("check: ", 0), 0u) << run.out;
  const json report = json::parse(slurp(out("r.json")));
  EXPECT_EQ(report.at("format"), "hlr-check/1");
  ASSERT_EQ(report.at("methods").size(), 4u);
  std::vector<std::string> names;
  for (const auto& m : report.at("methods")) {
    names.push_back(m.at("method").get<std::string>() + (m.contains("resolution") ? std::to_string(m.at("resolution").get<int>()) : ""));
    ASSERT_EQ(m.at("status"), "ok") << m;
    const double fraction = m.at("agreement").at("fraction");
    EXPECT_GT(fraction, 0.99) << m;  // a general view of a simple part: only pixel-size errors
    EXPECT_LE(fraction, 1.0);
  }
  EXPECT_EQ(names, (std::vector<std::string>{"epick", "double", "raster256", "raster1024"}));
  // The inexact kernels agree exactly on this part and view; the finer raster agrees better.
  EXPECT_EQ(report.at("methods").at(0).at("agreement").at("fraction"), 1.0);
  EXPECT_GT(report.at("methods").at(3).at("agreement").at("fraction"),
            report.at("methods").at(2).at("agreement").at("fraction"));
}

TEST_F(CliCheck, DiffImageAndErrors) {
  const std::string mesh = (kScenes / "cube.off").string();
  Outcome run = hlr({"check", mesh, "--view", "front", "--raster", "128", "--diff", out("d.png").string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;  // disagreement is a finding, not an error
  EXPECT_TRUE(is_png(slurp(out("d.png"))));
  EXPECT_NE(run.out.find("wrote " + out("d.png").string()), std::string::npos);
  // One comparison per image; a bad mesh leaves no file.
  Outcome two = hlr({"check", mesh, "--raster", "128,256", "--diff", out("e.png").string()});
  EXPECT_EQ(two.exit_code, 2);
  const std::string bad = write_input("bad.off", "OFF\n3 1 0\n0 0 0\n").string();
  Outcome broken = hlr({"check", bad, "--diff", out("f.png").string(), "--json", out("f.json").string()});
  EXPECT_EQ(broken.exit_code, 1);
  EXPECT_EQ(count_lines(broken.err), 1u) << broken.err;
  EXPECT_EQ(broken.err.rfind("hlr: " + bad + ": ", 0), 0u) << broken.err;
  EXPECT_EQ(entries(dir_ / "out"), std::vector<std::string>{"d.png"});
  Outcome kernel = hlr({"check", mesh, "--kernel", "epick"});
  EXPECT_EQ(kernel.exit_code, 2) << "check has --kernels, not --kernel";
}

}  // namespace

// ---- hlr batch ------------------------------------------------------------------------------------
namespace {

class CliBatch : public CliDraw {
 protected:
  // The manifest in in/, with a copy of the cube in in/meshes/ for relative paths.
  fs::path manifest(const json& jobs) const {
    fs::create_directories(dir_ / "in" / "meshes");
    fs::copy_file(kScenes / "cube.off", dir_ / "in" / "meshes" / "cube.off", fs::copy_options::overwrite_existing);
    return write_input("manifest.json", json{{"format", "hlr-batch/1"}, {"jobs", jobs}}.dump());
  }

  static std::vector<std::string> sorted_lines(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    std::sort(lines.begin(), lines.end());
    return lines;
  }

  static json without_stats(json doc) {
    doc.erase("stats");
    return doc;
  }

  // A JSON document without its timings, every "seconds" (hlr-check/1, hlr-clip/1's "stats").
  static json without_seconds(json doc) {
    if (doc.is_object()) doc.erase("seconds");
    if (doc.is_structured())  // iterating a number or a string would visit the value itself
      for (auto& item : doc) item = without_seconds(item);
    return doc;
  }
};

TEST_F(CliBatch, RunsEveryJobAsTheCliWouldAndReportsTheFailedOne) {
  const std::string bracket = (kScenes / "l_bracket.off").string();
  const fs::path m = manifest(json::array({
      {{"command", "draw"}, {"meshes", {bracket}}, {"view", "iso"}, {"outputs", {"../out/b.svg", "../out/b.json"}}},
      {{"command", "surfaces"}, {"meshes", {"meshes/cube.off"}}, {"view", "front"}, {"options", {"--exact"}},
       {"outputs", {"../out/deep/c.json"}}},
      {{"command", "draw"}, {"meshes", {"meshes/missing.off"}}, {"outputs", {"../out/m.svg"}}},
      {{"command", "sheet"}, {"meshes", {"meshes/cube.off"}}, {"view", "front,top"}, {"outputs", {"../out/s.dxf"}}},
  }));
  Outcome run = hlr({"batch", m.string(), "--jobs", "2"});
  EXPECT_EQ(run.exit_code, 1) << run.err;
  EXPECT_EQ(sorted_lines(run.out), (std::vector<std::string>{
                                       "job 0 ok: ../out/b.svg ../out/b.json",
                                       "job 1 ok: ../out/deep/c.json",
                                       "job 2 failed: meshes/missing.off: cannot open (No such file or directory)",
                                       "job 3 ok: ../out/s.dxf",
                                   }));
  EXPECT_NE(run.err.find("hlr batch: 3 of 4 jobs ok, 1 failed"), std::string::npos) << run.err;
  EXPECT_EQ(entries(dir_ / "out"), (std::vector<std::string>{"b.json", "b.svg", "deep", "s.dxf"}));

  // The files are the ones the CLI writes for the same command lines (JSON apart from stats).
  ASSERT_EQ(hlr({"draw", bracket, "--view", "iso", "-o", out("direct_b.svg").string(), "-o", out("direct_b.json").string()})
                .exit_code,
            0);
  EXPECT_EQ(slurp(out("b.svg")), slurp(out("direct_b.svg")));
  EXPECT_EQ(without_stats(json::parse(slurp(out("b.json")))), without_stats(json::parse(slurp(out("direct_b.json")))));
  const json surfaces = json::parse(slurp(dir_ / "out" / "deep" / "c.json"));
  EXPECT_EQ(surfaces.at("input").at("files"), json({"meshes/cube.off"}));  // run in the manifest's folder
  EXPECT_TRUE(surfaces.dump().find("_exact") != std::string::npos) << "the job's options are passed on";
}

TEST_F(CliBatch, RunsClipAndCheckJobsAsTheCliWould) {
  // A clip job reads "inputs" (SUBJECT.json and CLIP.json); a check job's outputs are its --diff
  // .png and --json .json. Absolute input paths, so that the same command lines run from here.
  const std::string subject = (kFixtures / "subject.json").string(), clips = (kFixtures / "clip.json").string();
  const std::string cube = (kScenes / "cube.off").string();
  const fs::path m = manifest(json::array({
      {{"command", "clip"}, {"inputs", {subject, clips}}, {"options", {"--exact"}}, {"outputs", {"../out/clip.json"}}},
      {{"command", "check"}, {"meshes", {cube}}, {"view", "iso"}, {"options", {"--raster", "256"}},
       {"outputs", {"../out/check/diff.png", "../out/check/report.json"}}},
      {{"command", "draw"}, {"meshes", {cube}}, {"view", "top"}, {"outputs", {"../out/top.svg"}}},
      {{"command", "clip"}, {"inputs", {subject, "polygons/missing.json"}}, {"outputs", {"../out/missing.json"}}},
  }));
  Outcome run = hlr({"batch", m.string(), "--jobs", "2", "--threads", "1"});
  EXPECT_EQ(run.exit_code, 1) << run.err;
  EXPECT_EQ(sorted_lines(run.out), (std::vector<std::string>{
                                       "job 0 ok: ../out/clip.json",
                                       "job 1 ok: ../out/check/diff.png ../out/check/report.json",
                                       "job 2 ok: ../out/top.svg",
                                       "job 3 failed: polygons/missing.json: cannot open (No such file or directory)",
                                   }));
  EXPECT_EQ(entries(dir_ / "out"), (std::vector<std::string>{"check", "clip.json", "top.svg"}));

  ASSERT_EQ(hlr({"clip", subject, clips, "--exact", "-o", out("direct_clip.json").string()}).exit_code, 0);
  ASSERT_EQ(hlr({"check", cube, "--view", "iso", "--raster", "256", "--diff", out("direct.png").string(), "--json",
                 out("direct.json").string()})
                .exit_code,
            0);
  ASSERT_EQ(hlr({"draw", cube, "--view", "top", "-o", out("direct_top.svg").string()}).exit_code, 0);
  EXPECT_EQ(without_seconds(json::parse(slurp(out("clip.json")))), without_seconds(json::parse(slurp(out("direct_clip.json")))));
  EXPECT_EQ(slurp(dir_ / "out" / "check" / "diff.png"), slurp(out("direct.png")));
  EXPECT_EQ(without_seconds(json::parse(slurp(dir_ / "out" / "check" / "report.json"))),
            without_seconds(json::parse(slurp(out("direct.json")))));
  EXPECT_EQ(slurp(out("top.svg")), slurp(out("direct_top.svg")));

  // The command lines: clip has no --threads, so the batch's is not passed on to it.
  Outcome list = hlr({"batch", m.string(), "--list", "--threads", "1"});
  ASSERT_EQ(list.exit_code, 0) << list.err;
  std::istringstream lines(list.out);
  std::string clip_line, check_line;
  std::getline(lines, clip_line);
  std::getline(lines, check_line);
  EXPECT_EQ(json::parse(clip_line),
            json({{"job", 0}, {"arguments", {"clip", subject, clips, "--exact", "-o", "../out/clip.json"}},
                  {"inputs", {1, 2}}, {"outputs", {5}}}));
  EXPECT_EQ(json::parse(check_line).at("arguments"),
            json({"check", cube, "--view", "iso", "--raster", "256", "--diff", "../out/check/diff.png", "--json",
                  "../out/check/report.json", "--threads", "1"}));
}

TEST_F(CliBatch, RunsShadowsAndMeshJobsAsTheCliWould) {
  // Neither command has a view; mesh writes one file and has no --threads.
  const std::string box = (kScenes.parent_path() / "shadows" / "box_on_ground.off").string();
  const std::string bracket = (kScenes / "l_bracket.off").string();
  const fs::path m = manifest(json::array({
      {{"command", "shadows"}, {"meshes", {box}}, {"options", {"--sun", "1,2,-4"}},
       {"outputs", {"../out/sun.json", "../out/sun.csv"}}},
      {{"command", "mesh"}, {"meshes", {bracket}}, {"outputs", {"../out/bracket.ply"}}},
      {{"command", "shadows"}, {"meshes", {box}}, {"outputs", {"../out/no_light.json"}}},
  }));
  Outcome run = hlr({"batch", m.string(), "--jobs", "2", "--threads", "1"});
  EXPECT_EQ(run.exit_code, 1) << run.err;
  const std::vector<std::string> lines = sorted_lines(run.out);
  ASSERT_EQ(lines.size(), 3u) << run.out;
  EXPECT_EQ(lines[0], "job 0 ok: ../out/sun.json ../out/sun.csv");
  EXPECT_EQ(lines[1], "job 1 ok: ../out/bracket.ply");
  EXPECT_EQ(lines[2].rfind("job 2 failed: ", 0), 0u) << lines[2];
  EXPECT_EQ(entries(dir_ / "out"), (std::vector<std::string>{"bracket.ply", "sun.csv", "sun.json"}));

  ASSERT_EQ(hlr({"shadows", box, "--sun", "1,2,-4", "--threads", "1", "-o", out("direct_sun.json").string(), "-o",
                 out("direct_sun.csv").string()})
                .exit_code,
            0);
  ASSERT_EQ(hlr({"mesh", bracket, "-o", out("direct_bracket.ply").string()}).exit_code, 0);
  EXPECT_EQ(without_stats(json::parse(slurp(out("sun.json")))), without_stats(json::parse(slurp(out("direct_sun.json")))));
  EXPECT_EQ(slurp(out("sun.csv")), slurp(out("direct_sun.csv")));
  EXPECT_EQ(slurp(out("bracket.ply")), slurp(out("direct_bracket.ply")));

  Outcome list = hlr({"batch", m.string(), "--list", "--threads", "3"});
  ASSERT_EQ(list.exit_code, 0) << list.err;
  std::istringstream jobs(list.out);
  std::string shadows_line, mesh_line;
  std::getline(jobs, shadows_line);
  std::getline(jobs, mesh_line);
  EXPECT_EQ(json::parse(shadows_line).at("arguments"),
            json({"shadows", box, "--sun", "1,2,-4", "-o", "../out/sun.json", "-o", "../out/sun.csv", "--threads", "3"}));
  EXPECT_EQ(json::parse(mesh_line).at("arguments"), json({"mesh", bracket, "-o", "../out/bracket.ply"}));
}

TEST_F(CliBatch, JobTimeoutIsEveryJobsOwnTimeoutUnlessItHasOne) {
  const fs::path m = manifest(json::array({
      {{"command", "draw"}, {"meshes", {"meshes/cube.off"}}, {"outputs", {"x.svg"}}},
      {{"command", "clip"}, {"inputs", {"s.json", "c.json"}}, {"options", {"--timeout", "9"}}, {"outputs", {"y.json"}}},
  }));
  Outcome run = hlr({"batch", m.string(), "--list", "--job-timeout", "2.5"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.out,
            R"({"arguments":["draw","meshes/cube.off","-o","x.svg","--timeout","2.5"],"inputs":[1],"job":0,"outputs":[3]})" "\n"
            R"({"arguments":["clip","s.json","c.json","--timeout","9","-o","y.json"],"inputs":[1,2],"job":1,"outputs":[6]})" "\n");
}

TEST_F(CliBatch, ListsTheJobsCommandLines) {
  const fs::path m = manifest(json::array({
      {{"command", "draw"}, {"meshes", {"meshes/cube.off", "b.off"}}, {"view", "top"}, {"options", {"--crease", "40"}},
       {"outputs", {"x.svg"}}},
      {{"command", "sheet"}, {"meshes", {"meshes/cube.off"}}, {"options", {"--threads", "1"}}, {"outputs", {"y.pdf"}}},
  }));
  Outcome run = hlr({"batch", m.string(), "--list", "--threads", "3"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.out,
            R"({"arguments":["draw","meshes/cube.off","b.off","--view","top","--crease","40","-o","x.svg","--threads","3"],)"
            R"("inputs":[1,2],"job":0,"outputs":[8]})" "\n"
            R"({"arguments":["sheet","meshes/cube.off","--threads","1","-o","y.pdf"],"inputs":[1],"job":1,"outputs":[5]})" "\n");
  EXPECT_TRUE(entries(dir_ / "out").empty());
}

TEST_F(CliBatch, MalformedManifestsAreOneLineAndRunNothing) {
  const std::string job = R"({"command": "draw", "meshes": ["meshes/cube.off"], "outputs": ["../out/x.svg"]})";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"", "file is empty"},
      {"{\"format\": \"hlr-batch/1\", \"jobs\": [", "not valid JSON at byte"},
      {"[]", "top level is an array, expected an object"},
      {R"({"jobs": []})", R"("format" is missing)"},
      {R"({"format": "hlr-lines/1", "jobs": []})", R"(format is "hlr-lines/1", expected "hlr-batch/1")"},
      {R"({"format": "hlr-batch/1"})", R"("jobs" is missing)"},
      {R"({"format": "hlr-batch/1", "jobs": [)" + job + R"(, 3]})", "job 1 is a number, expected an object"},
      {R"({"format": "hlr-batch/1", "jobs": [{"command": "frames", "meshes": ["a"], "outputs": ["b"]}]})",
       R"(job 0: unknown command "frames" (a job is draw, sheet, surfaces, check, shadows, mesh or clip))"},
      {R"({"format": "hlr-batch/1", "jobs": [{"command": "shadows", "meshes": ["a"], "view": "iso", "outputs": ["b"]}]})",
       R"(job 0: unknown key "view" (a shadows job has command, meshes, options and outputs))"},
      {R"({"format": "hlr-batch/1", "jobs": [{"command": "mesh", "meshes": ["a"], "outputs": ["b.off", "c.off"]}]})",
       R"(job 0: "outputs" has 2 paths, expected 1)"},
      // clip jobs: two "inputs" (polygon files), one output, no view
      {R"({"format": "hlr-batch/1", "jobs": [{"command": "clip", "meshes": ["a", "b"], "outputs": ["c"]}]})",
       R"(job 0: a clip job reads "inputs" (SUBJECT.json and CLIP.json), not "meshes")"},
      {R"({"format": "hlr-batch/1", "jobs": [{"command": "clip", "inputs": ["a"], "outputs": ["c"]}]})",
       R"(job 0: "inputs" has 1 path, expected 2 (SUBJECT.json and CLIP.json))"},
      {R"({"format": "hlr-batch/1", "jobs": [{"command": "clip", "inputs": ["a", "b"], "outputs": ["c", "d"]}]})",
       R"(job 0: "outputs" has 2 paths, expected 1)"},
      {R"({"format": "hlr-batch/1", "jobs": [{"command": "clip", "inputs": ["a", "b"], "view": "iso", "outputs": ["c"]}]})",
       R"(job 0: unknown key "view" (a clip job has command, inputs, options and outputs))"},
      {R"({"format": "hlr-batch/1", "jobs": [{"command": "clip", "inputs": ["a", "b"], "options": ["--output=d"], "outputs": ["c"]}]})",
       R"(job 0: "options" name an output (--output=d))"},
      {R"({"format": "hlr-batch/1", "jobs": [{"command": "draw", "inputs": ["a"], "outputs": ["b"]}]})",
       R"(job 0: a draw job reads "meshes", not "inputs")"},
      // check jobs: outputs by extension, one of each
      {R"({"format": "hlr-batch/1", "jobs": [{"command": "check", "meshes": ["a"], "outputs": ["b.svg"]}]})",
       R"(job 0: output "b.svg" is not .png (--diff) or .json (--json), what a check job writes)"},
      {R"({"format": "hlr-batch/1", "jobs": [{"command": "check", "meshes": ["a"], "outputs": ["b.json", "c.JSON"]}]})",
       R"(job 0: outputs "b.json" and "c.JSON" are both .json (--json): a check job writes one)"},
      {R"({"format": "hlr-batch/1", "jobs": [{"command": "check", "meshes": ["a"], "options": ["--diff", "d.png"], "outputs": ["b.json"]}]})",
       R"(job 0: "options" name an output (--diff))"},
      {R"({"format": "hlr-batch/1", "jobs": [{"command": "draw", "meshes": [], "outputs": ["b"]}]})",
       R"(job 0: "meshes" is empty)"},
      {R"({"format": "hlr-batch/1", "jobs": [{"command": "draw", "meshes": ["a"], "output": ["b"]}]})",
       R"(job 0: unknown key "output")"},
      {R"({"format": "hlr-batch/1", "jobs": [{"command": "draw", "meshes": ["a"], "outputs": [1]}]})",
       R"(job 0: "outputs" item 0 is a number, expected a string)"},
      {R"({"format": "hlr-batch/1", "jobs": [{"command": "draw", "meshes": ["a"], "options": ["-o", "c"], "outputs": ["b"]}]})",
       R"(job 0: "options" name an output (-o))"},
      {R"({"format": "hlr-batch/1", "jobs": [)" + job + ", " + job + "]}",
       R"(job 1: output "../out/x.svg" is written by job 0 too)"},
  };
  for (const auto& [text, problem] : cases) {
    const fs::path m = write_input("bad.json", text);
    SCOPED_TRACE(text);
    Outcome run = hlr({"batch", m.string()});
    EXPECT_EQ(run.exit_code, 1);
    EXPECT_EQ(count_lines(run.err), 1u) << run.err;
    EXPECT_EQ(run.err.rfind("hlr: " + m.string() + ": " + problem, 0), 0u) << run.err;
    EXPECT_EQ(run.out, "");
    EXPECT_TRUE(entries(dir_ / "out").empty());
  }
  Outcome missing = hlr({"batch", in("none.json").string()});
  EXPECT_EQ(missing.exit_code, 1);
  EXPECT_EQ(missing.err, "hlr: " + in("none.json").string() + ": cannot open (No such file or directory)\n");
}

}  // namespace
