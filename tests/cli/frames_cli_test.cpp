// End-to-end tests of `hlr frames`: every frame is the drawing `hlr draw --eye E --target T` makes,
// the fuzzy culling changes no output byte (but stats), the orbit and its progress lines, and bad
// input: one line on stderr, exit code 2, no output file.
#include "cli_support.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using namespace hlr::cli_test;

const std::string kBinary = HLR_BINARY;
const fs::path kScenes = HLR_SCENE_FIXTURES;
const fs::path kShared = HLR_SHARED_SCENES;

// An OFF file of closed, outward boxes (corner c has bits x, y, z).
struct Box {
  double x0, y0, z0, x1, y1, z1;
};
std::string boxes_off(const std::vector<Box>& boxes) {
  std::ostringstream off;
  off << "OFF\n" << 8 * boxes.size() << ' ' << 6 * boxes.size() << " 0\n";
  for (const Box& b : boxes)
    for (int c = 0; c < 8; ++c) off << (c & 1 ? b.x1 : b.x0) << ' ' << (c & 2 ? b.y1 : b.y0) << ' ' << (c & 4 ? b.z1 : b.z0) << '\n';
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    const std::size_t o = 8 * i;
    const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (const auto& q : quads) off << "4 " << o + q[0] << ' ' << o + q[1] << ' ' << o + q[2] << ' ' << o + q[3] << '\n';
  }
  return off.str();
}

// A wall (a closed box 10 x 0.2 x 5) in front of three small boxes that no eye near (0, -10, 2)
// sees, and one box beside the wall that every eye sees: the fuzzy culling has work to do.
std::string wall_scene() {
  return boxes_off({{-5, 0, 0, 5, 0.2, 5}, {-1, 2, 0.5, 0, 3, 1.5}, {1, 2.5, 1, 2, 3.5, 2}, {-3, 4, 0, -2, 5, 3},
                    {7, 1, 0, 8, 2, 1}});
}

// A wall 8 m wide with a box behind it, and a box far away that makes the scene's diagonal long
// enough (a tenth of it: 6.1 m) for the eyes, in two clusters 5 m apart, to form one group. Over
// the group's box the umbra of the wall is narrower than the box behind it, and nothing useful is
// culled; each cluster alone has the box behind the wall culled.
std::string split_scene() {
  return boxes_off({{-4, 0, 0, 4, 0.2, 4}, {-0.5, 1, 1, 0.5, 2, 2}, {40, 40, 0, 41, 41, 1}});
}
// Clusters A (frames 0, 2, 4) and B (frames 1, 3), interleaved: the parts are not consecutive.
const char* kSplitEyes = "-2.5 -10 2\n2.5 -10 2\n-2.45 -10 2.05\n2.55 -10 2.05\n-2.5 -9.95 2\n";

class CliFrames : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = make_temp_dir("hlr-frames-test", {"out", "logs", "in"});
    ASSERT_FALSE(dir_.empty());
  }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
  fs::path out(const std::string& name) const { return dir_ / "out" / name; }
  fs::path input(const std::string& name, const std::string& text) const {
    const fs::path p = dir_ / "in" / name;
    spit(p, text);
    return p;
  }
  std::vector<std::string> outputs() const { return entries(dir_ / "out"); }

  Outcome hlr(std::vector<std::string> args) const {
    args.insert(args.begin(), kBinary);
    return run_process(std::move(args), dir_ / "logs");
  }

  void expect_failure(const std::vector<std::string>& args, const std::string& prefix) const {
    SCOPED_TRACE(::testing::PrintToString(args));
    const Outcome run = hlr(args);
    EXPECT_EQ(run.exit_code, 2) << run.err;
    EXPECT_EQ(count_lines(run.err), 1u) << run.err;
    EXPECT_EQ(run.err.rfind(prefix, 0), 0u) << run.err;
    EXPECT_TRUE(outputs().empty()) << run.err;
  }

  fs::path dir_;
};

