// What is the volume block's own (000 §13; docs/volume.md "The block"; the conformance suite,
// tests/conformance_test.cpp, checks what every block shares): the rtl's cycles per resample
// (one access per clock, a page fault a clock more, rays back to back) on the figures' ray
// sets, and the configuration errors that name their field.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "blocks/volume/volume_block.hpp"
#include "harness/engine.hpp"

namespace tmu::tb {
namespace {

uint64_t counter(const RunResult& r, const std::string& name) {
  const auto v = counter_value(r.counters, name);
  EXPECT_TRUE(v.has_value()) << name;
  return v.value_or(0);
}

// The first `rays` rays of a figure's set in one mode, run by rtl without stalls: every
// output equals golden's, and from the first resample to the last the unit takes one clock per
// access and one more per slow access (a page fault in any bank), nothing else: consecutive
// locations and rays follow without a gap.
void expect_one_access_per_clock(const std::string& set, int mode, size_t rays) {
  BlockOptions o;
  o.vol_rays = set;
  o.vol_mode = mode;
  const VolumeBlock block(o);
  std::mt19937_64 rng(1);
  std::vector<Txn> items = block.setup_items();
  for (const Txn& t : block.random_items(rng, rays)) items.push_back(t);
  const RunResult golden = block.engine("golden")->run(items, RunOptions{});
  const RunResult rtl = block.engine("rtl")->run(items, RunOptions{});
  ASSERT_TRUE(rtl.error.empty()) << rtl.error;
  ASSERT_EQ(rtl.outputs, golden.outputs);
  ASSERT_EQ(rtl.requests, golden.requests);
  ASSERT_EQ(rtl.counters, golden.counters);
  const uint64_t resamples = counter(golden, "resamples");
  const uint64_t accesses = counter(golden, "accesses");
  const uint64_t slow = counter(golden, "slow_accesses");
  ASSERT_EQ(accesses, resamples * (mode ? 8u : 2u));
  // The first resample's accesses come before its output: the span covers the others'.
  const uint64_t per = mode ? 8 : 2;
  const uint64_t span = rtl.output_cycles.back() - rtl.output_cycles.front();
  uint64_t first_slow = 0;  // the first location's faults (its every bank is a new page)
  {
    const std::vector<Txn> one = {items[0], volume_ray_item({volume_ray_of(items[1]).start,
                                                             volume_ray_of(items[1]).step, 1})};
    first_slow = counter(block.engine("golden")->run(one, RunOptions{}), "slow_accesses");
  }
  EXPECT_EQ(span, accesses - per + slow - first_slow) << set << " mode " << mode;
  std::printf(
      "volume rtl, %s rays, %s mode: %llu resamples, %.4f cycles a resample "
      "(%.4f slow accesses a resample)\n",
      set.c_str(), mode ? "raw" : "value", static_cast<unsigned long long>(resamples),
      double(rtl.cycles) / double(resamples), double(slow) / double(resamples));
}

TEST(VolumeBlockTest, OneAccessPerClockValueMode) {
  expect_one_access_per_clock("z", 0, 96);
  expect_one_access_per_clock("x", 0, 96);
}

TEST(VolumeBlockTest, OneAccessPerClockRawMode) {
  expect_one_access_per_clock("z", 1, 48);
  expect_one_access_per_clock("oblique", 1, 48);
}

// A configuration the unit cannot take is an error that names the field and the reason.
TEST(VolumeBlockTest, BadConfigurationNamesTheField) {
  VolumeSetup s;
  s.size = {5, 6, 7};
  const auto message = [](const VolumeSetup& setup) {
    try {
      volume_setup_of(volume_cfg_item(setup));
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message(s), "no error");
  VolumeSetup w = s;
  w.config.weight_bits = 0;
  EXPECT_NE(message(w).find("cfg.weight_bits 0"), std::string::npos) << message(w);
  w.config.weight_bits = 9;
  EXPECT_NE(message(w).find("1..8"), std::string::npos) << message(w);
  VolumeSetup n = s;
  n.size[1] = 1;
  EXPECT_NE(message(n).find("cfg.size[1] (y) 1"), std::string::npos) << message(n);
  n.size[1] = 513;
  EXPECT_NE(message(n).find("2..512"), std::string::npos) << message(n);
  VolumeSetup big = s;
  big.size = {512, 512, 512};
  EXPECT_NE(message(big).find("2^21 cells"), std::string::npos) << message(big);
  // The golden level reports it as its run's error.
  const VolumeBlock block;
  const RunResult r = block.engine("golden")->run({volume_cfg_item(big)}, RunOptions{});
  EXPECT_NE(r.error.find("cfg.size"), std::string::npos) << r.error;
}

}  // namespace
}  // namespace tmu::tb
