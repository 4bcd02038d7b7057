#include "blocks/deflect/deflect_block.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "deflect/bump_map.hpp"
#include "formats/formats.hpp"
#include "harness/described_engines.hpp"
#include "harness/described_hls.hpp"
#include "hls/deflect/deflect_sc.hpp"
#include "rtl_models_deflect.hpp"

TMU_DESCRIBE_SC(deflect)

namespace tmu::tb {
namespace fmts = tmu::formats;
using deflect::MapAccess;
using deflect::SphereAngle;
using D = desc::deflect;

namespace {

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

// The unit with its MBR over a run: every miss is a request for its block.
class Golden : public Model {
 public:
  explicit Golden(std::shared_ptr<const deflect::S2sMap> map)
      : map_(std::move(map)), unit_(*map_) {}
  void step(const Txn& item, Sink& sink) override {
    const SphereAngle normal = deflect_normal(item), bump = deflect_bump(item);
    const deflect::Deflected d = unit_.deflect(normal, bump);
    if (d.access == MapAccess::kMiss) {
      Txn request;
      request.f[D::map_req_block] = deflect::deflect_address(kGrid, normal, bump).block;
      sink.request(0, request);
      ++fetches_;
    }
    Txn out;
    out.f[D::out_phi] = d.normal.phi;
    out.f[D::out_theta] = d.normal.theta;
    out.f[D::out_access] = static_cast<uint64_t>(d.access);
    sink.output(out);
  }
  Counters counters() const override { return {{"block_fetches", fetches_}}; }

 private:
  std::shared_ptr<const deflect::S2sMap> map_;
  deflect::DeflectionUnit unit_;
  uint64_t fetches_ = 0;
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
  return deflect_texel_item(normal, pack_rgb(deflect::pack_bump(kGrid, bump)));
}

Txn deflect_texel_item(SphereAngle normal, uint32_t bump_texel) {
  return channel_item(D::table(), "in", {normal.phi, normal.theta, bump_texel});
}

Txn deflect_steps_item(uint32_t normal_phi, int32_t normal_theta, uint32_t bump_phi,
                       int32_t bump_theta) {
  auto theta = [](int32_t steps) {
    return deflect::make_theta(kGrid, steps < 0, static_cast<uint32_t>(std::abs(steps)));
  };
  return deflect_item({normal_phi, theta(normal_theta)}, {bump_phi, theta(bump_theta)});
}

SphereAngle deflect_normal(const Txn& item) {
  return {static_cast<uint32_t>(item.f[D::in_normal_phi]),
          static_cast<uint32_t>(item.f[D::in_normal_theta])};
}

SphereAngle deflect_bump(const Txn& item) {
  return deflect::unpack_bump(kGrid, unpack_rgb(static_cast<uint32_t>(item.f[D::in_bump_texel])));
}

SphereAngle deflect_output(const Txn& output) {
  return {static_cast<uint32_t>(output.f[D::out_phi]),
          static_cast<uint32_t>(output.f[D::out_theta])};
}

Counters map_access_counters(const std::vector<Txn>& outputs) {
  uint64_t n[3] = {0, 0, 0};
  for (const Txn& t : outputs) {
    if (t.f[D::out_access] < 3) ++n[t.f[D::out_access]];
  }
  return {{"hits", n[0]}, {"misses", n[1]}, {"bypasses", n[2]}};
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
    : DescribedBlockOf(D::table()),
      map_(std::make_shared<const deflect::S2sMap>(kGrid)),
      timing_{options.dfl_map_latency, options.dfl_map_jitter} {
  if (timing_.latency < 1 || timing_.latency > 1000 || timing_.jitter < 0 ||
      timing_.jitter > 1000) {
    throw std::invalid_argument(
        fmt::format("deflect: map memory latency {} (1..1000) and jitter {} (0..1000)",
                    timing_.latency, timing_.jitter));
  }
  add_level("hls", hls_level<desc::deflect_sc, hls::DeflectSc>());
  TMU_ADD_RTL_LEVELS(deflect, variant());
}

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
  auto texel = [&items](SphereAngle n, uint32_t t) { items.push_back(deflect_texel_item(n, t)); };

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
  // Theta -0 (sign set, magnitude 0) on the normal and in the bump texel, in every quadrant.
  raw({123, kMinusZero}, {45, 20});
  raw({0, kMinusZero}, {0, kMinusZero});
  raw({511, kMinusZero}, {128, kMinusZero | 5});
  for (int q = 0; q < 4; ++q) raw({200, 0}, {static_cast<uint32_t>(q * kQ + 10), kMinusZero});
  // Texels the grid reads only in part: |theta| beyond Q - 1 saturates (G = Q .. 255, with
  // either sign), B's bits above phi's are ignored, and both together.
  for (uint32_t g : {uint32_t(kQ), uint32_t(kQ) + 1, 200u, 255u}) {
    texel({300, 40}, g << 8 | 0x10u);
    texel({7, kMinusZero | 3}, 0x40u << 16 | g << 8 | 0x80u);
  }
  for (uint32_t b : {0x7Eu, 0xFEu, 0xFFu, 0x02u}) texel({60, 20}, 0x33u << 16 | 9u << 8 | b);
  texel({60, 20}, 0xFFFFFFu);
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
    if (rng() % 10 < 3) {  // every raw port value: normals with -0, texels of any bits
      const uint64_t r = rng();
      items.push_back(deflect_texel_item({static_cast<uint32_t>(r), static_cast<uint32_t>(r >> 16)},
                                         static_cast<uint32_t>(r >> 32)));
    } else {  // a coherent stretch, as a render sends them
      for (const Txn& t : deflect_coherent_items(rng, static_cast<size_t>(uniform(rng, 16, 256)))) {
        if (items.size() < count) items.push_back(t);
      }
    }
  }
  return items;
}

std::unique_ptr<Model> DeflectBlock::golden() const { return std::make_unique<Golden>(map_); }

std::unique_ptr<Environment> DeflectBlock::environment(uint64_t seed) const {
  return std::make_unique<S2sMemory>(map_, timing_, seed);
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
          "bump texel: sign set, |theta| 0 (reads +0)",
          "bump texel: G >= Q (|theta| saturates to Q-1)",
          "bump texel: B bits above phi set (ignored)",
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
  const deflect::MapAddress a = deflect::deflect_address(kGrid, normal, bump);
  const bool bypass = a.k == kGrid.quarter();
  const auto access = static_cast<MapAccess>(output.f[D::out_access]);
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
  const Rgb8 texel = unpack_rgb(static_cast<uint32_t>(items[index].f[D::in_bump_texel]));
  if ((texel.b & 0x80) && texel.g == 0) ++cov["bump texel: sign set, |theta| 0 (reads +0)"];
  if (texel.g >= kGrid.quarter()) ++cov["bump texel: G >= Q (|theta| saturates to Q-1)"];
  if (((texel.r | uint32_t{texel.b & 0x7Fu} << 8) & ~kGrid.phi_mask()) != 0)
    ++cov["bump texel: B bits above phi set (ignored)"];
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

}  // namespace tmu::tb

TMU_REGISTER_BLOCK(deflect, DeflectBlock)
