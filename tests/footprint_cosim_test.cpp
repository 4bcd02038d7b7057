// Footprint assembly (000 §10): golden vs rtl (and hls) bit for bit, the memory's counters and
// the probe count included, on the block's directed hard cases and random fragments under
// back-pressure, in every border mode, at every maximum probe count with both q rules, at
// other setup widths (the log2 table built at elaboration for other T and F); its throughput
// (one probe per clock into the trilinear unit, fragments back to back without bubbles); and
// proof that the comparison has teeth (RTL mutants: the average's rounding constant, the
// probes' first position, k's rounding; an injected wrong bit).
#include <Vtmu_footprint.h>
#include <Vtmu_footprint_mutant_k.h>
#include <Vtmu_footprint_mutant_round.h>
#include <Vtmu_footprint_mutant_step.h>
#include <gtest/gtest.h>

#include <array>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <tuple>

#include "blocks/footprint_block.hpp"
#include "harness/cosim.hpp"
#include "harness/vector_file.hpp"
#include "tests/cosim_test_support.hpp"

namespace tmu::tb {
namespace {

namespace fs = std::filesystem;
using footprint::QRule;
using texram::Border;
using texram::Combine;
using texram::Filter;
using texram::TexelKind;

fs::path temp_dir() { return testing::temp_dir("tmu_footprint_cosim_test"); }
constexpr auto options = testing::cosim_options;
constexpr int32_t kOne = 256;

constexpr std::array<Border, 4> kBorders = {Border::kWrap, Border::kClamp, Border::kBorder,
                                            Border::kMirror};
constexpr std::array<TexelKind, 5> kKinds = {TexelKind::kLuminance, TexelKind::kIndex,
                                             TexelKind::kTrueColour, TexelKind::kSingle,
                                             TexelKind::kCcc};

uint64_t counter(const RunResult& r, const std::string& name) {
  const auto v = counter_value(r.counters, name);
  if (!v) ADD_FAILURE() << "no counter " << name;
  return v.value_or(0);
}

CosimResult cosim(const FootprintBlock& block, uint64_t seed, size_t count,
                  std::vector<std::string> engines = {"rtl"}) {
  std::stringstream log;
  const CosimResult r = run_cosim(block, options(seed, count, std::move(engines)), log);
  EXPECT_TRUE(r.pass) << block.describe() << "\n" << log.str();
  return r;
}

// --- every configuration -------------------------------------------------------------------

// Every maximum probe count (1 .. 16) with both q rules: ten runs of the directed items and
// 15000 random fragments under back-pressure (in-idle 0.25, out-stall 0.25, the rtl twice for
// the X check), border modes of u cycling through all four (v another), the texel kind,
// filter and texture varying. The union of the coverage must hit every case; the rtl's probe
// counter is the golden sum of 2^k. Two of the runs also go through the hls model.
TEST(FootprintCosimTest, EveryMaxProbesQRuleAndBorderMode) {
  Coverage all;
  uint64_t seed = 500;
  for (int max = 0; max <= 4; ++max) {
    for (QRule rule : {QRule::kHeights, QRule::kSides}) {
      ++seed;
      BlockOptions o;
      o.seed = seed;
      o.fp_log2_max_probes = max;
      o.fp_q_rule = rule;
      o.tri_border_u = kBorders[seed % 4];
      o.tri_border_v = kBorders[(seed / 4 + seed) % 4];
      o.tri_kind = kKinds[seed % 5];
      o.tri_filter = seed % 3 == 0 ? Filter::kBilinear : Filter::kTrilinear;
      o.tri_combine = seed % 2 == 0 ? Combine::kOne : Combine::kShade;
      o.tri_log2_w = 4 + static_cast<int>(seed % 4);  // 16 .. 128 texels
      o.tri_log2_h = 4 + static_cast<int>((seed / 2) % 4);
      const FootprintBlock block(o);
      SCOPED_TRACE(block.describe());
      const bool with_hls = max == 4;
      const CosimResult r = cosim(
          block, seed, 15000,
          with_hls ? std::vector<std::string>{"hls", "rtl"} : std::vector<std::string>{"rtl"});
      EXPECT_EQ(counter(r.runs.at("rtl"), "probes"), counter(r.runs.at("golden"), "probes"));
      for (const auto& [name, n] : r.coverage) all[name] += n;
    }
  }
  for (const auto& [name, n] : all) EXPECT_GT(n, 0u) << "coverage case not hit: " << name;
  EXPECT_GT(all["probe wrapped beyond the port (wrap, mirror)"], 0u);
  EXPECT_GT(all["probe saturated beyond the port (clamp, border)"], 0u);
  EXPECT_GT(all["every probe 255 in R, G or B (sum 16 x 255)"], 0u);
  std::cout << "10 configurations; coverage over all:\n";
  for (const auto& [name, n] : all) std::cout << "  " << name << ": " << n << "\n";
}

// The directed hard cases in every border mode pair (wrap or saturate per axis beyond the
// port, the texture's edges), 16 probes at most, both q rules, and a few random fragments.
TEST(FootprintCosimTest, DirectedCasesInEveryBorderMode) {
  for (Border bu : kBorders) {
    for (Border bv : kBorders) {
      BlockOptions o;
      o.seed = 7;
      o.fp_log2_max_probes = 4;
      o.fp_q_rule = bu == bv ? QRule::kSides : QRule::kHeights;
      o.tri_kind = TexelKind::kLuminance;
      o.tri_filter = Filter::kTrilinear;
      o.tri_border_u = bu;
      o.tri_border_v = bv;
      o.tri_log2_w = 5;
      o.tri_log2_h = 4;
      const FootprintBlock block(o);
      SCOPED_TRACE(block.describe());
      cosim(block, 7, 500);
    }
  }
}

// Other setup widths: the table follows T and F (computed at elaboration), lambda's rounding
// takes its widening path (F = 5: G = 6 < 8) or drops 5 bits (F = 12), the block-floating
// shift starts at 8 or 16 bits.
TEST(FootprintCosimTest, OtherSetupWidths) {
  for (const footprint::Widths& w : {footprint::Widths{8, 4, 5}, footprint::Widths{16, 10, 12}}) {
    for (QRule rule : {QRule::kHeights, QRule::kSides}) {
      BlockOptions o;
      o.seed = 31 + static_cast<uint64_t>(w.log_frac);
      o.fp_widths = w;
      o.fp_log2_max_probes = 4;
      o.fp_q_rule = rule;
      o.tri_kind = TexelKind::kIndex;
      o.tri_log2_w = 6;
      o.tri_log2_h = 6;
      const FootprintBlock block(o);
      SCOPED_TRACE(block.describe());
      cosim(block, o.seed, 5000);
    }
  }
}

// --- throughput ----------------------------------------------------------------------------

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
  o.fp_q_rule = QRule::kHeights;
  o.tri_kind = TexelKind::kLuminance;
  o.tri_filter = Filter::kTrilinear;
  o.tri_log2_w = 8;
  o.tri_log2_h = 8;
  o.tri_pattern = "smooth";
  const FootprintBlock block(o);
  std::vector<Txn> items = block.setup_items();
  size_t fragments = 0;
  // A rasterized span: rows of fragments a quarter texel apart, the same footprint: mostly
  // page hits.
  for (int32_t row = 0; row < 8; ++row) {
    for (int32_t i = 0; i < 200; ++i, ++fragments) {
      items.push_back(footprint_sample_item(40 * kOne + i * kOne / 4, (30 + 5 * row) * kOne + 77,
                                            r1u, 0, 0, r2v, 0x80808080u));
    }
  }
  const fs::path file = temp_dir() / "span.csv";
  write_vectors(file.string(), block.inputs(), items);
  CosimOptions c = options(5, 0, {"rtl"});
  c.vectors_in = file.string();
  c.in_idle = 0.0;
  c.out_stall = 0.0;
  c.x_check = false;
  std::stringstream log;
  const CosimResult r = run_cosim(block, c, log);
  EXPECT_TRUE(r.pass) << log.str();
  const RunResult& rtl = r.runs.at("rtl");
  return {fragments, counter(rtl, "probes"), rtl.cycles,
          counter(r.runs.at("golden"), "slow_accesses")};
}

// One probe per clock into the trilinear unit: a fragment of N probes takes N clocks, and
// back-to-back fragments do not bubble. 256 CLUT writes (one per clock), the setup, marcher,
// trilinear and average latency (21 cycles) and the 16 drain cycles come on top; each page
// fault costs the trilinear unit a clock.
TEST(FootprintCosimTest, OneProbePerClock) {
  constexpr uint64_t kOverhead = 256 + 21 + 16;
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

// --- teeth ---------------------------------------------------------------------------------

template <class Model>
CosimResult run_mutant(const FootprintBlock& block, uint64_t seed, size_t count,
                       std::stringstream& log) {
  CosimOptions o = options(seed, count, {"rtl"});
  o.x_check = false;
  return run_cosim(block, o, log, [&block](const std::string& level) -> std::unique_ptr<Engine> {
    if (level != "rtl") return nullptr;
    return make_footprint_rtl_engine<Model>("rtl", block.env());
  });
}

FootprintBlock mutant_block() {
  BlockOptions o;
  o.seed = 9;
  o.fp_log2_max_probes = 4;
  o.fp_q_rule = QRule::kHeights;
  o.tri_kind = TexelKind::kTrueColour;
  o.tri_filter = Filter::kTrilinear;
  o.tri_border_u = o.tri_border_v = Border::kWrap;
  o.tri_log2_w = 5;
  o.tri_log2_h = 5;
  return FootprintBlock(o);
}

// The average adds a quarter instead of half of N before its shift.
TEST(FootprintCosimTest, RoundingMutantIsCaughtWithAWaveform) {
  const FootprintBlock block = mutant_block();
  std::stringstream log;
  const CosimResult r = run_mutant<Vtmu_footprint_mutant_round>(block, 9, 300, log);
  testing::expect_rtl_caught_with_waveform(r, log.str(), "texsim cosim footprint --seed 9");
}

// The probes start half a probe spacing off along u (the first numerator misses its + d).
TEST(FootprintCosimTest, ProbePositionMutantIsCaught) {
  const FootprintBlock block = mutant_block();
  std::stringstream log;
  const CosimResult r = run_mutant<Vtmu_footprint_mutant_step>(block, 9, 300, log);
  EXPECT_FALSE(r.pass);
  EXPECT_NE(log.str().find("MISMATCH rtl vs golden"), std::string::npos) << log.str();
}

// k rounds rho up from three quarters instead of a half: the directed threshold ratios alone
// catch it (fewer probes: different colours, and the probe counter differs).
TEST(FootprintCosimTest, KRoundingMutantIsCaught) {
  const FootprintBlock block = mutant_block();
  std::stringstream log;
  const CosimResult r = run_mutant<Vtmu_footprint_mutant_k>(block, 9, 0, log);
  EXPECT_FALSE(r.pass);
  EXPECT_NE(log.str().find("counter probes: expected"), std::string::npos) << log.str();
}

// An injected wrong bit fails the run at that transaction.
TEST(FootprintCosimTest, InjectedFaultFailsTheRun) {
  const FootprintBlock block = mutant_block();
  CosimOptions o = options(5, 200, {"rtl"});
  o.inject_fault = 150;
  std::stringstream log;
  const CosimResult r = run_cosim(block, o, log);
  EXPECT_FALSE(r.pass);
  EXPECT_NE(log.str().find("first at transaction 150"), std::string::npos) << log.str();
}

}  // namespace
}  // namespace tmu::tb
