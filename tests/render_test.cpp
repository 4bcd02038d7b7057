// Rendering scenes: only the units a scene calls for are built and clocked; traces replay bit
// for bit; bands merge into the whole frame; --check catches an altered result; bad materials
// name their field.
#include "render/render.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "common/error.hpp"
#include "common/image.hpp"
#include "render/tiles.hpp"
#include "tests/cosim_test_support.hpp"

namespace tmu::render {
namespace {

const std::string kScenes = std::string(TMU_SOURCE_DIR) + "/scenes/";

RenderOptions options(Level level, const std::string& out) {
  RenderOptions o;
  o.level = level;
  o.out_dir = (tb::testing::temp_dir("tmu_render_test") / out).string();
  o.progress = false;
  return o;
}

RenderReport render(const std::string& scene, const RenderOptions& o, int expect_exit = 0) {
  std::stringstream log;
  RenderReport rep;
  EXPECT_EQ(render_scene(kScenes + scene, o, log, &rep), expect_exit) << log.str();
  return rep;
}

ImageRgb8 picture(const RenderOptions& o) { return read_image(o.out_dir + "/render.png"); }

bool has_kind(const RenderReport& r, const std::string& kind) {
  for (const UnitReport& u : r.units) {
    if (u.kind == kind) return true;
  }
  return false;
}

// The plain scene and the everything scene have the same frame and objects; the plain one
// uses plain textures only, so no mipmap generator, low-cost unit or footprint unit is built
// or clocked, and it takes fewer simulated cycles. (Cycles, not wall time: tests never time
// themselves.)
TEST(RenderTest, PlainSceneBuildsAndClocksOnlyTheTrilinearUnits) {
  reset_census();
  const RenderReport plain = render("plain.json", options(Level::kRtl, "plain"));
  EXPECT_EQ(census("mipgen").built, 0u);
  EXPECT_EQ(census("mipgen").cycles, 0u);
  EXPECT_EQ(census("lowcost").built, 0u);
  EXPECT_EQ(census("lowcost").cycles, 0u);
  EXPECT_EQ(census("footprint").built, 0u);
  EXPECT_EQ(census("footprint").cycles, 0u);
  EXPECT_GT(census("trilinear").built, 0u);
  for (const UnitReport& u : plain.units) EXPECT_EQ(u.kind, "trilinear") << u.name;

  reset_census();
  const RenderReport all = render("everything.json", options(Level::kRtl, "everything"));
  EXPECT_GT(census("mipgen").cycles, 0u);
  EXPECT_GT(census("lowcost").cycles, 0u);
  EXPECT_GT(census("footprint").cycles, 0u);
  EXPECT_TRUE(has_kind(all, "mipgen") && has_kind(all, "lowcost") && has_kind(all, "footprint"));
  EXPECT_EQ(plain.pixels, all.pixels);
  EXPECT_LT(plain.unit_cycles(), all.unit_cycles());
  std::cout << "plain scene: " << plain.unit_cycles()
            << " cycles; everything: " << all.unit_cycles() << " cycles\n";
}

TEST(RenderTest, RtlMatchesGoldenOnTheDefaultScene) {
  RenderOptions o = options(Level::kRtl, "default_rtl");
  o.check = Level::kGolden;
  const RenderReport r = render("default.json", o);
  ASSERT_TRUE(r.check.has_value());
  EXPECT_EQ(r.check->differing, 0u);
  EXPECT_GT(r.check->compared, 10000u);
}

TEST(RenderTest, TraceReplaysBitForBit) {
  RenderOptions save = options(Level::kGolden, "trace_save");
  save.save_trace = save.out_dir + "/default.trace.csv";
  render("default.json", save);
  RenderOptions replay = options(Level::kRtl, "trace_replay");
  replay.replay_trace = save.save_trace;
  replay.check = Level::kGolden;
  const RenderReport r = render("default.json", replay);
  EXPECT_EQ(r.check->differing, 0u);
  EXPECT_EQ(picture(replay), picture(save));
}

TEST(RenderTest, BandsMergeIntoTheWholeFrame) {
  const RenderOptions whole = options(Level::kGolden, "whole");
  render("default.json", whole);
  std::vector<std::string> bands;
  for (int i = 2; i >= 0; --i) {  // any order
    RenderOptions o = options(Level::kGolden, "band");
    o.tile = i;
    o.tiles = 3;
    render("default.json", o);
    bands.push_back(o.out_dir + "/render.tile-" + std::to_string(i) + "-of-3.png");
  }
  EXPECT_EQ(merge_bands(bands), picture(whole));
  bands.pop_back();  // one band missing
  EXPECT_THROW(merge_bands(bands), InputError);
}

TEST(RenderTest, CheckCatchesAnAlteredResult) {
  RenderOptions o = options(Level::kHls, "altered");
  o.check = Level::kGolden;
  o.inject_fault = 1234;
  const RenderReport r = render("plain.json", o, 1);
  ASSERT_TRUE(r.check.has_value());
  EXPECT_EQ(r.check->differing, 1u);
  EXPECT_TRUE(std::filesystem::exists(o.out_dir + "/render.check-diff.png"));
  EXPECT_NE(r.text().find("MISMATCH: 1 of"), std::string::npos);
}

TEST(RenderTest, CompareIdealReportsPsnr) {
  RenderOptions o = options(Level::kGolden, "compare");
  o.compare_ideal = true;
  const RenderReport r = render("plain.json", o);
  ASSERT_TRUE(r.compare.has_value());
  EXPECT_GT(r.compare->psnr, 40.0);  // golden within about a level of the ideal engine
  EXPECT_TRUE(std::filesystem::exists(o.out_dir + "/render.compare-error.png"));
}

TEST(RenderTest, MaterialTextureErrorsNameTheField) {
  const auto dir = tb::testing::temp_dir("tmu_render_bad");
  write_image((dir / "odd.png").string(), ImageRgb8(37, 21));
  std::ofstream(dir / "bad.json")
      << R"({"camera": {"position": [0, 1, 3], "target": [0, 0, 0], "up": [0, 1, 0],
    "fov": 50, "resolution": [32, 24]}, "materials": {"m": {"texture": {"image": "odd.png"}}},
    "objects": [{"type": "plane", "material": "m"}]})";
  std::stringstream log;
  try {
    render_scene((dir / "bad.json").string(), options(Level::kGolden, "bad"), log);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "materials.m.texture.image");
    EXPECT_NE(std::string(e.what()).find("powers of two"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace tmu::render
