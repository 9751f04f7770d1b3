// End-to-end tests of `hlr shadows`: outputs written (JSON checked against the hand-computed
// areas of fixtures/shadows, the CSV against a golden file, the SVG read back), sun studies, and
// bad input: one line on stderr, exit code 1 or 2, no output file.
#include "cli_support.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using namespace hlr::cli_test;

const std::string kBinary = HLR_BINARY;
const fs::path kShadowFixtures = HLR_SHADOW_FIXTURES;
const fs::path kGolden = HLR_SHADOW_GOLDEN;

class CliShadows : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = make_temp_dir("hlr-shadows-test", {"out", "logs"});
    ASSERT_FALSE(dir_.empty());
  }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
  fs::path out(const std::string& name) const { return dir_ / "out" / name; }
  std::vector<std::string> outputs() const { return entries(dir_ / "out"); }

  Outcome hlr(std::vector<std::string> args) const {
    args.insert(args.begin(), kBinary);
    return run_process(std::move(args), dir_ / "logs");
  }

  // A failed run: exit `code`, one line on stderr starting with `prefix` and containing `needle`,
  // nothing in the output directory.
  void expect_failure(const std::vector<std::string>& args, int code, const std::string& prefix,
                      const std::string& needle = "") const {
    SCOPED_TRACE(::testing::PrintToString(args));
    const Outcome run = hlr(args);
    EXPECT_EQ(run.exit_code, code) << run.err;
    EXPECT_EQ(count_lines(run.err), 1u) << run.err;
    EXPECT_EQ(run.err.rfind(prefix, 0), 0u) << run.err;
    EXPECT_NE(run.err.find(needle), std::string::npos) << run.err;
    EXPECT_TRUE(outputs().empty()) << run.err;
  }

  fs::path dir_;
};

const std::string box() { return (kShadowFixtures / "box_on_ground.off").string(); }

