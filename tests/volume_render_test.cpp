// Volume scenes through the renderer (render/volume_cast.hpp): the split over chips gives the
// single chip's frame bit for bit; early termination changes a pixel by at most the threshold's
// share and saves resamples; the segment length changes nothing but the unit's work; the golden
// frame is near the ideal's; the hls and rtl engines (the co-simulated block) give golden's frame
// and counters, checked piece by piece.
#include "render/volume_render.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "common/error.hpp"
#include "render/volume_cast.hpp"
#include "render/volume_engine_block.hpp"
#include "volume/volume_data.hpp"
#include "volume/volume_scene.hpp"

namespace tmu::render {
namespace {

// A small scene: 24 x 20 x 28 voxels (sides that do not divide evenly), 40 x 32 pixels.
host::VolumeScene scene_of(const std::string& field, const std::string& format,
                           const std::string& extra = "") {
  const std::string text = R"({
    "volume": {
      "data": {"field": ")" +
                           field + R"(", "size": [24, 20, 28]},
      "format": ")" + format +
                           R"(",
      "transfer": [{"value": 0, "colour": [0.2, 0.4, 1], "opacity": 0},
                   {"value": 110, "colour": [0.2, 0.4, 1], "opacity": 0.05},
                   {"value": 140, "colour": [1, 0.8, 0.3], "opacity": 0.7}],
      "step": 0.7)" + extra +
                           R"(
    },
    "camera": {"position": [1.5, -2.2, 1.4], "target": [0, 0, 0], "up": [0, 0, 1], "fov": 45,
               "resolution": [40, 32]},
    "background": [0.1, 0.2, 0.3])" +
                           (format == "raw" ? R"(,
    "lights": [{"type": "ambient", "colour": [0.3, 0.3, 0.3]},
               {"type": "directional", "direction": [-1, 1, -1], "colour": [0.7, 0.7, 0.7]}])"
                                            : "") +
                           "}";
  return host::parse_volume_scene(text, "test.json", ".");
}

VolumeFrame render(const host::VolumeScene& s, Level level, int chips) {
  return cast_volume(s, host::volume_grids(s), set_up_rays(s), {level, chips, nullptr});
}

TEST(VolumeRenderTest, SlabsGiveTheSingleChipFrameBitForBit) {
  for (const char* format : {"raw", "rgba"}) {
    for (const char* axis : {"x", "y", "z"}) {
      const host::VolumeScene s =
          scene_of("engine", format, std::string(R"(, "slab_axis": ")") + axis + "\"");
      const VolumeFrame one = render(s, Level::kGolden, 1);
      for (int chips : {2, 3, 4}) {
        const VolumeFrame split = render(s, Level::kGolden, chips);
        EXPECT_EQ(split.pixels, one.pixels) << format << " axis " << axis << " chips " << chips;
        EXPECT_EQ(split.chips.size(), static_cast<size_t>(chips));
        EXPECT_EQ(split.issued, one.issued);
        EXPECT_EQ(split.total.resamples, one.total.resamples);
        EXPECT_EQ(split.total.accesses, one.total.accesses);  // a resample's accesses are fixed
      }
      EXPECT_GT(one.composited, 1000u);
    }
  }
}

TEST(VolumeRenderTest, EarlyTerminationWithinItsThresholdAndCheaper) {
  for (const char* format : {"raw", "rgba"}) {
    const host::VolumeScene none =
        scene_of("marschner_lobb", format, R"(, "early_termination": false)");
    const VolumeFrame full = render(none, Level::kGolden, 1);
    EXPECT_EQ(full.rounds, 1u);
    EXPECT_EQ(full.issued, full.locations);
    for (double t : {0.9, 255.0 / 256}) {
      const host::VolumeScene s =
          scene_of("marschner_lobb", format,
                   R"(, "early_termination": {"alpha": )" + std::to_string(t) + "}");
      const VolumeFrame stopped = render(s, Level::kGolden, 1);
      EXPECT_GT(stopped.rays_terminated, 0u) << format;
      EXPECT_LT(stopped.issued, full.issued) << format;
      double worst = 0;
      for (size_t i = 0; i < full.pixels.size(); ++i) {
        for (int c = 0; c < 3; ++c)
          worst = std::max(worst, std::abs(full.pixels[i][c] - stopped.pixels[i][c]));
      }
      EXPECT_LE(worst, 1 - std::stod(std::to_string(t)) + 1e-12) << format << " t " << t;
      EXPECT_GT(worst, 0) << format;  // it did stop something that mattered
      // At 255/256 the 8-bit images differ by at most one level.
      if (t > 0.99) {
        const ImageRgb8 a = volume_image(full), b = volume_image(stopped);
        for (size_t i = 0; i < a.pixels.size(); ++i) {
          EXPECT_LE(std::abs(a.pixels[i].r - b.pixels[i].r), 1);
          EXPECT_LE(std::abs(a.pixels[i].g - b.pixels[i].g), 1);
          EXPECT_LE(std::abs(a.pixels[i].b - b.pixels[i].b), 1);
        }
      }
    }
  }
}

