// What is the footprint assembly unit's own (000 §10; the conformance suite checks what every
// block shares): one probe per clock into its trilinear unit with fragments back to back, and
// a CLUT write after every fragment reaching the trilinear unit between the fragments' probes
// whatever is still in flight.
#include <gtest/gtest.h>

#include <filesystem>
#include <iostream>
#include <random>
#include <sstream>
#include <tuple>

#include "blocks/footprint/footprint_block.hpp"
#include "harness/cosim.hpp"
#include "harness/handshake_driver.hpp"
#include "harness/vector_file.hpp"
#include "tests/cosim_test_support.hpp"

namespace tmu::tb {
namespace {

namespace fs = std::filesystem;
using texram::Border;
using texram::Filter;
using texram::TexelKind;

fs::path temp_dir() { return testing::temp_dir("tmu_footprint_test"); }
constexpr auto options = testing::cosim_options;
constexpr int32_t kOne = 256;

CosimResult run_vectors(const FootprintBlock& block, const std::vector<Txn>& items,
                        CosimOptions o) {
  const fs::path file = temp_dir() / "items.csv";
  write_vectors(file.string(), block.inputs(), items);
  o.vectors_in = file.string();
  std::stringstream log;
  const CosimResult r = run_cosim(block, o, log);
  EXPECT_TRUE(r.pass) << log.str();
  return r;
}

// A run without bubbles or stalls on a 1-plane texture: the rtl's cycles and probes.
struct Throughput {
  size_t fragments = 0;
  uint64_t probes = 0;
  uint64_t cycles = 0;
  uint64_t slow_accesses = 0;
};

Throughput full_speed(int max_probes, int32_t r1u, int32_t r2v) {
  BlockOptions o;
  o.seed = 5;
  o.fp_log2_max_probes = max_probes;
  o.fp_q_rule = footprint::QRule::kHeights;
  o.tri_kind = TexelKind::kLuminance;
  o.tri_filter = Filter::kTrilinear;
  o.tri_log2_w = 8;
  o.tri_log2_h = 8;
  o.tri_pattern = "smooth";
  const FootprintBlock block(o);
  std::vector<Txn> items = block.setup_items();  // the configuration alone (luminance)
  size_t fragments = 0;
  // A rasterized span: rows of fragments a quarter texel apart, the same footprint: mostly
  // page hits.
  for (int32_t row = 0; row < 8; ++row) {
    for (int32_t i = 0; i < 200; ++i, ++fragments) {
      items.push_back(footprint_sample_item(40 * kOne + i * kOne / 4, (30 + 5 * row) * kOne + 77,
                                            r1u, 0, 0, r2v, 0x80808080u));
    }
  }
  CosimOptions c = options(5, 0, {"rtl"});
  c.in_idle = 0.0;
  c.out_stall = 0.0;
  c.x_check = false;
  const CosimResult r = run_vectors(block, items, c);
  const RunResult& rtl = r.runs.at("rtl");
  return {fragments, counter_value(rtl.counters, "probes").value_or(0),
          rtl.cycles - (kQuietCycles + 1),  // the configuration waits for the quiet cycles
          counter_value(r.runs.at("golden").counters, "slow_accesses").value_or(0)};
}

// One probe per clock into the trilinear unit: a fragment of N probes takes N clocks, and
// back-to-back fragments do not bubble. The setup, marcher, trilinear and average latency (21
// cycles) and the 16 drain cycles come on top; each page fault costs the trilinear unit a
// clock.
TEST(FootprintTest, OneProbePerClock) {
  constexpr uint64_t kOverhead = 21 + kDrainCycles;
  // N = 1 (isotropic, 2 texels), 4 (ratio 4) and 16 (ratio 16) probes per fragment.
  for (const auto& [max, r1u, r2v] :
       {std::tuple{0, 2 * kOne, 2 * kOne}, std::tuple{2, 8 * kOne, 2 * kOne},
        std::tuple{4, 16 * kOne, kOne}}) {
    const Throughput t = full_speed(max, r1u, r2v);
    EXPECT_EQ(t.probes, t.fragments << max);
    const double per_clock =
        static_cast<double>(t.probes) / static_cast<double>(t.cycles - kOverhead);
    std::cout << (1 << max) << " probes per fragment: " << t.fragments << " fragments, " << t.probes
              << " probes, " << t.cycles << " cycles, " << t.slow_accesses
              << " slow accesses: " << per_clock << " probes per clock, "
              << static_cast<double>(t.cycles - kOverhead) / static_cast<double>(t.fragments)
              << " cycles per fragment\n";
    EXPECT_LE(t.cycles, kOverhead + t.probes + t.slow_accesses + 2);
    EXPECT_GE(per_clock, 0.9);
  }
}

// A CLUT write after every fragment of an index texture, 16 probes each, with and without
// back-pressure: a write must reach the trilinear unit after the previous fragment's probes
// and before the next one's, whatever is still in flight (hls and rtl).
TEST(FootprintTest, ClutWritesBetweenFragmentsInFlight) {
  BlockOptions o;
  o.seed = 77;
  o.tri_kind = TexelKind::kIndex;
  o.tri_filter = Filter::kTrilinear;
  o.tri_border_u = o.tri_border_v = Border::kWrap;
  o.tri_log2_w = o.tri_log2_h = 4;
  o.tri_pattern = "random";
  o.fp_log2_max_probes = 4;
  const FootprintBlock block(o);
  const texram::TexramTexture& tex = *block.textures()->texture_of(block.first().texram);
  std::vector<Txn> items = block.setup_items();
  std::mt19937_64 rng(o.seed);
  for (int i = 0; i < 200; ++i) {
    // A long thin footprint across the texture: 16 probes over many texels.
    items.push_back(footprint_sample_item(static_cast<int32_t>(rng() % (16 * kOne)),
                                          static_cast<int32_t>(rng() % (16 * kOne)), 12 * kOne,
                                          static_cast<int32_t>(rng() % (4 * kOne)), 0, kOne / 4,
                                          static_cast<uint32_t>(rng())));
    // A texel index the next fragments read, to a new colour.
    const std::vector<uint8_t>& bank = tex.banks[rng() % 8];
    items.push_back(
        footprint_clut_item(bank.at(rng() % bank.size()), static_cast<uint32_t>(rng())));
  }
  for (const double stall : {0.0, 0.6}) {
    SCOPED_TRACE("in-idle and out-stall " + std::to_string(stall));
    CosimOptions c = options(3, 0, {"hls", "rtl"});
    c.in_idle = c.out_stall = stall;
    const CosimResult r = run_vectors(block, items, c);
    EXPECT_EQ(counter_value(r.runs.at("golden").counters, "probes"), 200u * 16u);
  }
}

}  // namespace
}  // namespace tmu::tb