json without_stats(json doc) {
  doc.erase("stats");
  return doc;
}

TEST_F(CliFrames, EveryFrameIsTheDrawingOfItsEye) {
  const std::string mesh = (kScenes / "l_bracket.off").string();
  const std::vector<std::string> eyes{"6 -5 4", "-4 -6 3", "1.5 7 5.5"};
  std::string file = "# three eyes\n\n";
  for (const auto& e : eyes) file += e + "\n";
  const fs::path eyes_file = input("eyes.txt", file);
  const Outcome run = hlr({"frames", mesh, "--eyes", eyes_file.string(), "--target", "1,1,1", "-o",
                           (dir_ / "out" / "f%02d.json").string(), "-o", (dir_ / "out" / "f%02d.svg").string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(outputs(), (std::vector<std::string>{"f00.json", "f00.svg", "f01.json", "f01.svg", "f02.json", "f02.svg"}));
  for (std::size_t i = 0; i < eyes.size(); ++i) {
    std::string eye = eyes[i];
    for (char& c : eye) c = c == ' ' ? ',' : c;
    const std::string name = "d" + std::to_string(i) + ".json";
    const Outcome draw = hlr({"draw", mesh, "--eye", eye, "--target", "1,1,1", "-o", out(name).string()});
    ASSERT_EQ(draw.exit_code, 0) << draw.err;
    const std::string frame_name = "f0" + std::to_string(i) + ".json";
    const json frame = json::parse(slurp(out(frame_name)));
    EXPECT_EQ(without_stats(frame), without_stats(json::parse(slurp(out(name))))) << frame_name;
    const json& cull = frame.at("stats").at("cull");
    EXPECT_EQ(cull.at("patches"), 11u);  // l_bracket's faces
    EXPECT_TRUE(cull.contains("group") && cull.contains("culled") && cull.contains("fuzzy_seconds"));
    fs::remove(out(name));
    // One scale on every frame's sheet (the title block names the sheet's scale).
    const std::string svg = slurp(out("f0" + std::to_string(i) + ".svg"));
    EXPECT_NE(svg.find("NTS (perspective)"), std::string::npos);
  }
  EXPECT_NE(run.out.find("3 frames in 3 groups"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("sheets at one scale"), std::string::npos) << run.out;
}

TEST_F(CliFrames, FuzzyCullingChangesNoByteButTheStats) {
  const fs::path mesh = input("wall.off", wall_scene());
  // Five eyes in a small box in front of the wall (Lim's set-up), looking at it.
  const fs::path eyes = input("eyes.txt", "0 -10 2\n0.2 -10 2\n0 -10.2 2.1\n0.1 -9.9 1.9\n0.2 -10.1 2.2\n");
  for (const std::string cull : {"fuzzy", "none"}) {
    const Outcome run = hlr({"frames", mesh.string(), "--eyes", eyes.string(), "--target", "0,0,2", "--cull", cull,
                             "-o", (dir_ / "out" / (cull + "_%d.json")).string(), "-o",
                             (dir_ / "out" / (cull + "_%d.svg")).string(), "-o", (dir_ / "out" / (cull + "_%d.dxf")).string()});
    ASSERT_EQ(run.exit_code, 0) << run.err;
  }
  for (int i = 0; i < 5; ++i) {
    const std::string n = std::to_string(i);
    const json fuzzy = json::parse(slurp(out("fuzzy_" + n + ".json"))), none = json::parse(slurp(out("none_" + n + ".json")));
    EXPECT_EQ(without_stats(fuzzy).dump(), without_stats(none).dump());
    EXPECT_EQ(slurp(out("fuzzy_" + n + ".svg")), slurp(out("none_" + n + ".svg")));
    EXPECT_EQ(slurp(out("fuzzy_" + n + ".dxf")), slurp(out("none_" + n + ".dxf")));
    const json& cull = fuzzy.at("stats").at("cull");
    EXPECT_EQ(cull.at("group"), 0u);
    EXPECT_EQ(cull.at("patches"), 30u);
    // The wall's back and the three boxes behind it (their faces that do not reach the wall's
    // outline in the box of eyes): at least the 18 faces of the boxes.
    EXPECT_GE(cull.at("culled").get<int>(), 18) << cull;
    EXPECT_EQ(none.at("stats").at("cull").at("culled"), 0u);
    // The culled boxes' edges are hidden lines still.
    std::size_t hidden = 0;
    for (const auto& line : fuzzy.at("lines")) hidden += !line.at("visible").get<bool>();
    EXPECT_GE(hidden, 36u);
  }
}

TEST_F(CliFrames, AGroupTooWideToCullIsSplit) {
  const fs::path mesh = input("split.off", split_scene());
  const fs::path eyes = input("eyes.txt", kSplitEyes);
  std::string summary;
  for (const std::string cull : {"fuzzy", "none"}) {
    const Outcome run = hlr({"frames", mesh.string(), "--eyes", eyes.string(), "--target", "0,0,2", "--cull", cull, "-o",
                             (dir_ / "out" / (cull + "_%d.json")).string(), "-o", (dir_ / "out" / (cull + "_%d.svg")).string()});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    if (cull == "fuzzy") summary = run.out;
  }
  EXPECT_NE(summary.find("5 frames in 1 group"), std::string::npos) << summary;
  EXPECT_NE(summary.find("parts"), std::string::npos) << summary;
  std::vector<std::size_t> part(5);
  for (int i = 0; i < 5; ++i) {
    const std::string n = std::to_string(i);
    const json fuzzy = json::parse(slurp(out("fuzzy_" + n + ".json"))), none = json::parse(slurp(out("none_" + n + ".json")));
    EXPECT_EQ(without_stats(fuzzy).dump(), without_stats(none).dump()) << i;
    EXPECT_EQ(slurp(out("fuzzy_" + n + ".svg")), slurp(out("none_" + n + ".svg"))) << i;
    const json& cull = fuzzy.at("stats").at("cull");
    EXPECT_EQ(cull.at("group"), 0u);
    EXPECT_EQ(cull.at("parts"), 2u) << cull;
    part[i] = cull.at("part").get<std::size_t>();
    // The box behind the wall's faces towards the eyes, beside back faces.
    EXPECT_GE(cull.at("culled").get<int>(), 3) << cull;
    EXPECT_EQ(none.at("stats").at("cull").at("parts"), 1u);
  }
  // The parts are the clusters, numbered by first frame.
  EXPECT_EQ(part, (std::vector<std::size_t>{0, 1, 0, 1, 0}));
}

TEST_F(CliFrames, CullReportSolvesEveryFrameTwiceAndChangesNoByte) {
  const fs::path mesh = input("wall.off", wall_scene());
  const fs::path eyes = input("eyes.txt", "0 -10 2\n0.2 -10 2\n0 -10.2 2.1\n");
  for (const std::string mode : {"report", "none"}) {
    std::vector<std::string> args{"frames", mesh.string(), "--eyes", eyes.string(), "--target", "0,0,2", "--progress", "-o",
                                  (dir_ / "out" / (mode + "_%d.json")).string(), "-o", (dir_ / "out" / (mode + "_%d.svg")).string()};
    if (mode == "report") args.push_back("--cull-report");
    else args.insert(args.end(), {"--cull", "none"});
    const Outcome run = hlr(args);
    ASSERT_EQ(run.exit_code, 0) << run.err;
    if (mode == "report") {
      EXPECT_NE(run.out.find("without culling"), std::string::npos) << run.out;
      EXPECT_NE(run.out.find("saved"), std::string::npos) << run.out;
      EXPECT_NE(run.err.find("without culling (--cull-report)"), std::string::npos) << run.err;
    }
  }
  double saved = 0;
  for (int i = 0; i < 3; ++i) {
    const std::string n = std::to_string(i);
    const json report = json::parse(slurp(out("report_" + n + ".json"))), none = json::parse(slurp(out("none_" + n + ".json")));
    EXPECT_EQ(without_stats(report).dump(), without_stats(none).dump()) << i;
    EXPECT_EQ(slurp(out("report_" + n + ".svg")), slurp(out("none_" + n + ".svg"))) << i;
    const json& cull = report.at("stats").at("cull");
    EXPECT_GT(cull.at("unculled_seconds").get<double>(), 0) << cull;
    // One number for the group, in every frame.
    if (i == 0) saved = cull.at("group_saved_seconds").get<double>();
    EXPECT_EQ(cull.at("group_saved_seconds").get<double>(), saved) << cull;
    EXPECT_FALSE(none.at("stats").at("cull").contains("unculled_seconds"));
  }
}

TEST_F(CliFrames, FuzzyCullingChangesNoByteOnRealScenes) {
  // Orbits of real meshes: every frame its own group, culling what the frame itself hides.
  std::vector<fs::path> meshes{kScenes / "penetrating_boxes.off", kScenes / "stacked_boxes.off",
                               kScenes / "inward_box.off"};
  for (const char* name : {"joint.off", "part.off"})
    if (fs::exists(kShared / name)) meshes.push_back(kShared / name);
  for (const fs::path& mesh : meshes) {
    SCOPED_TRACE(mesh.string());
    for (const std::string cull : {"fuzzy", "none"}) {
      const Outcome run = hlr({"frames", mesh.string(), "--orbit", "3", "--elevation", "35", "--cull", cull, "-o",
                               (dir_ / "out" / (cull + "_%d.json")).string(), "-o", (dir_ / "out" / (cull + "_%d.svg")).string()});
      ASSERT_EQ(run.exit_code, 0) << run.err;
    }
    for (int i = 0; i < 3; ++i) {
      const std::string n = std::to_string(i);
      EXPECT_EQ(without_stats(json::parse(slurp(out("fuzzy_" + n + ".json")))).dump(),
                without_stats(json::parse(slurp(out("none_" + n + ".json")))).dump());
      EXPECT_EQ(slurp(out("fuzzy_" + n + ".svg")), slurp(out("none_" + n + ".svg")));
    }
    for (const auto& name : outputs()) fs::remove(out(name));
  }
}

// PNG frames share one view-plane window: one image size for every frame of an orbit, whose own
// boxes differ (a box off to one side), and the JSON's raster grid is the same in each.
TEST_F(CliFrames, PngFramesShareOneWindow) {
  const fs::path mesh = input("two.off", boxes_off({{0, 0, 0, 1, 1, 1}, {3, 0, 0, 4, 1, 1}}));
  const Outcome run = hlr({"frames", mesh.string(), "--orbit", "3", "--target", "0.5,0.5,0.5", "--raster", "160", "-o",
                           (dir_ / "out" / "f_%d.png").string(), "-o", (dir_ / "out" / "f_%d.json").string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  // Width and height from the PNG's IHDR chunk (big-endian, bytes 16..23).
  auto size = [](const std::string& png) {
    auto be = [&](std::size_t at) {
      return (std::uint32_t(std::uint8_t(png[at])) << 24) | (std::uint32_t(std::uint8_t(png[at + 1])) << 16) |
             (std::uint32_t(std::uint8_t(png[at + 2])) << 8) | std::uint32_t(std::uint8_t(png[at + 3]));
    };
    return std::pair<std::uint32_t, std::uint32_t>{be(16), be(20)};
  };
  const auto first = size(slurp(out("f_0.png")));
  EXPECT_EQ(std::max(first.first, first.second), 160u);
  const json raster0 = json::parse(slurp(out("f_0.json"))).at("raster");
  for (int i = 1; i < 3; ++i) {
    EXPECT_EQ(size(slurp(out("f_" + std::to_string(i) + ".png"))), first) << i;
    EXPECT_EQ(json::parse(slurp(out("f_" + std::to_string(i) + ".json"))).at("raster"), raster0) << i;
  }
}

TEST_F(CliFrames, OrbitReportsEveryFrame) {
  const std::string mesh = (kScenes / "cube.off").string();
  const Outcome run = hlr({"frames", mesh, "--orbit", "4", "--progress", "-o", (dir_ / "out" / "o_%03d.svg").string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(outputs(), (std::vector<std::string>{"o_000.svg", "o_001.svg", "o_002.svg", "o_003.svg"}));
  for (int i = 1; i <= 4; ++i) EXPECT_NE(run.err.find("frame " + std::to_string(i) + " of 4"), std::string::npos) << run.err;
  // The orbit starts on the front side (-Y) and goes round: the first frame is the draw of that eye.
  const Outcome json_run = hlr({"frames", mesh, "--orbit", "4", "--elevation", "0", "--distance", "5", "-o",
                                (dir_ / "out" / "j%d.json").string()});
  ASSERT_EQ(json_run.exit_code, 0) << json_run.err;
  const json first = json::parse(slurp(out("j0.json")));
  const auto eye = first.at("view").at("eye").get<std::vector<double>>();
  EXPECT_NEAR(eye[0], 0.5, 1e-12);
  EXPECT_NEAR(eye[1], -4.5, 1e-12);
  EXPECT_NEAR(eye[2], 0.5, 1e-12);
}

TEST_F(CliFrames, BadInputGivesOneLineAndNoFile) {
  const std::string cube = (kScenes / "cube.off").string();
  const std::string o = (dir_ / "out" / "f%d.json").string();
  auto eyes = [&](const std::string& text) { return input("e.txt", text).string(); };
  expect_failure({"frames", cube, "--eyes", eyes("3 3 3\n0.5 0.5 0.5\n"), "-o", o}, "hlr: --eye 0.5,0.5,0.5 (frame 1): the eye is at the target");
  expect_failure({"frames", cube, "--eyes", eyes("0.5 0.5 0\n"), "--target", "0.5,0.5,3", "-o", o},
                 "hlr: --eye 0.5,0.5,0 (frame 0): the eye lies on face");
  expect_failure({"frames", cube, "--eyes", eyes("0.5 0.5 10\n"), "--target", "0.5,0.5,20", "-o", o},
                 "hlr: --eye 0.5,0.5,10 (frame 0): the whole scene is behind the eye");
  expect_failure({"frames", cube, "--eyes", eyes("3 3 nan\n"), "-o", o}, "hlr: --eyes ");
  expect_failure({"frames", cube, "--eyes", eyes("3 3 1e999\n"), "-o", o}, "hlr: --eyes ");
  expect_failure({"frames", cube, "--eyes", eyes("# nothing\n\n"), "-o", o}, "hlr: --eyes ");
  expect_failure({"frames", cube, "--eyes", eyes("3 3\n"), "-o", o}, "hlr: --eyes ");
  expect_failure({"frames", cube, "--eyes", eyes("3 3 x\n"), "-o", o}, "hlr: --eyes ");
  expect_failure({"frames", cube, "--eyes", (dir_ / "in" / "missing.txt").string(), "-o", o}, "hlr: --eyes ");
  expect_failure({"frames", cube, "--orbit", "3", "-o", (dir_ / "out" / "f.json").string()}, "hlr: -o ");
  expect_failure({"frames", cube, "--orbit", "3", "-o", (dir_ / "out" / "f%d_%d.json").string()}, "hlr: -o ");
  expect_failure({"frames", cube, "--orbit", "3", "-o", (dir_ / "out" / "f%d.png").string()}, "hlr: -o ");
  expect_failure({"frames", cube, "-o", o}, "hlr: --eyes FILE or --orbit N");
  expect_failure({"frames", cube, "--orbit", "3", "--target", "0,0,inf", "-o", o}, "hlr: --target");
}

}  // namespace