TEST(VolumeRenderTest, TheSegmentChangesOnlyTheUnitsWork) {
  const VolumeFrame a = render(
      scene_of("sphere", "raw", R"(, "early_termination": {"segment": 1})"), Level::kGolden, 1);
  const VolumeFrame b = render(
      scene_of("sphere", "raw", R"(, "early_termination": {"segment": 64})"), Level::kGolden, 2);
  EXPECT_EQ(a.pixels, b.pixels);
  EXPECT_EQ(a.composited, b.composited);
  EXPECT_EQ(a.issued, a.composited);  // one location at a time: nothing resampled in vain
  EXPECT_GT(b.issued, a.issued);
}

TEST(VolumeRenderTest, GoldenIsNearTheIdeal) {
  const host::VolumeScene s = scene_of("marschner_lobb", "raw");
  const ImageRgb8 golden = volume_image(render(s, Level::kGolden, 1));
  const ImageRgb8 ideal = volume_image(render(s, Level::kIdeal, 1));
  EXPECT_GT(psnr(golden, ideal), 35);
  EXPECT_TRUE(std::isinf(psnr(ideal, volume_image(render(s, Level::kIdeal, 4)))));
  const VolumeFrame f = render(s, Level::kGolden, 1);
  EXPECT_TRUE(f.has_memory);
  EXPECT_EQ(f.total.accesses, 8 * f.total.resamples);  // raw mode: eight accesses
  EXPECT_EQ(f.total.resamples, f.issued);
  const VolumeFrame rgba = render(scene_of("marschner_lobb", "rgba"), Level::kGolden, 1);
  EXPECT_EQ(rgba.total.resamples, 4 * rgba.issued);  // a resample a component
  EXPECT_EQ(rgba.total.accesses, 2 * rgba.total.resamples);
}

// The co-simulated unit (render/volume_engine_block.hpp) renders the frame golden renders: every
// resample equal, every chip's counters equal to golden's one long run although the block ran
// in pieces (the open pages carried from piece to piece), and every piece equal to the golden
// block's unit by unit (outputs, memory requests, counters).
VolumeFrame checked(const host::VolumeScene& s, Level level, int chips,
                    std::vector<VolumeSample>* record, int64_t fault = -1) {
  VolumeCastOptions o{level, chips, record};
  o.check_units = Level::kGolden;
  o.inject_fault = fault;
  return cast_volume(s, host::volume_grids(s), set_up_rays(s), o);
}

