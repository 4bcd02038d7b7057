// Throughput of the CCC decoder at every model level on the same stimulus (texels/s), and
// of the encoder. Prints the ratio of each level against the golden model.
//   build/bench/tmu_ccc_bench [--benchmark_filter=...]
#include <benchmark/benchmark.h>

#include <random>

#include "bench/ratio_reporter.hpp"
#include "blocks/ccc_decoder/ccc_decoder_block.hpp"
#include "ccc/ccc_decoder.hpp"
#include "ccc/ccc_encoder.hpp"
#include "common/test_patterns.hpp"

namespace tmu::bench {
namespace {

// 256 CLUT writes, then `texels` random decodes: the same items for every engine.
const std::vector<tb::Txn>& decoder_items(size_t texels) {
  static std::map<size_t, std::vector<tb::Txn>> cache;
  auto& items = cache[texels];
  if (items.empty()) {
    const tb::CccDecoderBlock block;
    items = block.setup_items();
    std::mt19937_64 rng(7);
    for (size_t i = 0; i < texels; ++i) {
      items.push_back(tb::decode_item(static_cast<uint32_t>(rng()), static_cast<unsigned>(rng())));
    }
  }
  return items;
}

void decode(benchmark::State& state, const std::string& level) {
  const auto texels = static_cast<size_t>(state.range(0));
  const auto& items = decoder_items(texels);
  const auto engine = tb::CccDecoderBlock().engine(level);
  for (auto _ : state) {
    const tb::RunResult r = engine->run(items, tb::RunOptions{});
    if (!r.error.empty() || r.outputs.size() != texels) state.SkipWithError("run failed");
    benchmark::DoNotOptimize(r.outputs.data());
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations()) * static_cast<int64_t>(texels));
}

// Wall time throughout: the hls engine simulates in a forked child.
void BM_CccDecodeGolden(benchmark::State& s) { decode(s, "golden"); }
void BM_CccDecodeHls(benchmark::State& s) { decode(s, "hls"); }
void BM_CccDecodeRtl(benchmark::State& s) { decode(s, "rtl"); }
BENCHMARK(BM_CccDecodeGolden)->Arg(1 << 20)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_CccDecodeHls)->Arg(1 << 20)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_CccDecodeRtl)->Arg(1 << 20)->Unit(benchmark::kMillisecond)->UseRealTime();

// The golden arithmetic alone, without the harness's transaction records: the speed a
// software renderer calling the golden model directly gets.
void BM_CccDecodeGoldenFunction(benchmark::State& state) {
  const auto texels = static_cast<size_t>(state.range(0));
  std::vector<uint32_t> words(texels);
  std::mt19937_64 rng(7);
  for (uint32_t& w : words) w = static_cast<uint32_t>(rng());
  ccc::Clut clut{};
  for (size_t i = 0; i < clut.size(); ++i) clut[i] = unpack_rgb(static_cast<uint32_t>(rng()));
  for (auto _ : state) {
    uint32_t acc = 0;
    for (size_t i = 0; i < texels; ++i)
      acc ^= ccc::decode_texel(words[i], static_cast<unsigned>(i), clut);
    benchmark::DoNotOptimize(acc);
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations()) * static_cast<int64_t>(texels));
}
BENCHMARK(BM_CccDecodeGoldenFunction)->Arg(1 << 20)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_CccEncode(benchmark::State& state) {
  const int side = static_cast<int>(state.range(0));
  const ImageRgb8 img = patterns::default_image(side, side);
  for (auto _ : state) benchmark::DoNotOptimize(ccc::encode(img).blocks.data());
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations()) * side * side);
}
BENCHMARK(BM_CccEncode)->Arg(256)->Arg(1024)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace tmu::bench

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  const std::string golden = "BM_CccDecodeGolden/1048576/real_time";
  tmu::bench::RatioReporter reporter({{"BM_CccDecodeGoldenFunction/1048576/real_time", golden},
                                      {"BM_CccDecodeHls/1048576/real_time", golden},
                                      {"BM_CccDecodeRtl/1048576/real_time", golden}});
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();
}
