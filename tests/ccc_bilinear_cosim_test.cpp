// The low-cost CCC unit: golden vs hls vs rtl, bit for bit, with the lookahead on and off,
// on random stimulus and on every pixel of whole images, and proof that the comparison has
// teeth (an injected fault, two RTL mutants, a memory read beyond the texture).
#include <Vtmu_ccc_cache_bilinear.h>
#include <Vtmu_ccc_cache_bilinear_mutant_count.h>
#include <Vtmu_ccc_cache_bilinear_mutant_round.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <iostream>
#include <sstream>

#include "blocks/ccc_bilinear_block.hpp"
#include "ccc/ccc_encoder.hpp"
#include "common/test_patterns.hpp"
#include "harness/cosim.hpp"
#include "harness/vector_file.hpp"
#include "tests/cosim_test_support.hpp"

namespace tmu::tb {
namespace {

namespace fs = std::filesystem;

fs::path temp_dir() { return testing::temp_dir("tmu_ccc_bilinear_cosim_test"); }
constexpr auto options = testing::cosim_options;

BlockOptions block_options(uint64_t seed, bool lookahead, std::string texture = "") {
  BlockOptions b;
  b.seed = seed;
  b.lookahead = lookahead;
  b.texture = std::move(texture);
  return b;
}

uint64_t counter(const RunResult& r, const std::string& name) {
  const auto v = counter_value(r.counters, name);
  if (!v) ADD_FAILURE() << "no counter " << name;
  return v.value_or(0);
}

std::string counters_text(const RunResult& r) {
  return "hits " + std::to_string(counter(r, "hits")) + ", misses " +
         std::to_string(counter(r, "misses")) + ", prefetches " +
         std::to_string(counter(r, "prefetches"));
}

// --- random stimulus ----------------------------------------------------------------------

class CccBilinearRandomCosim : public ::testing::TestWithParam<bool> {};

TEST_P(CccBilinearRandomCosim, GoldenVsHlsVsRtl) {
  const bool lookahead = GetParam();
  // Seeds whose random textures are 40 x 46, 14 x 1, 282 x 43, 1 x 38, 65 x 247, 10 x 62.
  for (uint64_t seed : {1, 2, 20, 31, 35, 12}) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    std::cout << "seed " << seed << (lookahead ? ", lookahead on\n" : ", lookahead off\n");
    const CccBilinearBlock block(block_options(seed, lookahead));
    std::stringstream log;
    const CosimResult r = run_cosim(block, options(seed, 50'000, {"hls", "rtl"}), log);
    EXPECT_TRUE(r.pass) << log.str();
    EXPECT_GE(r.transactions, 50'000u);
    std::cout << "  " << block.texture()->width << " x " << block.texture()->height
              << " texels: " << counters_text(r.runs.at("golden")) << "; rtl "
              << r.runs.at("rtl").cycles << " cycles\n";
    if (!lookahead) {
      EXPECT_EQ(counter(r.runs.at("golden"), "prefetches"), 0u);
    }
    if (seed == 1) {  // a texture on which every case occurs
      for (const auto& [name, n] : r.coverage)
        EXPECT_GT(n, 0u) << "coverage case not hit: " << name;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Lookahead, CccBilinearRandomCosim, ::testing::Bool(),
                         [](const auto& param_info) { return param_info.param ? "On" : "Off"; });

TEST(CccBilinearCosimTest, HeavyBackPressureAndSlowMemory) {
  const CccBilinearBlock block(block_options(21, true));
  CosimOptions o = options(21, 20'000, {"hls", "rtl"});
  o.in_idle = 0.6;
  o.out_stall = 0.7;
  std::stringstream log;
  EXPECT_TRUE(run_cosim(block, o, log).pass) << log.str();
}

// All hits, no stalls: after the first fills the unit takes one request per clock.
TEST(CccBilinearCosimTest, OneRequestPerClockOnHits) {
  const CccBilinearBlock block(block_options(3, true));
  std::vector<Txn> items = block.setup_items();
  for (int i = 0; i < 2000; ++i) items.push_back(bilinear_sample_item(i % 2 ? 384 : 400, 300));
  const fs::path file = temp_dir() / "hits.csv";
  write_vectors(file.string(), block.inputs(), items);
  CosimOptions o = options(3, 0, {"rtl"});
  o.vectors_in = file.string();
  o.in_idle = 0.0;
  o.out_stall = 0.0;
  std::stringstream log;
  const CosimResult r = run_cosim(block, o, log);
  ASSERT_TRUE(r.pass) << log.str();
  // 256 CLUT writes and 2000 samples, one cycle each, plus the first fills and the drain.
  EXPECT_LE(r.runs.at("rtl").cycles, items.size() + 100) << log.str();
}

// --- whole images -------------------------------------------------------------------------

TEST(CccBilinearCosimTest, WholeImagesMagnifiedAndMinified) {
  // An encoded photo-like texture whose sides are not multiples of 4.
  const ccc::Texture tex = ccc::encode(patterns::smooth_field(157, 113, 5));
  const fs::path tex_path = temp_dir() / "field.ccc";
  ccc::write_ccc(tex_path.string(), tex);
  struct Case {
    const char* name;
    uint32_t out_w, out_h;
  };
  for (const Case& c : {Case{"2x magnification", 314, 226}, Case{"0.37x minification", 58, 42}}) {
    const std::vector<Txn> items = bilinear_resample_items(tex, c.out_w, c.out_h);
    const fs::path file = temp_dir() / (std::string(c.name).substr(0, 4) + ".csv");
    write_vectors(file.string(),
                  CccBilinearBlock(block_options(1, true, tex_path.string())).inputs(), items);
    for (bool lookahead : {true, false}) {
      SCOPED_TRACE(std::string(c.name) + (lookahead ? ", lookahead on" : ", lookahead off"));
      const CccBilinearBlock block(block_options(1, lookahead, tex_path.string()));
      CosimOptions o = options(1, 0, {"hls", "rtl"});
      o.vectors_in = file.string();
      std::stringstream log;
      const CosimResult r = run_cosim(block, o, log);
      EXPECT_TRUE(r.pass) << log.str();
      EXPECT_NE(log.str().find("MATCH: all " + std::to_string(size_t{c.out_w} * c.out_h)),
                std::string::npos)
          << log.str();
      std::cout << c.name << " of 157 x 113 (" << c.out_w << " x " << c.out_h
                << " pixels), lookahead " << (lookahead ? "on: " : "off: ")
                << counters_text(r.runs.at("golden")) << "; rtl " << r.runs.at("rtl").cycles
                << " cycles\n";
    }
  }
}

// --- teeth --------------------------------------------------------------------------------

TEST(CccBilinearCosimTest, InjectedFaultFailsTheRun) {
  const CccBilinearBlock block(block_options(5, true));
  CosimOptions o = options(5, 2000, {"hls", "rtl"});
  o.inject_fault = 700;
  std::stringstream log;
  const CosimResult r = run_cosim(block, o, log);
  EXPECT_FALSE(r.pass);
  EXPECT_NE(log.str().find("first at transaction 700"), std::string::npos) << log.str();
}

// The blend rounds with a quarter instead of half an LSB: wrong outputs.
TEST(CccBilinearCosimTest, RoundingMutantIsCaughtWithAWaveform) {
  const CccBilinearBlock block(block_options(9, true));
  CosimOptions o = options(9, 5000, {"rtl"});
  fs::remove_all(o.wave_dir);
  std::stringstream log;
  const CosimResult r =
      run_cosim(block, o, log, [&block](const std::string& level) -> std::unique_ptr<Engine> {
        if (level != "rtl") return nullptr;
        return make_ccc_bilinear_rtl_engine<Vtmu_ccc_cache_bilinear_mutant_round>(
            "rtl", block.texture(), true);
      });
  testing::expect_rtl_caught_with_waveform(r, log.str(), "texsim cosim ccc-bilinear --seed 9");
}

// The hit/miss adder drops the fourth block of a footprint: right outputs, wrong statistics.
TEST(CccBilinearCosimTest, CounterMutantIsCaught) {
  const CccBilinearBlock block(block_options(1, true));
  std::stringstream log;
  const CosimResult r =
      run_cosim(block, options(1, 5000, {"rtl"}), log,
                [&block](const std::string& level) -> std::unique_ptr<Engine> {
                  if (level != "rtl") return nullptr;
                  return make_ccc_bilinear_rtl_engine<Vtmu_ccc_cache_bilinear_mutant_count>(
                      "rtl", block.texture(), true);
                });
  EXPECT_FALSE(r.pass);
  EXPECT_NE(log.str().find("counter hits: expected"), std::string::npos) << log.str();
  EXPECT_NE(log.str().find("MISMATCH rtl vs golden: 0 of"), std::string::npos)
      << log.str();  // outputs right
}

// A memory read beyond the texture gets a poison word and fails the run: here the memory
// holds fewer blocks than the size the unit is configured with.
TEST(CccBilinearCosimTest, ReadBeyondTheTextureFailsTheRun) {
  ccc::Texture tex = random_bilinear_texture(4);
  tex.width = tex.height = 16;
  tex.blocks.assign(15, 0x01020304u);  // 16 expected: block (3, 3) is missing
  std::vector<Txn> items = bilinear_clut_load(tex);
  items.push_back(bilinear_sample_item(2 * 256, 2 * 256));
  items.push_back(bilinear_sample_item(15 * 256, 15 * 256));
  auto engine = make_ccc_bilinear_rtl_engine<Vtmu_ccc_cache_bilinear>(
      "rtl", std::make_shared<const ccc::Texture>(tex), false);
  const RunResult r = engine->run(items, RunOptions{});
  EXPECT_NE(r.error.find("read of block 15"), std::string::npos) << r.error;
  EXPECT_NE(r.error.find("beyond the texture's 15 blocks"), std::string::npos) << r.error;
}

}  // namespace
}  // namespace tmu::tb