TEST(VolumeRenderTest, RtlRendersTheGoldenFrameInPieces) {
  // Without early termination a chip's round is the whole frame: several pieces of at most
  // kVolumePieceResamples; with it, many rounds of short runs.
  for (const char* extra : {R"(, "early_termination": false)", ""}) {
    for (const char* format : {"raw", "rgba"}) {
      const host::VolumeScene s = scene_of("engine", format, extra);
      for (int chips : {1, 3}) {
        std::vector<VolumeSample> want, got;
        const VolumeFrame g =
            cast_volume(s, host::volume_grids(s), set_up_rays(s), {Level::kGolden, chips, &want});
        const VolumeFrame r = checked(s, Level::kRtl, chips, &got);
        const std::string what = std::string(format) + extra + " chips " + std::to_string(chips);
        EXPECT_EQ(got, want) << what;
        EXPECT_EQ(r.pixels, g.pixels) << what;
        ASSERT_EQ(r.chips.size(), g.chips.size());
        for (size_t c = 0; c < r.chips.size(); ++c) {
          EXPECT_EQ(r.chips[c], g.chips[c]) << what << " chip " << c;
          EXPECT_GT(r.chips[c].page_faults, 0u);
          // Clocked: the accesses and their extra fault periods, plus each run's reset,
          // configuration and drain (under 40 cycles a run).
          EXPECT_GE(r.chip_cycles[c], r.chips[c].accesses + r.chips[c].slow_accesses);
        }
        ASSERT_TRUE(r.unit_check.has_value());
        EXPECT_TRUE(r.unit_check->match()) << what << ": " << r.unit_check->first.front();
        EXPECT_EQ(r.unit_check->pieces, r.pieces);
        EXPECT_EQ(r.unit_check->outputs, r.total.resamples);
        EXPECT_EQ(r.unit_check->requests, r.total.accesses);
        // At least a run per round of each chip's component that had work, and a run per
        // kVolumePieceResamples of it (the raw scene without early termination on one chip
        // takes several: AnInjectedFaultIsCaught asserts it).
        const uint64_t components = std::string(format) == "raw" ? 1 : 4;
        uint64_t least = 0;
        for (const VolumeCounters& k : r.chips)
          least += components *
                   ((k.resamples / components + kVolumePieceResamples - 1) / kVolumePieceResamples);
        EXPECT_GE(r.pieces, least) << what;
        EXPECT_GE(r.pieces, r.rounds) << what;
      }
    }
  }
}

TEST(VolumeRenderTest, HlsRendersTheGoldenFrame) {
  const host::VolumeScene s = scene_of("sphere", "raw", R"(, "early_termination": false)");
  std::vector<VolumeSample> want, got;
  const VolumeFrame g =
      cast_volume(s, host::volume_grids(s), set_up_rays(s), {Level::kGolden, 2, &want});
  const VolumeFrame h = checked(s, Level::kHls, 2, &got);
  EXPECT_EQ(got, want);
  EXPECT_EQ(h.chips, g.chips);
  ASSERT_TRUE(h.unit_check.has_value());
  EXPECT_TRUE(h.unit_check->match());
  EXPECT_GE(h.pieces, 2u);
}

// An output flipped on purpose is caught twice: by the frame's resamples and by its piece's
// comparison with the golden block.
TEST(VolumeRenderTest, AnInjectedFaultIsCaught) {
  const host::VolumeScene s = scene_of("engine", "raw", R"(, "early_termination": false)");
  std::vector<VolumeSample> want, got;
  cast_volume(s, host::volume_grids(s), set_up_rays(s), {Level::kGolden, 1, &want});
  ASSERT_GT(want.size(), kVolumePieceResamples);              // more than one piece
  const auto fault = static_cast<int64_t>(want.size() - 10);  // in the last piece
  const VolumeFrame r = checked(s, Level::kRtl, 1, &got, fault);
  ASSERT_EQ(got.size(), want.size());
  size_t differing = 0;
  for (size_t i = 0; i < got.size(); ++i) differing += !(got[i] == want[i]);
  EXPECT_EQ(differing, 1u);
  EXPECT_EQ(std::abs(got[fault].value - want[fault].value), 1.0);
  ASSERT_TRUE(r.unit_check.has_value());
  EXPECT_EQ(r.unit_check->differing_pieces, 1u);
  ASSERT_FALSE(r.unit_check->first.empty());
  EXPECT_NE(r.unit_check->first.front().find(fmt::format("piece {}: 1 of", r.pieces - 1)),
            std::string::npos)
      << r.unit_check->first.front();
  EXPECT_NE(r.unit_check->first.front().find("(value)"), std::string::npos);
}

// `texsim volume-gen`'s file and the scene's field are the same voxels: the same frame.
TEST(VolumeRenderTest, AFileOfTheFieldRendersAsTheField) {
  const host::VolumeScene field = scene_of("engine", "raw");
  const auto dir =
      std::filesystem::temp_directory_path() / ("tmu_volume_file_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const volume::VoxelGrid g = host::field_values(field.data);
  {
    std::ofstream f(dir / "engine.raw", std::ios::binary);
    f.write(reinterpret_cast<const char*>(g.voxels.data()),
            static_cast<std::streamsize>(g.voxels.size()));
  }
  host::VolumeScene file = field;
  file.data.field = host::VolumeData::Field::kFile;
  file.data.file = (dir / "engine.raw").string();
  EXPECT_EQ(render(file, Level::kGolden, 1).pixels, render(field, Level::kGolden, 1).pixels);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace tmu::render
