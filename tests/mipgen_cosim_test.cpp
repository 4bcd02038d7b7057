// The TEXRAM mipmap generator: golden vs hls vs rtl, bit for bit, on random and directed frames
// of every kind of format (interlaced, non-square, 1 x 1, 1024-texel lines), under heavy
// back-pressure and at full throughput; the cells the rtl writes read back through the layout
// as build_pyramid; and proof that the comparison has teeth (a mutant rounding).
#include <Vtmu_mipgen.h>
#include <Vtmu_mipgen_mutant_round.h>
#include <gtest/gtest.h>
#include <verilated.h>

#include <iostream>
#include <memory>
#include <random>
#include <sstream>
#include <tuple>

#include "blocks/mipgen_block.hpp"
#include "formats/formats.hpp"
#include "harness/cosim.hpp"
#include "tests/cosim_test_support.hpp"
#include "texram/layout.hpp"
#include "texram/mipgen_stream.hpp"
#include "texram/mipmap.hpp"

namespace tmu::tb {
namespace {

constexpr auto options = testing::cosim_options;

BlockOptions format(uint64_t seed, int log2_w, int log2_h, bool interlaced) {
  BlockOptions b;
  b.seed = seed;
  b.mip_log2_w = log2_w;
  b.mip_log2_h = log2_h;
  b.mip_interlaced = interlaced ? 1 : 0;
  return b;
}

std::string describe(const texram::MipgenConfig& c) {
  return std::to_string(1u << c.log2_w) + " x " + std::to_string(1u << c.log2_h) +
         (c.interlaced ? " interlaced" : "") + ", plane " + std::to_string(c.plane) + " of " +
         std::to_string(c.planes);
}

texram::Level8 random_frame(int log2_w, int log2_h, uint64_t seed) {
  std::mt19937_64 rng(seed);
  texram::Level8 l(1u << log2_w, 1u << log2_h);
  for (uint8_t& t : l.texels) t = static_cast<uint8_t>(rng());
  return l;
}

// --- random formats and frames ------------------------------------------------------------

TEST(MipgenCosimTest, RandomFormatsGoldenVsHlsVsRtl) {
  // Seeds whose formats are 8 x 16, 64 x 32 interlaced, 2 x 1024, 1 x 8, 16 x 2, 1 x 4
  // interlaced, 1 x 1024 (printed below); the directed formats below cover the rest.
  for (uint64_t seed : {1, 2, 3, 4, 5, 6, 7}) {
    BlockOptions b;
    b.seed = seed;
    const MipgenBlock block(b);
    SCOPED_TRACE("seed " + std::to_string(seed) + ": " + describe(block.config()));
    std::stringstream log;
    const CosimResult r = run_cosim(block, options(seed, 1000, {"hls", "rtl"}), log);
    EXPECT_TRUE(r.pass) << log.str();
    std::cout << "seed " << seed << ": " << describe(block.config()) << ", " << r.items
              << " texels -> " << r.transactions << " writes; rtl " << r.runs.at("rtl").cycles
              << " cycles\n";
    for (const auto& [name, n] : r.coverage) {
      EXPECT_GT(n, 0u) << "coverage case not hit: " << name << "\n" << log.str();
    }
  }
}

// --- directed formats ----------------------------------------------------------------------

class MipgenFormatCosim : public ::testing::TestWithParam<std::tuple<int, int, bool>> {};

TEST_P(MipgenFormatCosim, GoldenVsHlsVsRtl) {
  const auto [lw, lh, interlaced] = GetParam();
  const MipgenBlock block(format(11, lw, lh, interlaced));
  std::stringstream log;
  // The four directed frames (0, 255, alternating, rounding ties), then one random frame.
  const CosimResult r = run_cosim(block, options(11, 1, {"hls", "rtl"}), log);
  EXPECT_TRUE(r.pass) << log.str();
  for (const auto& [name, n] : r.coverage) EXPECT_GT(n, 0u) << "not hit: " << name;
}

INSTANTIATE_TEST_SUITE_P(
    Formats, MipgenFormatCosim,
    ::testing::Values(std::tuple{0, 0, false}, std::tuple{0, 0, true},    // 1 x 1
                      std::tuple{10, 0, false}, std::tuple{10, 0, true},  // 1024-texel lines
                      std::tuple{0, 6, true}, std::tuple{0, 1, false},    // one texel wide
                      std::tuple{1, 1, true}, std::tuple{6, 1, true},     // one field-2 line
                      std::tuple{5, 2, true}, std::tuple{2, 5, false},    // non-square
                      std::tuple{4, 4, true}),
    [](const auto& param_info) {
      return std::to_string(1 << std::get<0>(param_info.param)) + "x" +
             std::to_string(1 << std::get<1>(param_info.param)) +
             (std::get<2>(param_info.param) ? "Interlaced" : "Progressive");
    });

TEST(MipgenCosimTest, HeavyBackPressure) {
  for (const auto& [lw, lh, il] : {std::tuple{5, 3, true}, std::tuple{0, 3, false},
                                   std::tuple{6, 0, true}, std::tuple{3, 3, false}}) {
    const MipgenBlock block(format(21, lw, lh, il));
    SCOPED_TRACE(describe(block.config()));
    CosimOptions o = options(21, 500, {"hls", "rtl"});
    o.in_idle = 0.6;
    o.out_stall = 0.6;
    std::stringstream log;
    EXPECT_TRUE(run_cosim(block, o, log).pass) << log.str();
  }
}

// One write per clock: without stalls the rtl never idles between writes (an item is taken
// in the cycle the previous item's last write leaves).
TEST(MipgenCosimTest, FullThroughputOneWritePerClock) {
  for (const auto& [lw, lh, il] : {std::tuple{5, 4, false}, std::tuple{4, 5, true},
                                   std::tuple{0, 0, false}, std::tuple{10, 0, true}}) {
    const MipgenBlock block(format(3, lw, lh, il));
    SCOPED_TRACE(describe(block.config()));
    CosimOptions o = options(3, 2000, {"hls", "rtl"});
    o.in_idle = 0.0;
    o.out_stall = 0.0;
    std::stringstream log;
    const CosimResult r = run_cosim(block, o, log);
    ASSERT_TRUE(r.pass) << log.str();
    // The first item is taken at cycle 0, its first write leaves at cycle 1, then one write
    // per cycle; the runner adds 16 drain cycles.
    const uint64_t writes = r.transactions;
    EXPECT_EQ(r.runs.at("rtl").cycles, writes + 1 + 16) << log.str();
    EXPECT_LE(r.runs.at("hls").cycles, writes + 4 + 16) << log.str();
  }
}

// --- the cells read back through the layout -----------------------------------------------

// The rtl's writes, stored in a bank image, read back through Geometry::cell: every level is
// build_pyramid's and every cell of the layout (replicas included) is written exactly once.
TEST(MipgenCosimTest, RtlWritesReadBackAsThePyramid) {
  for (const auto& [lw, lh, il, planes] :
       {std::tuple{0, 0, false, 1}, std::tuple{10, 0, true, 4}, std::tuple{0, 10, true, 1},
        std::tuple{7, 3, true, 4}, std::tuple{3, 7, false, 4}, std::tuple{6, 6, true, 1}}) {
    const texram::Level8 level0 = random_frame(lw, lh, 77);
    texram::BankMemory mem(texram::Geometry(lw, lh, planes));
    for (int plane = 0; plane < planes; ++plane) {
      const texram::MipgenConfig cfg{lw, lh, il, planes, plane};
      SCOPED_TRACE(describe(cfg));
      const RunResult run =
          make_mipgen_engine("rtl", cfg)->run(mipgen_frame_items(level0, il), RunOptions{});
      ASSERT_TRUE(run.error.empty()) << run.error;
      for (const Txn& t : run.outputs) mem.write(mipgen_txn_write(t));
      EXPECT_EQ(mem.read_pyramid(plane), texram::build_pyramid(level0));
      EXPECT_EQ(mem.cells_not_written_once(plane), 0u);
    }
  }
}

TEST(MipgenCosimTest, RtlWritesReadBackAsThePyramidAt1024x1024) {
  const texram::Level8 level0 = random_frame(10, 10, 78);
  const texram::MipgenConfig cfg{10, 10, true, 4, 3};
  const RunResult run =
      make_mipgen_engine("rtl", cfg)->run(mipgen_frame_items(level0, true), RunOptions{});
  ASSERT_TRUE(run.error.empty()) << run.error;
  texram::BankMemory mem(texram::Geometry(10, 10, 4));
  for (const Txn& t : run.outputs) mem.write(mipgen_txn_write(t));
  EXPECT_EQ(mem.read_pyramid(3), texram::build_pyramid(level0));
  EXPECT_EQ(mem.cells_not_written_once(3), 0u);
}

// The directed tie frame: every box sum of every level is 2 mod 4, and its pyramid is the
// one it was built from (128 at the top).
TEST(MipgenCosimTest, TieFrameRoundsEveryBoxHalfUp) {
  for (const auto& [lw, lh] :
       {std::pair{10, 10}, std::pair{10, 0}, std::pair{0, 9}, std::pair{4, 7}, std::pair{1, 1}}) {
    const texram::Level8 frame = mipgen_tie_frame(lw, lh);
    texram::MipgenStream s({lw, lh, false, 1, 0});
    std::vector<texram::CellWrite> w;
    size_t boxes = 0, ties = 0;
    for (const texram::MipgenInput& in : texram::mipgen_source(frame, false)) {
      s.step(in, w);
      for (uint32_t sum : s.last_box_sums()) {
        ++boxes;
        ties += sum % 4 == 2;
      }
    }
    EXPECT_EQ(ties, boxes) << lw << " x " << lh;
    EXPECT_EQ(texram::build_pyramid(frame).back().at(0, 0), 128);
  }
}

// --- teeth ---------------------------------------------------------------------------------

TEST(MipgenCosimTest, MutantRoundingIsCaught) {
  // The mutant adds 1 instead of 2 before dropping two bits: wrong exactly on the ties.
  const MipgenBlock block(format(9, 3, 2, true));
  CosimOptions o = options(9, 200, {"rtl"});
  std::stringstream log;
  const CosimResult r =
      run_cosim(block, o, log, [&](const std::string& level) -> std::unique_ptr<Engine> {
        if (level == "rtl")
          return make_mipgen_rtl_engine<Vtmu_mipgen_mutant_round>("rtl", block.config());
        return nullptr;
      });
  EXPECT_FALSE(r.pass);
  EXPECT_EQ(r.failing_engine, "rtl");
  EXPECT_NE(log.str().find("value"), std::string::npos) << log.str();
  EXPECT_NE(log.str().find("reproduce: texsim cosim mipgen --seed 9"), std::string::npos)
      << log.str();
  ASSERT_FALSE(r.wave_path.empty());
}

TEST(MipgenCosimTest, InjectedFaultFailsTheRun) {
  const MipgenBlock block(format(5, 2, 2, false));
  CosimOptions o = options(5, 100, {"hls", "rtl"});
  o.inject_fault = 40;
  std::stringstream log;
  const CosimResult r = run_cosim(block, o, log);
  EXPECT_FALSE(r.pass);
  EXPECT_NE(log.str().find("first at transaction 40"), std::string::npos) << log.str();
}

}  // namespace
}  // namespace tmu::tb
