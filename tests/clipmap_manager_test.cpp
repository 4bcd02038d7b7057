// The clip-map's texture memory manager (golden/clipmap/tile_manager.hpp) on a file maketx made:
// its loads build a clip-map whose samples equal the trilinear unit's on the whole pyramid of
// that file where the tiles hold the taps; a frame after any path of frames equals the same
// frame from scratch (the clip-map is a function of the eye); a move of one texel costs one row
// at level 0; a bad file is a clear error. And the generated terrain's file.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <random>

#include "clipmap/terrain.hpp"
#include "clipmap/tile_centre.hpp"
#include "clipmap/tile_manager.hpp"
#include "common/error.hpp"
#include "common/image.hpp"
#include "common/test_patterns.hpp"
#include "texram/texture.hpp"
#include "texram/trilinear.hpp"

namespace tmu::clipmap {
namespace {

namespace fs = std::filesystem;
constexpr int32_t kOne = 256;

// A 2^v x 2^v picture made into a tiled, mip-mapped file by maketx (32 x 32 file tiles).
std::string tiled_file(int log2_side) {
  const fs::path dir = fs::temp_directory_path() / ("tmu_clipmap_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string png = (dir / "terrain.png").string(), tx = (dir / "terrain.tx").string();
  write_image(png, patterns::smooth_field(1 << log2_side, 1 << log2_side, 11));
  const std::string cmd =
      "maketx --filter box --tile 32 32 -o '" + tx + "' '" + png + "' >/dev/null 2>&1";
  if (std::system(cmd.c_str()) != 0) throw std::runtime_error("maketx failed: " + cmd);
  return tx;
}

Config config(texram::TexelKind kind = texram::TexelKind::kLuminance) {
  Config c;
  c.log2_virtual = 8;
  c.log2_tile = 4;
  c.sampler.kind = kind;
  c.sampler.filter = texram::Filter::kTrilinear;
  return c;
}

void apply(ClipMemory& m, Regions& r, const FrameUpdate& u) {
  for (const auto& [level, region] : u.regions) r[static_cast<size_t>(level)] = region;
  for (const Load& l : u.loads) {
    for (const BankAccess& a : load_writes(m.geometry, l)) write(m.banks, a);
  }
}

TEST(ClipmapManagerTest, ItsClipMapSamplesLikeTheWholePyramidOfTheFile) {
  const std::string file = tiled_file(8);
  for (auto kind : {texram::TexelKind::kLuminance, texram::TexelKind::kTrueColour}) {
    const Config c = config(kind);
    TileManager manager(c, file);
    // The whole pyramid of the file, as the trilinear unit holds a texture.
    std::vector<texram::Pyramid8> planes(static_cast<size_t>(c.planes()));
    for (int l = 0; l <= c.log2_virtual; ++l) {
      const uint32_t side = 1u << (c.log2_virtual - l);
      for (auto& p : planes) p.emplace_back(side, side);
      for (uint32_t y = 0; y < side; ++y) {
        for (uint32_t x = 0; x < side; ++x) {
          const uint32_t t = manager.texel(l, x, y);
          for (size_t p = 0; p < planes.size(); ++p) {
            planes[p][static_cast<size_t>(l)].at(x, y) = static_cast<uint8_t>(t >> (24 - 8 * p));
          }
        }
      }
    }
    const texram::TexramTexture full = texram::texture_from_planes(kind, planes);
    ClipMemory m(c.geometry());
    Regions r{};
    std::mt19937_64 rng(2);
    int compared = 0;
    for (int frame = 0; frame < 6; ++frame) {
      const double eu = static_cast<double>(rng() % 256), ev = static_cast<double>(rng() % 256);
      apply(m, r, manager.update(eu, ev));
      for (int i = 0; i < 2000; ++i) {
        const texram::Request q{
            static_cast<int32_t>((eu + static_cast<double>(rng() % 40) - 20) * kOne),
            static_cast<int32_t>((ev + static_cast<double>(rng() % 40) - 20) * kOne),
            static_cast<int32_t>(rng() % (4 * kOne)) - kOne, 0};
        ClipPlan p;
        const uint32_t got = sample(m, c, r, q, &p);
        if (p.wayward) continue;
        ASSERT_EQ(got, texram::sample(full, c.sampler, q)) << "frame " << frame;
        ++compared;
      }
    }
    EXPECT_GT(compared, 3000);
  }
}

TEST(ClipmapManagerTest, AFrameEqualsTheSameFrameFromScratch) {
  const std::string file = tiled_file(8);
  const Config c = config();
  TileManager path(c, file);
  ClipMemory m(c.geometry());
  Regions r{};
  // Small steps, a jump of more than a tile at every level, the virtual texture's edges.
  const double eyes[][2] = {{100, 100}, {101, 100}, {101.5, 99}, {90, 120},    {250, 3},
                            {255, 255}, {0, 0},     {-5, 300},   {128, 127.5}, {20, 200}};
  for (const auto& e : eyes) {
    apply(m, r, path.update(e[0], e[1]));
    TileManager scratch(c, file);
    ClipMemory ms(c.geometry());
    Regions rs{};
    apply(ms, rs, scratch.update(e[0], e[1]));
    ASSERT_EQ(r, rs) << "eye (" << e[0] << ", " << e[1] << ")";
    ASSERT_EQ(m.banks, ms.banks) << "eye (" << e[0] << ", " << e[1] << ")";
    EXPECT_EQ(r, centred_regions(c, e[0], e[1]));
  }
}

TEST(ClipmapManagerTest, OneTexelOfEyeMovementCostsOneRowAtLevelZero) {
  const Config c = config();
  TileManager manager(c, tiled_file(8));
  const FrameUpdate first = manager.update(100.5, 100.5);
  EXPECT_EQ(first.rows[0], 16u);  // the whole tile
  EXPECT_GT(first.file_tiles_read, 0u);
  const FrameUpdate step = manager.update(101.5, 100.5);
  EXPECT_EQ(step.rows[0], 1u);
  EXPECT_EQ(step.loads.size(),
            16u + (step.rows[1] * 16u) + (step.rows[2] * 16u) + (step.rows[3] * 16u));
  const FrameUpdate still = manager.update(101.5, 100.5);
  EXPECT_TRUE(still.loads.empty());
  EXPECT_TRUE(still.regions.empty());
}

TEST(ClipmapManagerTest, AFileItCannotUseIsAClearError) {
  const fs::path dir =
      fs::temp_directory_path() / ("tmu_clipmap_bad_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string png = (dir / "flat.png").string();
  write_image(png, patterns::gradient(256, 256));
  try {
    TileManager(config(), png);
    FAIL() << "a PNG is not a tiled mipmap";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), png);
    EXPECT_NE(std::string(e.what()).find("maketx"), std::string::npos) << e.what();
  }
  Config big = config();
  big.log2_virtual = 9;
  try {
    TileManager(big, tiled_file(8));
    FAIL() << "a 256 file is not a 512 clip-map";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("10 expected"), std::string::npos) << e.what();
  }
  EXPECT_THROW(TileManager(config(), (dir / "missing.tx").string()), InputError);
}

// The generated terrain is streamed in bands of rows to its picture (a 32k terrain would not fit
// in memory whole): the file's level 0 is the picture terrain() makes whole, band after band, a
// band that does not divide the side included; a fill that fails leaves no file.
TEST(ClipmapTerrainTest, TheStreamedPictureIsTheWholeOne) {
  const fs::path dir =
      fs::temp_directory_path() / ("tmu_clipmap_terrain_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string tx = (dir / "t.tx").string();
  write_terrain_mipmap(tx, 7, 5, 32, /*keep_picture=*/true);
  const ImageRgb8 whole = terrain(7, 5);
  EXPECT_EQ(read_image((dir / "t.tif").string()), whole);
  EXPECT_EQ(read_image(tx), whole);  // maketx's level 0

  const std::string bands = (dir / "bands.png").string();
  write_image_rows(bands, 128, 128, 23, [&](int y, int n, Rgb8* rows) {
    for (int i = 0; i < n; ++i)
      std::copy_n(&whole.at(0, y + i), 128, rows + static_cast<size_t>(i) * 128);
  });
  EXPECT_EQ(read_image(bands), whole);

  const std::string failed = (dir / "failed.png").string();
  EXPECT_THROW(write_image_rows(failed, 128, 128, 16,
                                [](int y, int, Rgb8*) {
                                  if (y >= 64) throw InputError("source", "", "cut off");
                                }),
               InputError);
  EXPECT_FALSE(fs::exists(failed));
}

}  // namespace
}  // namespace tmu::clipmap
