#include "blocks/deflect_block.hpp"

#include <Vtmu_deflect.h>
#include <fmt/format.h>

#include <algorithm>
#include <chrono>

#include "formats/formats.hpp"
#include "harness/hls_runner.hpp"
#include "hls/deflect/deflect_sc.hpp"

namespace tmu::tb {
namespace fmts = tmu::formats;
using deflect::MapAccess;
using deflect::SphereAngle;

namespace {

const Schema kInputs({{"normal_phi", fmts::kSpherePhi},
                      {"normal_theta", fmts::kSphereTheta},
                      {"bump_phi", fmts::kSpherePhi},
                      {"bump_theta", fmts::kSphereTheta}});
const Schema kOutputs({{"phi", fmts::kSpherePhi},
                       {"theta", fmts::kSphereTheta},
                       {"access", fmts::kMapAccess}});

// The grid of the ports (A = 9: 512 x 256).
const deflect::SphereGrid kGrid{fmts::kSpherePhi.width()};
const auto kQ = static_cast<int32_t>(kGrid.quarter());
const auto kPhiCount = static_cast<int32_t>(kGrid.phi_count());
const uint32_t kMinusZero = 1u << kGrid.mag_bits();  // theta -0: sign set, magnitude 0

// Uniform in lo..hi (inclusive) from the generator's raw output (no std distributions, so
// the stimulus is the same on every standard library).
int64_t uniform(std::mt19937_64& rng, int64_t lo, int64_t hi) {
  return lo + static_cast<int64_t>(rng() % static_cast<uint64_t>(hi - lo + 1));
}

uint32_t wrap_phi(int64_t steps) {
  return static_cast<uint32_t>(((steps % kPhiCount) + kPhiCount) % kPhiCount);
}

Counters golden_counters(uint64_t hits, uint64_t misses, uint64_t bypasses) {
  return {{"hits", hits}, {"misses", misses}, {"bypasses", bypasses}, {"block_fetches", misses}};
}

class GoldenEngine : public Engine {
 public:
  explicit GoldenEngine(std::shared_ptr<const deflect::S2sMap> map) : map_(std::move(map)) {}
  std::string name() const override { return "golden"; }
  RunResult run(const std::vector<Txn>& items, const RunOptions&) override {
    RunResult r;
    r.outputs.reserve(items.size());
    const auto start = std::chrono::steady_clock::now();
    deflect::DeflectionUnit unit(*map_);
    uint64_t counts[3] = {0, 0, 0};
    for (const Txn& t : items) {
      const deflect::Deflected d = unit.deflect(deflect_normal(t), deflect_bump(t));
      Txn out;
      out.f[kDflOutPhi] = d.normal.phi;
      out.f[kDflOutTheta] = d.normal.theta;
      out.f[kDflOutAccess] = static_cast<uint64_t>(d.access);
      ++counts[static_cast<size_t>(d.access)];
      r.outputs.push_back(out);
    }
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    r.output_cycles.assign(r.outputs.size(), 0);
    r.counters = golden_counters(counts[0], counts[1], counts[2]);
    return r;
  }

