// The harness itself: the scoreboard catches what it must, the driver neither drops nor
// duplicates, vector files round-trip and reject bad input with a named field.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "common/error.hpp"
#include "harness/handshake_driver.hpp"
#include "harness/hls_runner.hpp"
#include "harness/scoreboard.hpp"
#include "harness/vector_file.hpp"

namespace tmu::tb {
namespace {

const Schema kOut({{"rgb", fx::UQ(24, 0)}, {"flag", fx::UQ(1, 0)}});

RunResult outputs_of(std::initializer_list<uint64_t> values) {
  RunResult r;
  for (uint64_t v : values) {
    Txn t;
    t.f[0] = v;
    r.outputs.push_back(t);
    r.output_cycles.push_back(r.outputs.size());
  }
  return r;
}

// --- the hls engine's child process ---------------------------------------------------------

// What the child computed arrives whole: every field of every output, request and counter, the
// cycles, seconds and error; a child that dies or throws becomes an error, not a result.
TEST(RunInChildTest, TheResultCrossesThePipeWhole) {
  RunResult sent = outputs_of({7, 0xFFFF'FFFF'FFFF'FFFFu, 0});
  sent.outputs[1].f[31] = 0x8000'0000'0000'0001u;
  sent.cycles = 12345;
  sent.counters = {{"hits", 3}, {"", 0}, {"page_faults", 1u << 31}};
  sent.requests = {{}, std::vector<Txn>(70'000)};  // more than the pipe holds: read as written
  for (size_t i = 0; i < sent.requests[1].size(); ++i) sent.requests[1][i].f[i % 32] = i;
  sent.seconds = 0.25;
  sent.error = "a message\nof two lines";
  const RunResult got = run_in_child([&] { return sent; });
  EXPECT_EQ(got.outputs, sent.outputs);
  EXPECT_EQ(got.output_cycles, sent.output_cycles);
  EXPECT_EQ(got.cycles, sent.cycles);
  EXPECT_EQ(got.counters, sent.counters);
  EXPECT_EQ(got.requests, sent.requests);
  EXPECT_EQ(got.seconds, sent.seconds);
  EXPECT_EQ(got.error, sent.error);
}

TEST(RunInChildTest, AChildThatDiesOrThrowsIsAnError) {
  EXPECT_EQ(run_in_child([]() -> RunResult { ::_exit(5); }).error,
            "hls child exited with status 5");
  EXPECT_EQ(run_in_child([]() -> RunResult { std::abort(); }).error,
            "hls child killed by signal 6");
  EXPECT_EQ(run_in_child([]() -> RunResult { throw std::runtime_error("no clock"); }).error,
            "hls: no clock");
}

// --- scoreboard -------------------------------------------------------------------------

TEST(ScoreboardTest, IdenticalRunsMatch) {
  const auto a = outputs_of({1, 2, 3});
  EXPECT_TRUE(compare(kOut, a, a).match());
  EXPECT_EQ(compare(kOut, a, a).compared, 3u);
}

TEST(ScoreboardTest, OneFlippedBitIsCaughtWithItsIndexAndField) {
  const auto golden = outputs_of({0x111111, 0x222222, 0x333333});
  auto rtl = golden;
  rtl.outputs[1].f[1] ^= 1;  // the second field of the second transaction
  const Comparison c = compare(kOut, golden, rtl);
  EXPECT_FALSE(c.match());
  ASSERT_TRUE(c.first.has_value());
  EXPECT_EQ(c.first->output_index, 1u);
  EXPECT_EQ(c.first->fields, std::vector<int>{1});
  EXPECT_NE(mismatch_table(kOut, *c.first).find("differs"), std::string::npos);
}

TEST(ScoreboardTest, MissingExtraAndReorderedOutputsFail) {
  const auto golden = outputs_of({1, 2, 3});
  EXPECT_FALSE(compare(kOut, golden, outputs_of({1, 2})).match());        // dropped
  EXPECT_FALSE(compare(kOut, golden, outputs_of({1, 2, 3, 3})).match());  // duplicated
  EXPECT_FALSE(compare(kOut, golden, outputs_of({1, 3, 2})).match());     // reordered
  const Comparison missing = compare(kOut, golden, outputs_of({1, 2}));
  ASSERT_TRUE(missing.first.has_value());
  EXPECT_FALSE(missing.first->got.has_value());
}

TEST(ScoreboardTest, CountersAndEngineErrorsFail) {
  auto golden = outputs_of({1});
  golden.counters = {{"hits", 5}};
  auto rtl = golden;
  rtl.counters = {{"hits", 6}};
  EXPECT_FALSE(compare(kOut, golden, rtl).match());
  rtl.counters = {};
  EXPECT_FALSE(compare(kOut, golden, rtl).match());  // a counter the reference predicts is missing
  rtl = golden;
  rtl.error = "deadlock";
  EXPECT_FALSE(compare(kOut, golden, rtl).match());
}

// --- handshake driver -------------------------------------------------------------------

// A one-register model of a block that takes an item when empty or being emptied.
TEST(HandshakeDriverTest, StallsNeitherDropNorDuplicate) {
  std::vector<Txn> items(500);
  for (size_t i = 0; i < items.size(); ++i) items[i].f[0] = i;
  RunOptions opt;
  opt.stalls = {42, 0.5, 0.5};
  HandshakeDriver d(items, ItemPlan::without_config(items.size(), items.size()), opt);
  bool full = false;
  Txn reg;
  while (!d.done()) {
    const Txn* in = d.begin_cycle();
    const bool ready = !full || d.out_ready();
    const bool out_fire = full && d.out_ready();
    const Txn out = reg;
    const bool in_fire = in != nullptr && ready;
    if (out_fire) full = false;
    if (in_fire) {
      reg = *in;
      full = true;
    }
    d.end_cycle(in_fire, out_fire ? &out : nullptr);
  }
  for (size_t i = 0; i < items.size(); ++i) EXPECT_EQ(d.result().outputs[i].f[0], i);
  EXPECT_GT(d.cycle(), items.size() * 3 / 2);  // the stalls really happened
}

TEST(HandshakeDriverTest, DuplicateOutputThrows) {
  std::vector<Txn> items(1);
  HandshakeDriver d(items, ItemPlan::without_config(1, 1), RunOptions{});
  const Txn out;
  d.begin_cycle();
  d.end_cycle(true, &out);
  d.begin_cycle();
  EXPECT_THROW(d.end_cycle(false, &out), std::runtime_error);
}

TEST(HandshakeDriverTest, DeadlockThrows) {
  std::vector<Txn> items(1);
  RunOptions opt;
  opt.max_idle_cycles = 10;
  HandshakeDriver d(items, ItemPlan::without_config(1, 1), opt);
  EXPECT_THROW(
      {
        for (int i = 0; i < 20; ++i) {
          d.begin_cycle();
          d.end_cycle(false, nullptr);
        }
      },
      std::runtime_error);
}

// A configuration item waits until every output of the items before it is out and the block
// has been quiet for kQuietCycles cycles, is applied in one cycle, and is never presented.
TEST(HandshakeDriverTest, ConfigurationWaitsForTheBlockToBeQuiet) {
  std::vector<Txn> items(3);
  ItemPlan plan;
  plan.outputs = {1, 0, 1};
  plan.config = {false, true, false};
  plan.total = 2;
  HandshakeDriver d(items, plan, RunOptions{});
  // The first item is taken; its output comes 5 cycles later.
  ASSERT_EQ(d.begin_cycle(), &items[0]);
  EXPECT_FALSE(d.configuring());
  d.end_cycle(true, nullptr);
  int cycle = 1;
  for (; cycle < 6; ++cycle) {
    EXPECT_EQ(d.begin_cycle(), nullptr) << cycle;  // the output of item 0 is not out yet
    const Txn out;
    d.end_cycle(false, cycle == 5 ? &out : nullptr);
  }
  for (int quiet = 0; quiet < kQuietCycles; ++quiet, ++cycle) {
    EXPECT_EQ(d.begin_cycle(), nullptr) << cycle;
    d.end_cycle(false, nullptr);
  }
  ASSERT_EQ(d.begin_cycle(), &items[1]);
  EXPECT_TRUE(d.configuring());
  d.end_cycle(false, nullptr);
  ASSERT_EQ(d.begin_cycle(), &items[2]);
  EXPECT_FALSE(d.configuring());
}

// Something in flight (a request outstanding) holds the configuration back.
TEST(HandshakeDriverTest, ConfigurationWaitsWhileTheBlockIsBusy) {
  std::vector<Txn> items(1);
  ItemPlan plan;
  plan.outputs = {0};
  plan.config = {true};
  HandshakeDriver d(items, plan, RunOptions{});
  for (int i = 0; i < 50; ++i) {
    EXPECT_EQ(d.begin_cycle(/*quiet=*/false), nullptr);
    d.end_cycle(false, nullptr);
  }
  for (int i = 0; i < kQuietCycles; ++i) {
    EXPECT_EQ(d.begin_cycle(true), nullptr);
    d.end_cycle(false, nullptr);
  }
  EXPECT_EQ(d.begin_cycle(true), &items[0]);
  EXPECT_TRUE(d.configuring());
}

// --- vector files -----------------------------------------------------------------------

const Schema kIn({{"op", fx::UQ(1, 0)}, {"u", fx::SQ(16, 8)}, {"rgb", fx::UQ(24, 0)}});

std::string temp_file(const std::string& name, const std::string& content) {
  const auto path = std::filesystem::temp_directory_path() / ("tmu_vec_" + name);
  std::ofstream(path) << content;
  return path.string();
}

TEST(VectorFileTest, RoundTripsAndAcceptsAnyColumnOrder) {
  std::vector<Txn> items(3);
  items[0].f = {1, 0xFFFF80, 0xABCDEF};
  items[2].f = {0, 0x7FFFFF, 1};
  const std::string path = temp_file("rt.csv", "");
  write_vectors(path, kIn, items);
  EXPECT_EQ(read_vectors(path, kIn), items);
  const auto reordered =
      read_vectors(temp_file("order.csv", "# comment\nrgb,u\n0x10, -128\n"), kIn);
  ASSERT_EQ(reordered.size(), 1u);
  EXPECT_EQ(reordered[0].f[1], 0xFFFF80u);  // -0.5 as 24-bit two's complement
  EXPECT_EQ(reordered[0].f[2], 0x10u);
}

TEST(VectorFileTest, BadInputNamesTheLineAndField) {
  auto field_of = [](const std::string& content) {
    try {
      read_vectors(temp_file("bad.csv", content), kIn);
    } catch (const InputError& e) {
      return e.field() + " / " + e.reason();
    }
    return std::string("no error");
  };
  EXPECT_EQ(field_of("op,bogus\n"), "line 1: header / unknown field 'bogus' (fields: op, u, rgb)");
  EXPECT_NE(field_of("op,u\n2,0\n").find("line 2: op"), std::string::npos);         // out of range
  EXPECT_NE(field_of("op,u\n0,0x1000000\n").find("line 2: u"), std::string::npos);  // too wide
  EXPECT_NE(field_of("op,u\n0\n").find("line 2"), std::string::npos);               // short row
  EXPECT_NE(field_of("op,u\n0,abc\n").find("not a number"), std::string::npos);
  EXPECT_NE(field_of("").find("header"), std::string::npos);
  EXPECT_THROW(read_vectors("/nonexistent/v.csv", kIn), InputError);
}

}  // namespace
}  // namespace tmu::tb
