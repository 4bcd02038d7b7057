// What is the TEXRAM trilinear unit's own (000 §2, §5, §6; the conformance suite checks what
// every block shares): the header's worked example (one access reading all eight banks), one
// sample per clock on page hits, a read beyond a bank failing the run, and a sample of an index
// texture before its CLUT load rejected.
#include <gtest/gtest.h>

#include <array>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "blocks/trilinear/trilinear_block.hpp"
#include "harness/cosim.hpp"
#include "harness/handshake_driver.hpp"
#include "harness/vector_file.hpp"
#include "tests/cosim_test_support.hpp"

namespace tmu::tb {
namespace {

namespace fs = std::filesystem;
using D = desc::trilinear;
using texram::Filter;
using texram::TexelKind;

fs::path temp_dir() { return testing::temp_dir("tmu_trilinear_test"); }
constexpr auto options = testing::cosim_options;
constexpr int32_t kOne = 256;

BlockOptions block_options(uint64_t seed, TexelKind kind, Filter filter, int log2_w, int log2_h) {
  BlockOptions o;
  o.seed = seed;
  o.tri_kind = kind;
  o.tri_filter = filter;
  o.tri_border_u = o.tri_border_v = texram::Border::kWrap;
  o.tri_combine = texram::Combine::kOne;
  o.tri_log2_w = log2_w;
  o.tri_log2_h = log2_h;
  o.tri_pattern = "smooth";
  return o;
}

// tmu_trilinear.sv's example: an 8 x 8 luminance texture, trilinear, wrap, u = v = 2.0, lambda
// 1.5: levels 1 and 2 (weight 1/2). Level 1 (4 x 4, the first odd level: position 0 of banks
// 4-7) has its taps at x, y = 0, 1; level 2 (2 x 2, after level 0's 16 positions in banks
// 0-3) at 0, 1 too. One access reads all eight banks: 16 in banks 0-3, 0 in banks 4-7; the
// rtl makes exactly that request.
TEST(TrilinearTest, TheHeadersExampleReadsEveryBankInOneAccess) {
  const TrilinearBlock block(block_options(1, TexelKind::kLuminance, Filter::kTrilinear, 3, 3));
  std::vector<Txn> items = block.setup_items();
  items.push_back(trilinear_sample_item(2 * kOne, 2 * kOne, kOne + kOne / 2));
  const RunResult golden = block.engine("golden")->run(items, {});
  ASSERT_TRUE(golden.error.empty()) << golden.error;
  ASSERT_EQ(golden.requests.at(0).size(), 1u);
  const Txn& access = golden.requests[0][0];
  for (size_t b = 0; b < 8; ++b) {
    EXPECT_EQ(access.f[D::mem_req_en + b], 1u) << "bank " << b;
    EXPECT_EQ(access.f[D::mem_req_addr + b], b < 4 ? 16u : 0u) << "bank " << b;
  }
  const RunResult rtl = block.engine("rtl")->run(items, {});
  ASSERT_TRUE(rtl.error.empty()) << rtl.error;
  EXPECT_EQ(rtl.requests, golden.requests);
  EXPECT_EQ(rtl.outputs, golden.outputs);
}

// The cycles of 16 rasterized spans of 250 samples on a 256 x 256 texture: rows of u steps of a
// quarter texel at a fixed v and lambda, no stalls.
struct Throughput {
  size_t samples = 0;
  uint64_t cycles = 0;
  uint64_t slow_accesses = 0;
};

Throughput span_throughput(TexelKind kind, Filter filter, int32_t lambda) {
  const TrilinearBlock block(block_options(5, kind, filter, 8, 8));
  std::vector<Txn> items = block.setup_items();
  const size_t setup = items.size();
  for (int32_t row = 0; row < 16; ++row) {
    for (int32_t i = 0; i < 250; ++i) {
      items.push_back(trilinear_sample_item(8 * kOne + i * kOne / 4, (20 + 7 * row) * kOne + 77,
                                            lambda, 0x80808080u));
    }
  }
  const fs::path file = temp_dir() / "span.csv";
  write_vectors(file.string(), block.inputs(), items);
  CosimOptions c = options(5, 0, {"hls", "rtl"});
  c.vectors_in = file.string();
  c.in_idle = 0.0;
  c.out_stall = 0.0;
  std::stringstream log;
  const CosimResult r = run_cosim(block, c, log);
  EXPECT_TRUE(r.pass) << log.str();
  // The configuration waits for the quiet cycles; the CLUT load (index, CCC) is a write per
  // clock; the samples' cycles come after.
  return {items.size() - setup, r.runs.at("rtl").cycles - (kQuietCycles + 1) - (setup - 1),
          counter_value(r.runs.at("golden").counters, "slow_accesses").value_or(0)};
}

// 1-plane textures: one sample per clock when every access hits; each fault adds a clock.
// 4-plane textures: four accesses, four clocks per sample.
TEST(TrilinearTest, OneSamplePerClockOnPageHits) {
  // The pipeline's latency and the 16 drain cycles.
  constexpr uint64_t kOverhead = 12 + kDrainCycles;
  for (Filter filter : {Filter::kBilinear, Filter::kTrilinear}) {
    const Throughput t = span_throughput(TexelKind::kLuminance, filter, kOne / 2);
    const double per_clock =
        static_cast<double>(t.samples) / static_cast<double>(t.cycles - kOverhead);
    std::cout << "luminance " << name(filter) << ": " << t.samples << " samples, " << t.cycles
              << " cycles, " << t.slow_accesses << " slow accesses: " << per_clock
              << " samples per clock ("
              << static_cast<double>(t.samples) /
                     static_cast<double>(t.cycles - kOverhead - t.slow_accesses)
              << " without the faults' extra periods)\n";
    EXPECT_LE(t.cycles, kOverhead + t.samples + t.slow_accesses + 2);
    EXPECT_GE(per_clock, 0.95);
  }
  const Throughput t = span_throughput(TexelKind::kTrueColour, Filter::kTrilinear, kOne / 2);
  std::cout << "rgba trilinear: " << t.samples << " samples, " << t.cycles << " cycles, "
            << t.slow_accesses << " slow accesses\n";
  EXPECT_LE(t.cycles, kOverhead + 4 * t.samples + t.slow_accesses + 2);
}

// A memory holding fewer cells than the layout needs: the read beyond a bank fails the run.
TEST(TrilinearTest, ReadBeyondABankFailsTheRun) {
  const TrilinearBlock seeded(block_options(9, TexelKind::kLuminance, Filter::kBilinear, 5, 4));
  texram::TexramTexture small = *seeded.textures()->texture_of(seeded.first());
  for (auto& bank : small.banks) bank.resize(bank.size() / 2);
  const TrilinearBlock block(BlockOptions{},
                             {std::make_shared<const texram::TexramTexture>(std::move(small)),
                              seeded.first().config, "half the banks"});
  std::vector<Txn> items = block.setup_items();
  items.push_back(trilinear_sample_item(31 * kOne, 15 * kOne, 0));  // the last cells of level 0
  const RunResult r = block.engine("rtl")->run(items, {});
  EXPECT_NE(r.error.find("texram memory: read of bank"), std::string::npos) << r.error;
}

// The CLUT is a RAM without reset: a sample of an index texture before all of it is written
// is a stimulus error, which golden reports.
TEST(TrilinearTest, IndexSampleBeforeTheClutLoadIsAnError) {
  const TrilinearBlock block(block_options(3, TexelKind::kIndex, Filter::kBilinear, 4, 4));
  std::vector<Txn> items = block.setup_items();
  items.resize(1 + 255);  // the configuration and all but the last CLUT entry
  items.push_back(trilinear_sample_item(kOne, kOne, 0));
  const RunResult r = block.engine("golden")->run(items, {});
  EXPECT_NE(r.error.find("before all 256 CLUT entries are written"), std::string::npos) << r.error;
}

}  // namespace
}  // namespace tmu::tb