 private:
  std::shared_ptr<const deflect::S2sMap> map_;
};

// The hls module with its signals, the map memory and the access monitor.
class HlsBench : public sc_core::sc_module, public ScAdapter {
 public:
  HlsBench(sc_core::sc_module_name name, sc_core::sc_clock& clk, sc_core::sc_signal<bool>& rst_n,
           std::shared_ptr<const deflect::S2sMap> map, S2sMemoryTiming timing, uint64_t memory_seed)
      : sc_module(name), dut_("dut"), memory_(std::move(map), timing, memory_seed) {
    dut_.clk_i(clk);
    dut_.rst_ni(rst_n);
    dut_.in_valid_i(in_valid_);
    dut_.in_ready_o(in_ready_);
    dut_.in_normal_phi_i(in_normal_phi_);
    dut_.in_normal_theta_i(in_normal_theta_);
    dut_.in_bump_phi_i(in_bump_phi_);
    dut_.in_bump_theta_i(in_bump_theta_);
    dut_.out_valid_o(out_valid_);
    dut_.out_ready_i(out_ready_);
    dut_.out_phi_o(out_phi_);
    dut_.out_theta_o(out_theta_);
    dut_.out_access_o(out_access_);
    dut_.map_req_valid_o(map_req_valid_);
    dut_.map_req_block_o(map_req_block_);
    dut_.map_resp_valid_i(map_resp_valid_);
    dut_.map_resp_data_i(map_resp_data_);
  }
  void drive(const Txn* item) override {
    in_valid_.write(item != nullptr);
    in_normal_phi_.write(item ? item->f[kDflNormalPhi] : 0);
    in_normal_theta_.write(item ? item->f[kDflNormalTheta] : 0);
    in_bump_phi_.write(item ? item->f[kDflBumpPhi] : 0);
    in_bump_theta_.write(item ? item->f[kDflBumpTheta] : 0);
  }
  bool accepts(const Txn&) const override { return in_ready_.read(); }
  void set_out_ready(bool ready) override { out_ready_.write(ready); }
  bool out_valid() const override { return out_valid_.read(); }
  Txn out() const override {
    Txn t;
    t.f[kDflOutPhi] = out_phi_.read();
    t.f[kDflOutTheta] = out_theta_.read();
    t.f[kDflOutAccess] = out_access_.read();
    return t;
  }
  void env_drive() override {
    const S2sMemory::Inputs& in = memory_.drive();
    map_resp_valid_.write(in.resp_valid);
    sc_dt::sc_biguint<Dut::kBlockDataW> data = 0;
    for (size_t w = 0; w < in.resp_words.size(); ++w) {
      const int lo = static_cast<int>(32 * w);
      const int hi = std::min(lo + 31, Dut::kBlockDataW - 1);
      data.range(hi, lo) = in.resp_words[w];
    }
    map_resp_data_.write(data);
  }
  void env_sample() override {
    memory_.sample(map_req_valid_.read(), static_cast<uint32_t>(map_req_block_.read()));
    monitor_.sample(out_valid_.read() && out_ready_.read(), out_access_.read());
  }
  std::string env_error() const override { return memory_.error(); }
  Counters counters() const override { return deflect_bench_counters(monitor_, memory_); }

 private:
  using Dut = hls::DeflectSc;
  template <int W>
  using sig = sc_core::sc_signal<sc_dt::sc_uint<W>>;

  Dut dut_;
  S2sMemory memory_;
  MapAccessMonitor monitor_;
  sc_core::sc_signal<bool> in_valid_{"in_valid"}, in_ready_{"in_ready"};
  sig<Dut::kPhiW> in_normal_phi_{"in_normal_phi"}, in_bump_phi_{"in_bump_phi"};
  sig<Dut::kThetaW> in_normal_theta_{"in_normal_theta"}, in_bump_theta_{"in_bump_theta"};
  sc_core::sc_signal<bool> out_valid_{"out_valid"}, out_ready_{"out_ready"};
  sig<Dut::kPhiW> out_phi_{"out_phi"};
  sig<Dut::kThetaW> out_theta_{"out_theta"};
  sig<Dut::kAccessW> out_access_{"out_access"};
  sc_core::sc_signal<bool> map_req_valid_{"map_req_valid"};
  sig<Dut::kBlockW> map_req_block_{"map_req_block"};
  sc_core::sc_signal<bool> map_resp_valid_{"map_resp_valid"};
  sc_core::sc_signal<sc_dt::sc_biguint<Dut::kBlockDataW>> map_resp_data_{"map_resp_data"};
};

class HlsEngine : public Engine {
 public:
  HlsEngine(std::shared_ptr<const deflect::S2sMap> map, S2sMemoryTiming timing)
      : map_(std::move(map)), timing_(timing) {}
  std::string name() const override { return "hls"; }
  RunResult run(const std::vector<Txn>& items, const RunOptions& options) override {
    return run_hls<HlsBench>(
        [&](sc_core::sc_clock& clk, sc_core::sc_signal<bool>& rst_n) {
          return std::make_unique<HlsBench>("bench", clk, rst_n, map_, timing_,
                                            options.stalls.seed ^ kS2sMemorySeedSalt);
        },
        items, items.size(), options);
  }

