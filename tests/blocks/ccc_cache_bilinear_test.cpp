// What is the low-cost CCC unit's own (000 §4; the conformance suite checks what every block
// shares): one request per clock on hits, whole images magnified and minified through every
// level with the lookahead on and off, a read beyond the texture failing the run, a new
// texture size without a CLUT load rejected, and the memory requests compared where outputs
// and counters agree.
#include <Vtmu_ccc_cache_bilinear.h>
#include <Vtmu_ccc_cache_bilinear_mutant_neighbour.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <iostream>
#include <sstream>

#include "blocks/ccc_cache_bilinear/ccc_cache_bilinear_block.hpp"
#include "ccc/ccc_encoder.hpp"
#include "common/test_patterns.hpp"
#include "harness/cosim.hpp"
#include "harness/described_engines.hpp"
#include "harness/vector_file.hpp"
#include "tests/cosim_test_support.hpp"

namespace tmu::tb {
namespace {

namespace fs = std::filesystem;
using D = desc::ccc_cache_bilinear;

fs::path temp_dir() { return testing::temp_dir("tmu_ccc_cache_bilinear_test"); }
constexpr auto options = testing::cosim_options;

BlockOptions block_options(uint64_t seed, std::optional<bool> lookahead, std::string texture = "") {
  BlockOptions b;
  b.seed = seed;
  b.lookahead = lookahead;
  b.texture = std::move(texture);
  return b;
}

std::string counters_text(const RunResult& r) {
  std::string out;
  for (const auto& [name, value] : r.counters) out += name + " " + std::to_string(value) + " ";
  return out;
}

// All hits, no stalls: after the first fills the unit takes one request per clock.
TEST(CccCacheBilinearTest, OneRequestPerClockOnHits) {
  const CccCacheBilinearBlock block(block_options(3, true));
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
  // 256 CLUT writes and 2000 samples, one cycle each, plus the configuration, the first fills
  // and the drain.
  EXPECT_LE(r.runs.at("rtl").cycles, items.size() + 100) << log.str();
}

// An encoded photo-like texture whose sides are not multiples of 4, every pixel resampled.
TEST(CccCacheBilinearTest, WholeImagesMagnifiedAndMinified) {
  const ccc::Texture tex = ccc::encode(patterns::smooth_field(157, 113, 5));
  const fs::path tex_path = temp_dir() / "field.ccc";
  ccc::write_ccc(tex_path.string(), tex);
  struct Case {
    const char* name;
    uint32_t out_w, out_h;
  };
  for (const Case& c : {Case{"2x magnification", 314, 226}, Case{"0.37x minification", 58, 42}}) {
    for (bool lookahead : {true, false}) {
      SCOPED_TRACE(std::string(c.name) + (lookahead ? ", lookahead on" : ", lookahead off"));
      const CccCacheBilinearBlock block(block_options(1, lookahead, tex_path.string()));
      std::vector<Txn> items = block.setup_items();
      for (const Txn& t : bilinear_resample_items(tex, c.out_w, c.out_h)) items.push_back(t);
      const fs::path file = temp_dir() / (std::string(c.name).substr(0, 4) + ".csv");
      write_vectors(file.string(), block.inputs(), items);
      CosimOptions o = options(1, 0, {"hls", "rtl"});
      o.vectors_in = file.string();
      std::stringstream log;
      const CosimResult r = run_cosim(block, o, log);
      EXPECT_TRUE(r.pass) << log.str();
      EXPECT_NE(log.str().find("MATCH: all " + std::to_string(size_t{c.out_w} * c.out_h)),
                std::string::npos)
          << log.str();
      const RunResult& g = r.runs.at("golden");
      if (!lookahead) {
        EXPECT_EQ(counter_value(g.counters, "prefetches"), 0u);
      }
      std::cout << c.name << " of 157 x 113 (" << c.out_w << " x " << c.out_h
                << " pixels), lookahead " << (lookahead ? "on: " : "off: ") << counters_text(g)
                << g.requests.at(0).size() << " memory requests; rtl " << r.runs.at("rtl").cycles
                << " cycles\n";
    }
  }
}

// A memory read beyond the texture gets a poison word and fails the run: here the memory
// holds fewer blocks than the size the unit is configured with.
TEST(CccCacheBilinearTest, ReadBeyondTheTextureFailsTheRun) {
  ccc::Texture tex = random_bilinear_texture(16, 16, 4);
  tex.blocks.assign(15, 0x01020304u);  // 16 expected: block (3, 3) is missing
  const CccCacheBilinearBlock block(block_options(4, false),
                                    std::make_shared<const ccc::Texture>(tex));
  std::vector<Txn> items = block.setup_items();
  items.push_back(bilinear_sample_item(2 * 256, 2 * 256));
  items.push_back(bilinear_sample_item(15 * 256, 15 * 256));
  const RunResult r = block.engine("rtl")->run(items, RunOptions{});
  EXPECT_NE(r.error.find("read of block 15"), std::string::npos) << r.error;
  EXPECT_NE(r.error.find("beyond the texture's 15 blocks"), std::string::npos) << r.error;
}

// A new texture size without the CLUT load that invalidates the cache is a stimulus error
// (the RTL's tags would name other blocks), which golden reports.
TEST(CccCacheBilinearTest, NewSizeWithoutClutLoadIsAnError) {
  const CccCacheBilinearBlock block(block_options(6, true));
  std::vector<Txn> items = block.setup_items();
  items.push_back(bilinear_sample_item(300, 300));
  ccc::Texture other = random_bilinear_texture(block.texture()->width + 1, 9, 7);
  items.push_back(block.config_item(other, true, 7));
  items.push_back(bilinear_sample_item(300, 300));
  const RunResult r = block.engine("golden")->run(items, RunOptions{});
  EXPECT_NE(r.error.find("without a CLUT write"), std::string::npos) << r.error;
}

// The lookahead fetching the block before instead of after (tmu_ccc_footprint_axis.sv): the
// report names the memory requests that differ (the seed 5 once passed this mutant
// when only outputs and counters were compared).
TEST(CccCacheBilinearTest, MemoryRequestsCatchAWrongPrefetch) {
  const CccCacheBilinearBlock block(block_options(5, true));
  CosimOptions o = options(5, 3000, {"rtl"});
  o.x_check = false;
  std::stringstream log;
  const CosimResult r = run_cosim(block, o, log, [](const std::string& level) {
    return level == "rtl" ? rtl_level<D, Vtmu_ccc_cache_bilinear_mutant_neighbour>("rtl")(
                                CccCacheBilinearBlock(block_options(5, true)))
                          : nullptr;
  });
  EXPECT_FALSE(r.pass);
  EXPECT_NE(log.str().find("memory requests of channel 0:"), std::string::npos) << log.str();
  std::cout << log.str().substr(log.str().find("MISMATCH"), 700) << "\n";
}

}  // namespace
}  // namespace tmu::tb