TEST_F(CliShadows, WritesJsonCsvAndSvg) {
  const Outcome run = hlr({"shadows", box(), "--sun", "1,2,-4", "-o", out("s.json").string(), "-o",
                           out("s.csv").string(), "-o", out("s.svg").string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.err, "");
  EXPECT_EQ(outputs(), (std::vector<std::string>{"s.csv", "s.json", "s.svg"}));
  const json doc = json::parse(slurp(out("s.json")));
  EXPECT_EQ(doc.at("format"), "hlr-shadows/1");
  EXPECT_EQ(doc.at("lights").at(0).at("type"), "directional");
  EXPECT_EQ(doc.at("lights").at(0).at("direction"), json({1.0, 2.0, -4.0}));
  ASSERT_EQ(doc.at("sources").size(), 7u);
  const json& ground = doc.at("sources").at(0);
  EXPECT_EQ(ground.at("faces"), json({0}));
  EXPECT_EQ(ground.at("plane"), json({0.0, 0.0, 1.0, 0.0}));
  EXPECT_EQ(ground.at("area"), 400.0);
  const json& gl = ground.at("lights").at(0);
  EXPECT_EQ(gl.at("facing"), "toward");
  EXPECT_EQ(gl.at("lit_area"), 393.0);
  ASSERT_FALSE(gl.at("shadow").empty());
  for (const auto& s : gl.at("shadow")) {
    EXPECT_FALSE(s.at("by").empty());
    for (const auto& p : s.at("outer")) EXPECT_EQ(p.at(2), 0.0);  // model coordinates, on the ground
  }
  // The bottom faces away: attached shadow, the whole face, nobody to blame.
  const json& bottom = doc.at("sources").at(1).at("lights").at(0);
  EXPECT_EQ(bottom.at("facing"), "away");
  EXPECT_TRUE(bottom.at("lit").empty());
  EXPECT_EQ(bottom.at("shadow").size(), 1u);
  EXPECT_TRUE(bottom.at("shadow").at(0).at("by").empty());
  const std::string svg = slurp(out("s.svg"));
  EXPECT_EQ(svg.rfind("<?xml", 0), 0u);
  EXPECT_NE(svg.find("<g id=\"light-0\">"), std::string::npos);
  EXPECT_NE(svg.find("</svg>"), std::string::npos);
}

TEST_F(CliShadows, PointLightWritesJsonCsvAndSvg) {
  // A sun and a point light, each solved on its own; the point light over the box's -y side.
  const Outcome run = hlr({"shadows", box(), "--sun", "1,2,-4", "--point-light", "1,-4,4", "-o", out("p.json").string(),
                           "-o", out("p.csv").string(), "-o", out("p.svg").string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(outputs(), (std::vector<std::string>{"p.csv", "p.json", "p.svg"}));
  const json doc = json::parse(slurp(out("p.json")));
  ASSERT_EQ(doc.at("lights").size(), 2u);
  EXPECT_EQ(doc.at("lights").at(1), json({{"type", "point"}, {"position", {1.0, -4.0, 4.0}}}));
  const json& ground = doc.at("sources").at(0).at("lights");
  EXPECT_EQ(ground.at(0).at("lit_area"), 393.0);
  EXPECT_EQ(ground.at(1).at("lit_area"), 372.0);  // fixtures/shadows/README.md
  for (const auto& s : ground.at(1).at("shadow")) {
    EXPECT_FALSE(s.at("by").empty());
    for (const auto& p : s.at("outer")) EXPECT_EQ(p.at(2), 0.0);
  }
  EXPECT_EQ(doc.at("sources").at(4).at("lights").at(1).at("facing"), "away");  // +x: the light at x = 1
  std::istringstream csv(slurp(out("p.csv")));
  std::string header, ground_row;
  std::getline(csv, header);
  std::getline(csv, ground_row);
  EXPECT_EQ(header, "mesh,face,area,lit_area_sun1,sunlit_fraction_sun1,lit_area_point1,sunlit_fraction_point1");
  EXPECT_EQ(ground_row, "0,0,400.0,393.0,0.9825,372.0,0.93");
  const std::string svg = slurp(out("p.svg"));
  EXPECT_NE(svg.find("<g id=\"light-1\">"), std::string::npos);
  EXPECT_NE(svg.find("point1 at (1.0, -4.0, 4.0)"), std::string::npos);
}

TEST_F(CliShadows, PointLightAmongTheGeometry) {
  // fixtures/shadows/README.md: the light between two boxes needs the cube of six views.
  const std::string between = (kShadowFixtures / "light_between_boxes.off").string();
  const Outcome run = hlr({"shadows", between, "--point-light", "0,0,1", "-o", out("p.json").string(), "-o",
                           out("p.csv").string(), "-o", out("p.svg").string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(outputs(), (std::vector<std::string>{"p.csv", "p.json", "p.svg"}));
  const json doc = json::parse(slurp(out("p.json")));
  EXPECT_EQ(doc.at("lights").at(0), json({{"type", "point"}, {"position", {0.0, 0.0, 1.0}}}));
  EXPECT_EQ(doc.at("sources").at(0).at("faces"), json({0}));
  EXPECT_EQ(doc.at("sources").at(0).at("lights").at(0).at("lit_area"), 177.5);
  std::istringstream csv(slurp(out("p.csv")));
  std::string line;
  std::getline(csv, line);
  std::getline(csv, line);
  EXPECT_EQ(line, "0,0,400.0,177.5,0.44375");
  EXPECT_NE(slurp(out("p.svg")).find("<g id=\"light-0\">"), std::string::npos);
  const Outcome draw = hlr({"draw", between, "--view", "iso", "--point-light", "0,0,1", "-o", out("d.svg").string()});
  ASSERT_EQ(draw.exit_code, 0) << draw.err;
  EXPECT_NE(slurp(out("d.svg")).find("id=\"shadows\""), std::string::npos);
  // Inside box A: refused, no file.
  fs::remove(out("p.json"));
  fs::remove(out("p.csv"));
  fs::remove(out("p.svg"));
  fs::remove(out("d.svg"));
  expect_failure({"shadows", between, "--point-light", "-2,0,1", "-o", out("x.json").string()}, 2,
                 "hlr: --point-light -2,0,1: ", "inside a closed solid");
}

// hlr sheet --sun/--point-light: every view carries the shadows, as hlr draw --view NAME does.
TEST_F(CliShadows, SheetDrawsTheShadowsOnEveryView) {
  const std::string between = (kShadowFixtures / "light_between_boxes.off").string();
  const Outcome run = hlr({"sheet", between, "--views", "front,top,iso", "--point-light", "0,0,1", "--sun", "1,2,-4", "-o",
                           out("s.svg").string(), "-o", out("s.dxf").string(), "-o", out("s.pdf").string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const std::string svg = slurp(out("s.svg"));
  const std::string dxf = slurp(out("s.dxf"));
  EXPECT_EQ(slurp(out("s.pdf")).rfind("%PDF", 0), 0u);
  for (const std::string view : {"front", "top", "iso"}) {
    SCOPED_TRACE(view);
    // The view's shadow group lies inside the view's group and holds filled paths, the same areas
    // hlr draw --view NAME fills.
    const std::size_t group = svg.find("<g id=\"view-" + view + "\"");
    const std::size_t shadows = svg.find("<g id=\"view-" + view + "-shadows\"");
    ASSERT_NE(group, std::string::npos);
    ASSERT_NE(shadows, std::string::npos);
    EXPECT_LT(group, shadows);
    EXPECT_EQ(svg.find("<g id=\"view-", group + 1), shadows);  // no other view's group between them
    const std::size_t end = svg.find("</g>", shadows);
    std::size_t sheet_paths = 0;
    for (std::size_t at = svg.find("<path", shadows); at < end; at = svg.find("<path", at + 1)) ++sheet_paths;
    const Outcome draw = hlr({"draw", between, "--view", view, "--point-light", "0,0,1", "--sun", "1,2,-4", "-o",
                              out("d.svg").string(), "-o", out("d.dxf").string()});
    ASSERT_EQ(draw.exit_code, 0) << draw.err;
    const std::string drawn = slurp(out("d.svg"));
    const std::size_t own = drawn.find("<g id=\"shadows\"");
    ASSERT_NE(own, std::string::npos);
    std::size_t draw_paths = 0;
    for (std::size_t at = drawn.find("<path", own); at < drawn.find("</g>", own); at = drawn.find("<path", at + 1)) ++draw_paths;
    EXPECT_GT(sheet_paths, 0u);
    EXPECT_EQ(sheet_paths, draw_paths);
    // DXF: the view's block has HATCH entities on SHADOW, as many as the drawing's.
    std::string upper = view;
    for (char& ch : upper) ch = char(std::toupper(static_cast<unsigned char>(ch)));
    const std::size_t block = dxf.find("\nVIEW_" + upper + "\n", dxf.find("\nBLOCKS\n"));
    ASSERT_NE(block, std::string::npos);
    const std::size_t block_end = dxf.find("ENDBLK", block);
    std::size_t hatches = 0;
    for (std::size_t at = dxf.find("\nHATCH\n", block); at < block_end; at = dxf.find("\nHATCH\n", at + 1)) ++hatches;
    const std::string drawn_dxf = slurp(out("d.dxf"));
    std::size_t drawn_hatches = 0;
    for (std::size_t at = drawn_dxf.find("\nHATCH\n"); at != std::string::npos; at = drawn_dxf.find("\nHATCH\n", at + 1))
      ++drawn_hatches;
    EXPECT_EQ(hatches, drawn_hatches);
    EXPECT_GT(hatches, 0u);
  }
  EXPECT_NE(dxf.find("\nSHADOW\n"), std::string::npos);
  // Without lights the sheet has no shadows and no SHADOW layer.
  const Outcome plain = hlr({"sheet", between, "--views", "front", "-o", out("p.dxf").string(), "-o", out("p.svg").string()});
  ASSERT_EQ(plain.exit_code, 0) << plain.err;
  EXPECT_EQ(slurp(out("p.dxf")).find("\nSHADOW\n"), std::string::npos);
  EXPECT_EQ(slurp(out("p.svg")).find("-shadows\""), std::string::npos);
}

TEST_F(CliShadows, SheetShadowMistakes) {
  const std::string o = out("s.svg").string();
  expect_failure({"sheet", box(), "--point-light", "1,1,1", "-o", o}, 2, "hlr: --point-light 1,1,1: ", "inside a closed solid");
  expect_failure({"sheet", box(), "--sun", "0,0,0", "-o", o}, 2, "hlr: --sun 0,0,0: ", "zero");
  expect_failure({"sheet", box(), "--sun", "1,2,-4", "--kernel", "epick", "-o", o}, 2, "hlr: --sun 1,2,-4: ",
                 "exact path only");
}

TEST_F(CliShadows, CsvIsTheGoldenFile) {
  // Regenerate: hlr shadows fixtures/shadows/two_boxes.off --sun -1,0,-1 --sun 1,2,-4 --sun 0,0,-1
  //   --union -o tests/golden/shadows/two_boxes.csv (and review the diff).
  const Outcome run = hlr({"shadows", (kShadowFixtures / "two_boxes.off").string(), "--sun", "-1,0,-1", "--sun",
                           "1,2,-4", "--sun", "0,0,-1", "--union", "-o", out("t.csv").string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(slurp(out("t.csv")), slurp(kGolden / "two_boxes.csv"));
}

TEST_F(CliShadows, SunStudyGivesOneLightPerStep) {
  const Outcome run = hlr({"shadows", box(), "--sun-at", "2026-06-21T09:00+10:00/15:00/PT1H", "--site",
                           "-33.86,151.21", "--union", "-o", out("d.csv").string(), "-o", out("d.json").string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const json doc = json::parse(slurp(out("d.json")));
  ASSERT_EQ(doc.at("lights").size(), 7u);
  for (const auto& l : doc.at("lights")) {
    EXPECT_GT(l.at("altitude").get<double>(), 0.0);
    EXPECT_LT(l.at("direction").at(2).get<double>(), 0.0);  // the sun above: light travels down
  }
  EXPECT_EQ(doc.at("lights").at(3).at("time"), "2026-06-21T12:00+10:00");
  // Sydney in June: the sun stands in the north (+Y), so the light travels toward -Y at noon.
  EXPECT_LT(doc.at("lights").at(3).at("direction").at(1).get<double>(), 0.0);
  std::istringstream csv(slurp(out("d.csv")));
  std::string header;
  std::getline(csv, header);
  EXPECT_NE(header.find("lit_area_2026-06-21T09:00+10:00"), std::string::npos) << header;
  EXPECT_NE(header.find("sunlit_fraction_2026-06-21T15:00+10:00"), std::string::npos) << header;
  EXPECT_NE(header.find("union_shadow_area"), std::string::npos) << header;
  EXPECT_TRUE(doc.at("sources").at(0).contains("union_shadow_area"));
}

// A sun study's fuzzy culling: the faces no sun direction of a group can light are left out of its
// light views, and the CSV (per-face lit areas, the union) is the same, byte for byte, as without
// culling; a JSON output (polygons) turns culling off and says so in stats.cull.
TEST_F(CliShadows, SunStudyCullingChangesNoByteOfTheCsv) {
  const std::string room = (kShadowFixtures / "furnished_room.off").string();
  const std::vector<std::string> study{"--sun-at", "2026-06-21T08:00+02:00/18:00/PT1H", "--site", "48.85,2.35", "--union"};
  auto args = [&](std::vector<std::string> tail) {
    std::vector<std::string> a{"shadows", room};
    a.insert(a.end(), study.begin(), study.end());
    a.insert(a.end(), tail.begin(), tail.end());
    return a;
  };
  expect_failure(args({"--cull", "maybe", "-o", out("x.csv").string()}), 2, "hlr: ", "--cull");
  const Outcome none = hlr(args({"--cull", "none", "-o", out("none.csv").string()}));
  ASSERT_EQ(none.exit_code, 0) << none.err;
  const Outcome fuzzy = hlr(args({"-o", out("fuzzy.csv").string()}));  // the default
  ASSERT_EQ(fuzzy.exit_code, 0) << fuzzy.err;
  EXPECT_EQ(slurp(out("none.csv")), slurp(out("fuzzy.csv")));
  EXPECT_NE(none.out.find("cull none"), std::string::npos) << none.out;
  EXPECT_NE(fuzzy.out.find("cull fuzzy"), std::string::npos) << fuzzy.out;
  // Something was culled: every group line names its count, and the interior (floor and
  // furniture, 220 of the 408 faces) is hidden from the summer sun.
  std::size_t most = 0, groups = 0;
  for (std::size_t at = fuzzy.out.find("faces culled"); at != std::string::npos; at = fuzzy.out.find("faces culled", at + 1)) {
    const std::size_t line = fuzzy.out.rfind(", ", fuzzy.out.rfind(" of ", at)) + 2;
    most = std::max<std::size_t>(most, std::stoul(fuzzy.out.substr(line)));
    ++groups;
  }
  EXPECT_GT(groups, 1u) << fuzzy.out;
  EXPECT_GT(most, 100u) << fuzzy.out;

  // With a JSON output the polygons would change: no culling, and stats.cull says so.
  const Outcome json_run = hlr(args({"-o", out("d.json").string(), "-o", out("d.csv").string()}));
  ASSERT_EQ(json_run.exit_code, 0) << json_run.err;
  EXPECT_EQ(slurp(out("d.csv")), slurp(out("none.csv")));
  const json doc = json::parse(slurp(out("d.json")));
  const json& cull = doc.at("stats").at("cull");
  EXPECT_EQ(cull.at("mode"), "none");
  ASSERT_GT(cull.at("groups").size(), 1u);
  std::size_t lights = 0;
  for (const auto& g : cull.at("groups")) {
    EXPECT_EQ(g.at("culled"), 0);
    EXPECT_EQ(g.at("patches"), 408);
    lights += g.at("lights").at(1).get<std::size_t>() - g.at("lights").at(0).get<std::size_t>() + 1;
  }
  EXPECT_EQ(lights, doc.at("lights").size());
}

TEST_F(CliShadows, BadInputIsOneLineAndNoFile) {
  const std::string o = out("x.json").string();
  expect_failure({"shadows", box(), "--sun", "0,0,0", "-o", o}, 2, "hlr: --sun 0,0,0: ", "zero");
  expect_failure({"shadows", box(), "--sun", "1,nan,-1", "-o", o}, 2, "hlr: --sun 1,nan,-1: ", "not finite");
  expect_failure({"shadows", box(), "--sun", "1,2", "-o", o}, 2, "hlr: --sun 1,2: ");
  expect_failure({"shadows", box(), "-o", o}, 2, "hlr: ", "no light");
  // Point lights: non-finite, malformed, and where nothing can serve: inside the box, on its top
  // face, on the ground.
  expect_failure({"shadows", box(), "--point-light", "0,inf,10", "-o", o}, 2, "hlr: --point-light 0,inf,10: ",
                 "not finite");
  expect_failure({"shadows", box(), "--point-light", "0,10", "-o", o}, 2, "hlr: --point-light 0,10: ");
  for (const auto& [light, why] : std::vector<std::pair<std::string, std::string>>{
           {"1,1,1", "inside a closed solid of " + box()}, {"1,1,2", "on face 2 of " + box()}, {"5,5,0", "on face 0 of " + box()}})
    expect_failure({"shadows", box(), "--sun", "1,2,-4", "--point-light", light, "-o", o, "-o", out("x.svg").string()},
                   2, "hlr: --point-light " + light + ": ", why);
  expect_failure({"shadows", box(), "--sun-at", "2026-06-21T09:00", "-o", o}, 2, "hlr: --sun-at", "--site");
  expect_failure({"shadows", box(), "--sun-at", "2026-06-21T09:00", "--site", "91,0", "-o", o}, 2, "hlr: --site 91,0: ",
                 "latitude");
  expect_failure({"shadows", box(), "--sun-at", "2026-06-21T09:00", "--site", "0,181", "-o", o}, 2,
                 "hlr: --site 0,181: ", "longitude");
  expect_failure({"shadows", box(), "--sun-at", "2026-02-30T09:00", "--site", "0,0", "-o", o}, 2,
                 "hlr: --sun-at 2026-02-30T09:00: ", "no such date");
  expect_failure({"shadows", box(), "--sun-at", "noon", "--site", "0,0", "-o", o}, 2, "hlr: --sun-at noon: ");
  expect_failure({"shadows", box(), "--sun-at", "2026-06-21T09:00/15:00/PT0M", "--site", "0,0", "-o", o}, 2,
                 "hlr: --sun-at", "zero");
  // Midnight in Sydney: below the horizon, an error naming the time.
  expect_failure({"shadows", box(), "--sun-at", "2026-06-21T00:00+10:00", "--site", "-33.86,151.21", "-o", o}, 1,
                 "hlr: --sun-at 2026-06-21T00:00+10:00: ", "below the horizon");
  expect_failure({"shadows", box(), "--sun", "1,2,-4", "-o", out("x.txt").string()}, 1, "hlr: " + out("x.txt").string());
  expect_failure({"shadows", (dir_ / "missing.off").string(), "--sun", "1,2,-4", "-o", o}, 1,
                 "hlr: " + (dir_ / "missing.off").string());
  // Every output is opened before the lights are solved: one that cannot be written stops the run
  // at once, and the others are not written either.
  const std::string unwritable = (dir_ / "no-such-dir" / "x.csv").string();
  expect_failure({"shadows", box(), "--sun", "1,2,-4", "-o", o, "-o", unwritable}, 1, "hlr: " + unwritable,
                 "cannot write");
  expect_failure({"shadows", box(), "--sun", "1,2,-4", "--threads", "-1", "-o", o}, 2, "hlr: ", "--threads");
}

TEST_F(CliShadows, OneThreadAndTwoGiveTheSameResult) {
  // Enough sources for the light view's area sort to run in parallel strips.
  const fs::path mesh = fs::path(HLR_SHARED_SCENES) / "couplingdown.off";
  if (!fs::exists(mesh)) GTEST_SKIP() << "no " << mesh;
  std::string csv[2];
  json doc[2];
  for (int t = 0; t < 2; ++t) {
    const std::string tag = std::to_string(t + 1);
    const Outcome run = hlr({"shadows", mesh.string(), "--sun", "1,2,-4", "--sun", "0.3,-1,-0.5", "--threads", tag, "-o",
                             out(tag + ".json").string(), "-o", out(tag + ".csv").string()});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    csv[t] = slurp(out(tag + ".csv"));
    doc[t] = json::parse(slurp(out(tag + ".json")));
    doc[t].erase("stats");
  }
  EXPECT_EQ(csv[0], csv[1]);
  EXPECT_TRUE(doc[0] == doc[1]);
}

TEST_F(CliShadows, DrawWithSunFillsTheShadowsAndIsTheGoldenFile) {
  // Regenerate: hlr draw fixtures/shadows/box_on_ground.off --view iso --sun 1,2,-4
  //   -o tests/golden/shadows/box_on_ground_iso_sun.svg -o tests/golden/shadows/box_on_ground_iso_sun.dxf
  const Outcome run = hlr({"draw", box(), "--view", "iso", "--sun", "1,2,-4", "-o", out("d.svg").string(), "-o",
                           out("d.dxf").string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const std::string svg = slurp(out("d.svg")), dxf = slurp(out("d.dxf"));
  EXPECT_NE(svg.find("<g id=\"shadows\" fill=\"#d1d1d1\" stroke=\"none\""), std::string::npos);
  EXPECT_NE(dxf.find("HATCH"), std::string::npos);
  EXPECT_NE(dxf.find("SHADOW"), std::string::npos);
  EXPECT_EQ(svg, slurp(kGolden / "box_on_ground_iso_sun.svg"));
  EXPECT_EQ(dxf, slurp(kGolden / "box_on_ground_iso_sun.dxf"));
  // Without --sun: no shadow group, no SHADOW layer.
  ASSERT_EQ(hlr({"draw", box(), "--view", "iso", "-o", out("p.svg").string(), "-o", out("p.dxf").string()}).exit_code, 0);
  EXPECT_EQ(slurp(out("p.svg")).find("shadows"), std::string::npos);
  EXPECT_EQ(slurp(out("p.dxf")).find("SHADOW"), std::string::npos);
}

TEST_F(CliShadows, DrawWithPointLightFillsTheShadowsAndIsTheGoldenFile) {
  // Regenerate (and review the diff) with
  //   hlr draw fixtures/shadows/box_on_ground.off --view top --point-light 1,-4,4
  //   -o tests/golden/shadows/box_on_ground_top_point_light.svg -o tests/golden/shadows/box_on_ground_top_point_light.dxf
  const Outcome run = hlr({"draw", box(), "--view", "top", "--point-light", "1,-4,4", "-o", out("d.svg").string(), "-o",
                           out("d.dxf").string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const std::string svg = slurp(out("d.svg")), dxf = slurp(out("d.dxf"));
  EXPECT_NE(svg.find("<g id=\"shadows\" fill=\"#d1d1d1\" stroke=\"none\""), std::string::npos);
  EXPECT_NE(dxf.find("SHADOW"), std::string::npos);
  EXPECT_EQ(svg, slurp(kGolden / "box_on_ground_top_point_light.svg"));
  EXPECT_EQ(dxf, slurp(kGolden / "box_on_ground_top_point_light.dxf"));
  // Seen from above, the ground's shadow differs from the sun's: not the same drawing.
  ASSERT_EQ(hlr({"draw", box(), "--view", "top", "--sun", "1,2,-4", "-o", out("s.svg").string()}).exit_code, 0);
  EXPECT_NE(svg, slurp(out("s.svg")));
}

TEST_F(CliShadows, DrawSunMistakes) {
  expect_failure({"draw", box(), "--view", "iso", "--sun", "0,0,0", "-o", out("x.svg").string()}, 2, "hlr: --sun 0,0,0: ");
  expect_failure({"draw", box(), "--view", "iso", "--sun", "1,2,-4", "--kernel", "epick", "-o", out("x.svg").string()},
                 2, "hlr: --sun 1,2,-4: ", "exact path only");
  expect_failure({"draw", box(), "--view", "iso", "--point-light", "1,1,1", "-o", out("x.svg").string()}, 2,
                 "hlr: --point-light 1,1,1: ", "inside a closed solid");
  expect_failure({"draw", box(), "--view", "iso", "--point-light", "1,-4,4", "--raster", "64", "-o",
                  out("x.svg").string()},
                 2, "hlr: --point-light 1,-4,4: ", "exact path only");
}

// hlr check --sun/--point-light: the exact lit areas against the raster shadow map.
TEST_F(CliShadows, CheckComparesTheShadowMapAndItConverges) {
  const Outcome run = hlr({"check", box(), "--sun", "1,2,-4", "--point-light", "1,-4,4", "--raster", "64,512", "--json",
                           out("c.json").string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(outputs(), std::vector<std::string>{"c.json"});
  EXPECT_NE(run.out.find("raster 64, sun 1,2,-4: lit area "), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("raster 512, point light 1,-4,4: lit area "), std::string::npos) << run.out;
  EXPECT_NE(run.out.rfind("check: raster 64 misses "), std::string::npos) << run.out;  // the coarser map is worse
  const json doc = json::parse(slurp(out("c.json")));
  EXPECT_EQ(doc.at("format"), "hlr-check/1");
  ASSERT_EQ(doc.at("lights").size(), 2u);
  EXPECT_EQ(doc.at("lights").at(1).at("type"), "point");
  // The exact lit areas of fixtures/shadows/README.md: 393 + 3 * 4 under the sun, 372 + 2 * 4 under the light.
  EXPECT_NEAR(doc.at("reference").at("lit_area").at(0).get<double>(), 405, 1e-9);
  EXPECT_NEAR(doc.at("reference").at("lit_area").at(1).get<double>(), 380, 1e-9);
  EXPECT_NEAR(doc.at("reference").at("area").get<double>(), 424, 1e-9);  // 400 + 6 * 4
  const json& methods = doc.at("shadow_methods");
  ASSERT_EQ(methods.size(), 2u);
  EXPECT_EQ(methods.at(0).at("resolution"), 64);
  for (int k = 0; k < 2; ++k) {
    const json& coarse = methods.at(0).at("lights").at(k);
    const json& fine = methods.at(1).at("lights").at(k);
    EXPECT_EQ(coarse.at("faces"), 7);
    EXPECT_EQ(coarse.at("exact_lit_area"), doc.at("reference").at("lit_area").at(k));
    const double e64 = coarse.at("relative_lit_area_error").get<double>(), e512 = fine.at("relative_lit_area_error").get<double>();
    EXPECT_GT(e64, 0.0);
    EXPECT_LT(e512, e64 / 3) << k;
    EXPECT_LT(fine.at("max_fraction_difference").get<double>(), coarse.at("max_fraction_difference").get<double>());
    EXPECT_EQ(coarse.at("max_face"), (json{0, 0}));  // the ground: where the shadow edges are
    EXPECT_NEAR(coarse.at("lit_area_error").get<double>(), e64 * 424, 1e-9);
    EXPECT_LE(fine.at("mean_fraction_difference").get<double>(), fine.at("max_fraction_difference").get<double>());
    EXPECT_NEAR(fine.at("raster_lit_area").get<double>(), fine.at("exact_lit_area").get<double>(),
                fine.at("lit_area_error").get<double>() + 1e-9);
    EXPECT_GT(fine.at("samples").get<double>(), 30 * coarse.at("samples").get<double>());
  }
}

TEST_F(CliShadows, CheckShadowMistakes) {
  const std::string o = out("c.json").string();
  expect_failure({"check", box(), "--sun", "0,0,0", "--json", o}, 2, "hlr: --sun 0,0,0: ", "zero");
  expect_failure({"check", box(), "--point-light", "1,1,1", "--json", o}, 2, "hlr: --point-light 1,1,1: ",
                 "inside a closed solid");
  expect_failure({"check", (kShadowFixtures / "light_between_boxes.off").string(), "--point-light", "0,0,1", "--json", o},
                 2, "hlr: --point-light 0,0,1: ", "among the geometry");
  expect_failure({"check", box(), "--sun", "1,2,-4", "--view", "top", "--json", o}, 2, "hlr: --sun 1,2,-4: ", "no view");
  expect_failure({"check", box(), "--sun", "1,2,-4", "--kernels", "epick", "--json", o}, 2, "hlr: --kernels: ");
  expect_failure({"check", box(), "--sun", "1,2,-4", "--diff", out("c.png").string()}, 2, "hlr: --diff: ");
  expect_failure({"check", box(), "--sun", "1,2,-4", "--raster", "8", "--json", o}, 2, "hlr: ", "--raster");
  expect_failure({"check", box(), "--sun", "1,2,-4", "--json", out("c.txt").string()}, 1, "hlr: " + out("c.txt").string());
}

TEST_F(CliShadows, HelpShowsAnExample) {
  const Outcome run = hlr({"shadows", "--help"});
  EXPECT_EQ(run.exit_code, 0);
  EXPECT_NE(run.out.find("hlr shadows fixtures/shadows/box_on_ground.off --sun 1,2,-4"), std::string::npos) << run.out;
}

}  // namespace
