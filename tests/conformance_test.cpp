// The conformance suite: the same checks for every block of rtl/blocks.cmake, in every variant
// there (built from the variant's `texsim cosim` options, as a user would), and every mutant
// of the table there. A block's own test file keeps only what is truly its own.
//
// For each block and variant:
//   - golden = hls = rtl on the directed items and random ones under 25 % bubbles and stalls:
//     outputs, counters and every memory request (address and order), the rtl run repeated
//     with other random initial values (X check), every coverage case hit;
//   - heavy back-pressure (60 % bubbles, 60 % output stalls), and the output mostly stalled;
//   - random runs long enough that a block with a configuration draws several environments,
//     written between batches as a driver would;
//   - an injected wrong bit caught by rtl, with a waveform, and its printed reproduce line,
//     parsed as `texsim cosim` parses it, failing the same way.
// For each mutant: the cosim on the mutated model fails (or, for an x-leak mutant, its two
// runs with different random initial values differ).
#include <gtest/gtest.h>

#include <filesystem>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "blocks/registry.hpp"
#include "harness/cosim.hpp"
#include "harness/described_block.hpp"
#include "tests/cosim_test_support.hpp"
#include "tests/mutant_cases.hpp"
#include "texsim/cosim_options.hpp"

namespace tmu::tb {

// How GoogleTest prints a case (ctest's test names end in it): the variant, not its bytes.
void PrintTo(const BlockVariant& v, std::ostream* os) {
  *os << v.block << (v.key.empty() ? "" : "/" + v.key);
}
void PrintTo(const MutantCase& m, std::ostream* os) {
  *os << m.block << (m.key.empty() ? "" : "/" + m.key) << " mutant " << m.name;
}

namespace {

std::string case_name(const std::string& block, const std::string& key) {
  return key.empty() ? block : block + "_" + key;
}

// The block of a variant as `texsim cosim BLOCK OPTIONS --seed SEED` makes it.
std::unique_ptr<Block> block_of(const BlockVariant& v, uint64_t seed) {
  const texsim::CosimRequest r =
      texsim::parse_cosim_line(v.block + " " + v.options + " --seed " + std::to_string(seed));
  return make_block(r.block, r.block_options);
}

BlockVariant variant_of(const std::string& block, const std::string& key) {
  for (const BlockVariant& v : block_variants()) {
    if (v.block == block && v.key == key) return v;
  }
  throw std::invalid_argument("no variant " + case_name(block, key));
}

// The timed levels golden is compared with: hls where the block has it, and rtl.
std::vector<std::string> timed_levels(const Block& block) {
  std::vector<std::string> out;
  const auto* d = dynamic_cast<const DescribedBlock*>(&block);
  for (const std::string level : {"hls", "rtl"}) {
    if (!d) {
      out.push_back(level);
      continue;
    }
    for (const std::string& l : d->levels()) {
      if (l == level) out.push_back(level);
    }
  }
  return out;
}

CosimOptions options(uint64_t seed, size_t count, std::vector<std::string> engines) {
  return testing::cosim_options(seed, count, std::move(engines));
}

void expect_every_case_hit(const CosimResult& r) {
  for (const auto& [name, n] : r.coverage) EXPECT_GT(n, 0u) << "coverage case not hit: " << name;
}

class Conformance : public ::testing::TestWithParam<BlockVariant> {};

TEST_P(Conformance, GoldenEqualsEveryLevelUnderStalls) {
  const auto block = block_of(GetParam(), 11);
  std::stringstream log;
  const CosimResult r = run_cosim(*block, options(11, 3000, timed_levels(*block)), log);
  EXPECT_TRUE(r.pass) << log.str();
  EXPECT_EQ(r.x_check, XCheck::kIdentical) << log.str();
  expect_every_case_hit(r);
}

TEST_P(Conformance, HeavyBackPressure) {
  const auto block = block_of(GetParam(), 12);
  CosimOptions o = options(12, 1000, timed_levels(*block));
  o.in_idle = 0.6;
  o.out_stall = 0.6;
  std::stringstream log;
  EXPECT_TRUE(run_cosim(*block, o, log).pass) << log.str();
}

// The output never ready for long stretches: the pipeline holds and drops nothing.
TEST_P(Conformance, OutputMostlyStalled) {
  const auto block = block_of(GetParam(), 13);
  CosimOptions o = options(13, 500, timed_levels(*block));
  o.directed = false;
  o.in_idle = 0.0;
  o.out_stall = 0.95;
  std::stringstream log;
  EXPECT_TRUE(run_cosim(*block, o, log).pass) << log.str();
}

// A long random run: a block with a configuration gets a new environment every few thousand
// transactions (written between batches), every one of them checked.
TEST_P(Conformance, RandomRunsReconfigure) {
  const auto block = block_of(GetParam(), 14);
  CosimOptions o = options(14, 12000, {"rtl"});
  o.directed = false;
  const std::vector<Txn> items = build_stimulus(*block, o);
  const auto* d = dynamic_cast<const DescribedBlock*>(block.get());
  ASSERT_NE(d, nullptr);
  if (d->port_table().cfg_op() >= 0) {
    size_t configs = 0;
    for (const Txn& t : items) configs += d->port_table().is_cfg(t);
    EXPECT_GE(configs, 3u) << "a random run of 12000 items should draw several environments";
  }
  std::stringstream log;
  EXPECT_TRUE(run_cosim(*block, o, log).pass) << log.str();
}

// A deliberately wrong bit in output 7 is caught on rtl with a waveform of the cycles around
// it, and the printed reproduce line, run as printed, fails the same way.
TEST_P(Conformance, InjectedFaultIsCaughtAndReproduced) {
  const auto block = block_of(GetParam(), 15);
  CosimOptions o = options(15, 200, {"rtl"});
  o.inject_fault = 7;
  o.x_check = false;
  std::stringstream log;
  const CosimResult r = run_cosim(*block, o, log);
  testing::expect_rtl_caught_with_waveform(r, log.str(), "texsim cosim " + block->name());
  const std::string text = log.str();
  const size_t at = text.find("reproduce: texsim cosim ");
  ASSERT_NE(at, std::string::npos) << text;
  const size_t begin = at + std::string("reproduce: texsim cosim ").size();
  const std::string line = text.substr(begin, text.find('\n', begin) - begin);
  EXPECT_NE(line.find("--inject-fault 7"), std::string::npos) << line;

  texsim::CosimRequest again = texsim::parse_cosim_line(line);
  again.cosim.wave_dir = o.wave_dir;
  std::stringstream log2;
  const CosimResult r2 =
      run_cosim(*make_block(again.block, again.block_options), again.cosim, log2);
  EXPECT_FALSE(r2.pass) << log2.str();
  EXPECT_EQ(r2.failing_engine, "rtl");
  const auto first_line = [](const std::string& s) {
    const size_t a = s.find("first at transaction");
    return a == std::string::npos ? std::string() : s.substr(a, s.find('\n', a) - a);
  };
  EXPECT_EQ(first_line(log2.str()), first_line(text));
  EXPECT_FALSE(first_line(text).empty()) << text;
}

INSTANTIATE_TEST_SUITE_P(Blocks, Conformance, ::testing::ValuesIn(block_variants()),
                         [](const ::testing::TestParamInfo<BlockVariant>& p) {
                           return case_name(p.param.block, p.param.key);
                         });

// ---- mutants ------------------------------------------------------------------------------------

class Mutant : public ::testing::TestWithParam<MutantCase> {};

// The block's cosim (directed and random items under stalls) on the mutated model.
TEST_P(Mutant, IsCaught) {
  const MutantCase& m = GetParam();
  const auto block = block_of(variant_of(m.block, m.key), 21);
  const auto& described = dynamic_cast<const DescribedBlock&>(*block);
  CosimOptions o = options(21, 3000, {"rtl"});
  o.x_check = m.expect == "x-leak";
  std::stringstream log;
  const CosimResult r = run_cosim(*block, o, log, [&](const std::string& level) {
    return level == "rtl" ? m.rtl(described) : nullptr;
  });
  if (m.expect == "x-leak") {
    EXPECT_EQ(r.x_check, XCheck::kDifferent) << m.why << "\n" << log.str();
  } else {
    EXPECT_FALSE(r.pass) << m.why << "\n" << log.str();
    EXPECT_EQ(r.failing_engine, "rtl");
  }
  // What caught it, for the reader.
  const std::string text = log.str();
  for (const char* key : {"MISMATCH rtl", "x-check"}) {
    const size_t at = text.find(key);
    if (at != std::string::npos) std::cout << m.why << ":\n" << text.substr(at, 400) << "\n";
  }
  if (const auto rtl = r.runs.find("rtl"); rtl != r.runs.end() && !rtl->second.error.empty()) {
    std::cout << m.why << ":\n  rtl error: " << rtl->second.error.substr(0, 400) << "\n";
  }
}

INSTANTIATE_TEST_SUITE_P(Table, Mutant, ::testing::ValuesIn(mutant_cases()),
                         [](const ::testing::TestParamInfo<MutantCase>& p) {
                           return case_name(p.param.block, p.param.key) + "_" + p.param.name;
                         });

}  // namespace
}  // namespace tmu::tb