 private:
  std::shared_ptr<const deflect::S2sMap> map_;
  S2sMemoryTiming timing_;
};

// Items named by what the look-up sees: phi' (steps, taken modulo 4Q) and the bump's theta,
// on a normal (phi_N, theta_N); the bump's phi is phi' + theta_N.
Txn prime_item(uint32_t normal_phi, int32_t normal_theta, int64_t phi_prime, int32_t bump_theta) {
  return deflect_steps_item(normal_phi, normal_theta, wrap_phi(phi_prime + normal_theta),
                            bump_theta);
}

// phi' of the first-octant column k in quadrant q (k = 0 .. Q).
int64_t phi_prime_of(int quadrant, int32_t k) {
  const int64_t mirrored = quadrant % 2 == 1 ? -int64_t{k} : int64_t{k};
  return (quadrant + quadrant % 2) * int64_t{kQ} + mirrored;  // k, 2Q - k, 2Q + k, 4Q - k
}

}  // namespace

// ---- Items -------------------------------------------------------------------------------

Txn deflect_item(SphereAngle normal, SphereAngle bump) {
  Txn t;
  t.f[kDflNormalPhi] = normal.phi;
  t.f[kDflNormalTheta] = normal.theta;
  t.f[kDflBumpPhi] = bump.phi;
  t.f[kDflBumpTheta] = bump.theta;
  return kInputs.masked(t);
}

Txn deflect_steps_item(uint32_t normal_phi, int32_t normal_theta, uint32_t bump_phi,
                       int32_t bump_theta) {
  auto theta = [](int32_t steps) {
    return deflect::make_theta(kGrid, steps < 0, static_cast<uint32_t>(std::abs(steps)));
  };
  return deflect_item({normal_phi, theta(normal_theta)}, {bump_phi, theta(bump_theta)});
}

SphereAngle deflect_normal(const Txn& item) {
  return {static_cast<uint32_t>(item.f[kDflNormalPhi]),
          static_cast<uint32_t>(item.f[kDflNormalTheta])};
}

SphereAngle deflect_bump(const Txn& item) {
  return {static_cast<uint32_t>(item.f[kDflBumpPhi]), static_cast<uint32_t>(item.f[kDflBumpTheta])};
}

std::vector<Txn> deflect_coherent_items(std::mt19937_64& rng, size_t count) {
  const int32_t max_theta = kQ - 1;
  std::vector<Txn> items;
  items.reserve(count);
  // A step of -1, 0 or +1 with probability 1/(2 odds) each way.
  auto drift = [&rng](int64_t odds) -> int32_t {
    const int64_t r = uniform(rng, 0, 2 * odds - 1);
    return r == 0 ? -1 : r == 1 ? 1 : 0;
  };
  while (items.size() < count) {
    // One run: a stretch of a surface. The normal turns slowly; the bump map's slopes stay
    // within +-amp steps of flat (amp 0: a flat stretch of the bump map).
    const auto run = static_cast<size_t>(uniform(rng, 16, 256));
    auto normal_phi = static_cast<int32_t>(uniform(rng, 0, kPhiCount - 1));
    auto normal_theta = static_cast<int32_t>(uniform(rng, -max_theta, max_theta));
    const auto amp = static_cast<int32_t>(rng() % 4 == 0 ? 0 : uniform(rng, 1, 24));
    auto bump_phi = static_cast<int32_t>(uniform(rng, -amp, amp));
    auto bump_theta = static_cast<int32_t>(uniform(rng, -amp, amp));
    for (size_t i = 0; i < run && items.size() < count; ++i) {
      normal_phi += drift(8);
      normal_theta = std::clamp(normal_theta + drift(8), -max_theta, max_theta);
      bump_phi = std::clamp(bump_phi + drift(4), -amp, amp);
      bump_theta = std::clamp(bump_theta + drift(4), -amp, amp);
      items.push_back(
          deflect_steps_item(wrap_phi(normal_phi), normal_theta, wrap_phi(bump_phi), bump_theta));
    }
  }
  return items;
}

// ---- The block ---------------------------------------------------------------------------

DeflectBlock::DeflectBlock(const BlockOptions& options)
    : map_(std::make_shared<const deflect::S2sMap>(kGrid)),
      timing_{options.dfl_map_latency, options.dfl_map_jitter} {
  if (timing_.latency < 1 || timing_.latency > 1000 || timing_.jitter < 0 ||
      timing_.jitter > 1000) {
    throw std::invalid_argument(
        fmt::format("deflect: map memory latency {} (1..1000) and jitter {} (0..1000)",
                    timing_.latency, timing_.jitter));
  }
}

const Schema& DeflectBlock::inputs() const { return kInputs; }
const Schema& DeflectBlock::outputs() const { return kOutputs; }

std::string DeflectBlock::repro_options() const {
  std::string out;
  if (timing_.latency != S2sMemoryTiming{}.latency)
    out += fmt::format("--map-latency {}", timing_.latency);
  if (timing_.jitter != 0)
    out += fmt::format("{}--map-jitter {}", out.empty() ? "" : " ", timing_.jitter);
  return out;
}

std::vector<Txn> DeflectBlock::directed_items() const {
  const int32_t top = kQ - 1;  // the largest theta magnitude (the pole, saturated)
  std::vector<Txn> items;
  auto steps = [&items](uint32_t np, int32_t nt, uint32_t bp, int32_t bt) {
    items.push_back(deflect_steps_item(np, nt, bp, bt));
  };
  auto prime = [&items](uint32_t np, int32_t nt, int64_t phi_prime, int32_t bt) {
    items.push_back(prime_item(np, nt, phi_prime, bt));
  };
  auto raw = [&items](SphereAngle n, SphereAngle b) { items.push_back(deflect_item(n, b)); };

  // The flat bump (0, +0) on normals all over the sphere, the poles included: the result is
  // the normal itself (the first is also the first look-up after reset: a miss).
  for (uint32_t np : {0u, 1u, 127u, 128u, 255u, 256u, 383u, 384u, 511u}) {
    for (int32_t nt : {-top, -100, -64, -5, -1, 0, 1, 5, 64, 100, top}) steps(np, nt, 0, 0);
  }
  raw({300, kMinusZero}, {0, 0});  // a normal with theta -0 reads as the equator
  // Normals at the poles with deflections in every direction, the largest included.
  for (int32_t nt : {top, -top}) {
    for (uint32_t np : {0u, 511u}) {
      for (uint32_t bp : {0u, 1u, 64u, 127u, 128u, 129u, 255u, 256u, 300u, 384u, 511u}) {
        for (int32_t bt : {-top, -40, 0, 40, top}) steps(np, nt, bp, bt);
      }
    }
  }
  // phi' = phi_D - theta_N wraps below 0 and beyond 2 pi; phi_N + the offset wraps past 2 pi.
  steps(10, 20, 5, 7);
  steps(0, top, 0, 30);
  steps(100, 1, 0, -3);
  steps(10, -20, 500, 7);
  steps(0, -top, 511, -30);
  steps(511, 0, 20, 10);  // phi_N = 511 with a positive offset
  steps(500, 0, 30, 40);
  steps(0, 0, 20, -10);  // phi_N = 0 with a negative offset: 4Q - l, no wrap
  steps(511, 60, 300, -90);
  // Each quadrant of phi' with each sign of theta'.
  for (int q = 0; q < 4; ++q) {
    for (int32_t bt : {25, -25}) {
      prime(77, 13, q * kQ + 37, bt);
      prime(400, -60, q * kQ + 90, bt);
    }
  }
  // The z = 0 column (k = Q: phi' = Q or 3Q), every theta' from the pole to the largest.
  for (int64_t pp : {kQ, 3 * kQ}) {
    for (int32_t bt : {0, 1, 2, 5, 64, top - 1, top, -1, -5, -top}) {
      for (int32_t nt : {0, 50, -50}) prime(250, nt, pp, bt);
    }
    raw({250, 0}, {static_cast<uint32_t>(pp), kMinusZero});  // theta' = -0 at the pole
  }
  // k = 0 (the y = 0 plane): phi' = 0 and 2Q.
  for (int64_t pp : {int64_t{0}, 2 * int64_t{kQ}}) {
    for (int32_t bt : {0, 3, -3, 64, top, -top}) prime(33, 7, pp, bt);
  }
  // Theta -0 (sign set, magnitude 0) on the normal and on the bump, in every quadrant.
  raw({123, kMinusZero}, {45, 20});
  raw({0, kMinusZero}, {0, kMinusZero});
  raw({511, kMinusZero}, {128, kMinusZero | 5});
  for (int q = 0; q < 4; ++q) raw({200, 0}, {static_cast<uint32_t>(q * kQ + 10), kMinusZero});
  // The largest deflections: |theta_D| = Q - 1 all around.
  for (int64_t pp : {0, 50, 127, 128, 200, 255, 256, 300, 384, 450, 511}) {
    for (int32_t bt : {top, -top}) prime(60, 20, pp, bt);
  }

  // Cache sequences, in quadrant 0 on the equator (phi' = k, theta' = k_theta).
  auto at = [&prime](int32_t k_theta, int32_t k) { prime(100, 0, k, k_theta); };
  auto bypass = [&prime](int32_t k_theta) { prime(100, 0, phi_prime_of(1, kQ), k_theta); };
  for (int i = 0; i < 3; ++i) {  // alternating two blocks: every look-up misses
    at(9, 9);
    at(41, 70);
  }
  at(9, 9);
  bypass(9);
  at(41, 70);  // a miss right after a bypass
  at(20, 20);  // back-to-back misses
  at(60, 60);
  at(100, 100);
  at(120, 3);
  at(50, 30);  // a miss, then hits in the same block
  at(51, 31);
  at(48, 28);
  at(49, 29);
  bypass(50);
  at(50, 30);                              // the bypass left the MBR as it was: a hit
  for (int i = 0; i < 8; ++i) at(77, 77);  // the same block repeated
  return items;
}

std::vector<Txn> DeflectBlock::random_items(std::mt19937_64& rng, size_t count) const {
  std::vector<Txn> items;
  items.reserve(count);
  while (items.size() < count) {
    if (rng() % 10 < 3) {  // uniform angles: every raw port value, -0 included
      const uint64_t r = rng();
      items.push_back(
          deflect_item({static_cast<uint32_t>(r), static_cast<uint32_t>(r >> 16)},
                       {static_cast<uint32_t>(r >> 32), static_cast<uint32_t>(r >> 48)}));
    } else {  // a coherent stretch, as a render sends them
      for (const Txn& t : deflect_coherent_items(rng, static_cast<size_t>(uniform(rng, 16, 256)))) {
        if (items.size() < count) items.push_back(t);
      }
    }
  }
  return items;
}

std::unique_ptr<Engine> DeflectBlock::engine(const std::string& level) const {
  if (level == "golden") return std::make_unique<GoldenEngine>(map_);
  if (level == "hls") return std::make_unique<HlsEngine>(map_, timing_);
  if (level == "rtl") return make_deflect_rtl_engine<Vtmu_deflect>("rtl", map_, timing_);
  throw std::invalid_argument("deflect: no engine '" + level + "' (golden, hls, rtl)");
}

std::vector<std::string> DeflectBlock::coverage_cases() const {
  return {"access: hit",
          "access: miss",
          "access: bypass",
          "flat bump (0, +0)",
          "normal at the pole, theta_N = +(Q-1)",
          "normal at the pole, theta_N = -(Q-1)",
          "phi' wraps below 0 (phi_D < theta_N)",
          "phi' wraps past 2 pi (theta_N < 0)",
          "phi wraps past 2 pi (+ phi_N)",
          "phi' quadrant 0",
          "phi' quadrant 1",
          "phi' quadrant 2",
          "phi' quadrant 3",
          "theta' positive",
          "theta' negative",
          "bypass, quadrant 1 (phi' = Q)",
          "bypass, quadrant 3 (phi' = 3Q)",
          "bypass at the pole (k_theta = 0)",
          "k = 0 (y = 0 plane)",
          "normal theta -0",
          "bump theta -0",
          "largest deflection (|theta_D| = Q-1)",
          "cache: first look-up misses",
          "cache: hit after hit (same block)",
          "cache: alternating two blocks (miss)",
          "cache: miss right after a bypass",
          "cache: back-to-back misses",
          "cache: hit right after a miss",
          "cache: hit after a bypass (MBR kept)"};
}

void DeflectBlock::cover(const std::vector<Txn>& items, size_t index, const Txn& output,
                         Coverage& cov) const {
  const SphereAngle normal = deflect_normal(items[index]), bump = deflect_bump(items[index]);
  const int64_t phi_prime_steps = int64_t{bump.phi} - deflect::theta_steps(kGrid, normal.theta);
  const auto phi_prime = static_cast<uint32_t>(wrap_phi(phi_prime_steps));
  const deflect::MapAddress a = deflect::map_address(kGrid, phi_prime, bump.theta);
  const bool bypass = a.k == kGrid.quarter();
  const auto access = static_cast<MapAccess>(output.f[kDflOutAccess]);
  const uint32_t top = kGrid.quarter() - 1;

  ++cov[access == MapAccess::kHit    ? "access: hit"
        : access == MapAccess::kMiss ? "access: miss"
                                     : "access: bypass"];
  if (bump.phi == 0 && bump.theta == 0) ++cov["flat bump (0, +0)"];
  if (deflect::theta_mag(kGrid, normal.theta) == top) {
    ++cov[deflect::theta_negative(kGrid, normal.theta) ? "normal at the pole, theta_N = -(Q-1)"
                                                       : "normal at the pole, theta_N = +(Q-1)"];
  }
  if (phi_prime_steps < 0) ++cov["phi' wraps below 0 (phi_D < theta_N)"];
  if (phi_prime_steps >= kPhiCount) ++cov["phi' wraps past 2 pi (theta_N < 0)"];
  const uint32_t l_phi = bypass ? kGrid.quarter() : map_->entry(a.k_theta, a.k) >> kGrid.mag_bits();
  if (deflect::expand_phi(kGrid, a.sx, a.sz, l_phi) + normal.phi >= kGrid.phi_count())
    ++cov["phi wraps past 2 pi (+ phi_N)"];
  ++cov[fmt::format("phi' quadrant {}", phi_prime >> kGrid.mag_bits())];
  if (a.k_theta != 0) ++cov[a.sx ? "theta' negative" : "theta' positive"];
  if (bypass) {
    ++cov[phi_prime >> kGrid.mag_bits() == 1 ? "bypass, quadrant 1 (phi' = Q)"
                                             : "bypass, quadrant 3 (phi' = 3Q)"];
    if (a.k_theta == 0) ++cov["bypass at the pole (k_theta = 0)"];
  }
  if (a.k == 0) ++cov["k = 0 (y = 0 plane)"];
  if (normal.theta == kMinusZero) ++cov["normal theta -0"];
  if (bump.theta == kMinusZero) ++cov["bump theta -0"];
  if (a.k_theta == top) ++cov["largest deflection (|theta_D| = Q-1)"];

  // The cache's sequences, from the look-ups before this one (a hit right after a miss reads
  // the block that miss fetched).
  if (index == 0 || index != cover_next_) cover_prev_ = cover_prev2_ = {}, cover_looked_up_ = false;
  const Recent& p = cover_prev_;
  const Recent& p2 = cover_prev2_;
  if (access == MapAccess::kMiss) {
    if (!cover_looked_up_) ++cov["cache: first look-up misses"];
    if (p.valid && p2.valid && !p.bypass && !p2.bypass && p2.block == a.block && p.block != a.block)
      ++cov["cache: alternating two blocks (miss)"];
    if (p.valid && p.bypass) ++cov["cache: miss right after a bypass"];
    if (p.valid && p.access == MapAccess::kMiss) ++cov["cache: back-to-back misses"];
  }
  if (access == MapAccess::kHit && p.valid) {
    if (p.access == MapAccess::kHit) ++cov["cache: hit after hit (same block)"];
    if (p.access == MapAccess::kMiss) ++cov["cache: hit right after a miss"];
    if (p.bypass) ++cov["cache: hit after a bypass (MBR kept)"];
  }
  cover_looked_up_ = cover_looked_up_ || !bypass;
  cover_prev2_ = cover_prev_;
  cover_prev_ = {true, bypass, a.block, access};
  cover_next_ = index + 1;
}

std::vector<Port> DeflectBlock::ports() const {
  const int phi = fmts::kSpherePhi.width(), theta = fmts::kSphereTheta.width();
  return {{"clk_i"},
          {"rst_ni"},
          {"in_valid_i"},
          {"in_ready_o"},
          {"in_normal_phi_i", phi},
          {"in_normal_theta_i", theta},
          {"in_bump_phi_i", phi},
          {"in_bump_theta_i", theta},
          {"out_valid_o"},
          {"out_ready_i"},
          {"out_phi_o", phi},
          {"out_theta_o", theta},
          {"out_access_o", fmts::kMapAccess.width()},
          {"map_req_valid_o"},
          {"map_req_block_o", fmts::kS2sBlockAddr.width()},
          {"map_resp_valid_i"},
          {"map_resp_data_i", fmts::kS2sBlockEntries * fmts::kS2sEntry.width()}};
}

}  // namespace tmu::tb
