#include "blocks/noise/noise_block.hpp"

#include <algorithm>
#include <cmath>

#include "blocks/noise/solid_stimulus.hpp"
#include "formats/formats.hpp"
#include "harness/described_engines.hpp"
#include "harness/described_hls.hpp"
#include "hls/perlin/noise_sc.hpp"
#include "perlin/noise_ideal.hpp"
#include "rtl_models_noise.hpp"

TMU_DESCRIBE_SC(noise)

namespace tmu::tb {
namespace fmts = tmu::formats;
using perlin::NoiseConfig;
using D = desc::noise;

namespace {

constexpr uint32_t kLatticeMask = (1u << perlin::kLatticeBits) - 1;
constexpr int32_t kNoiseOne = perlin::noise_one(NoiseConfig{});  // 1.0 of P, raw
constexpr int32_t kUnit = solid::kUnit;

uint64_t raw_bits(int64_t value, const fx::Format& f) {
  return static_cast<uint64_t>(value) & ((uint64_t{1} << f.width()) - 1);
}

class GoldenNoise : public Model {
 public:
  void step(const Txn& item, Sink& sink) override {
    const auto [u, v, w] = solid::coords(item, D::in_u);
    Txn out;
    out.f[D::out_p] = raw_bits(perlin::noise(NoiseConfig{}, u, v, w), fmts::kNoiseValue);
    sink.output(out);
  }
};

// The ideal (double precision) noise of the same coordinates, rounded to the output format
// only so that the run has outputs: `texsim levels` times it, nothing compares it.
class IdealNoise : public Model {
 public:
  void step(const Txn& item, Sink& sink) override {
    const double unit = std::ldexp(1.0, fmts::kSolidCoord.frac_bits);
    const auto [u, v, w] = solid::coords(item, D::in_u);
    const double p = perlin::ideal::noise(u / unit, v / unit, w / unit);
    Txn out;
    out.f[D::out_p] =
        raw_bits(std::llround(std::ldexp(p, fmts::kNoiseValue.frac_bits)), fmts::kNoiseValue);
    sink.output(out);
  }
};

constexpr const char* kLatticePoint = "lattice point (every fraction zero)";
constexpr const char* kOneFracZero = "one fraction zero, another not";
constexpr const char* kFracFFF = "raw fraction 0xFFF (below boundary)";
constexpr const char* kFrac001 = "raw fraction 0x001 (above boundary)";
constexpr const char* kLowBits = "fraction bits below fade index set";
constexpr const char* kFade0Nonzero = "fade index 0, fraction not zero";
constexpr const char* kFade255 = "fade index 255 (weight 2^B)";
constexpr const char* kFade128 = "fade index 128 (weight 1/2)";
constexpr std::array<const char*, 3> kEveryFade = {"every fade index on u", "every fade index on v",
                                                   "every fade index on w"};
constexpr const char* kIndexWrap = "lattice index 4095 (+1 wraps to 0)";
constexpr const char* kLarge = "|coord| >= 2^20 (octave 3 wraps)";
constexpr const char* kCornerMin = "a corner's lattice value -1.0";
constexpr const char* kCornerMax = "a corner's lattice value 127/128";
constexpr const char* kPMinusOne = "P = -1.0";
constexpr const char* kPZero = "P = 0";
constexpr const char* kPPositive = "P > 0";
constexpr const char* kPNegative = "P < 0";
constexpr const char* kPLarge = "|P| >= 1/2";
constexpr const char* kTie = "lerp tie: c (b-a) = 2^(B-1) mod 2^B";
constexpr const char* kStepDown = "a lerp steps down (b < a, c > 0)";

}  // namespace

NoiseTrace trace_noise(int64_t u, int64_t v, int64_t w) {
  const NoiseConfig c;
  NoiseTrace t;
  const std::array<int64_t, 3> coords = {u, v, w};
  for (size_t a = 0; a < 3; ++a) {
    t.index[a] = static_cast<uint32_t>(coords[a] >> perlin::kCoordFracBits) & kLatticeMask;
    t.frac[a] = static_cast<uint32_t>(coords[a]) & static_cast<uint32_t>(kUnit - 1);
    t.fade_index[a] = t.frac[a] >> (perlin::kCoordFracBits - c.fade_index_bits);
    t.fade[a] = perlin::fade_entry(c, t.fade_index[a]);
  }
  for (uint32_t n = 0; n < 8; ++n) {
    t.corner[n] = perlin::lattice_value(t.index[0] + (n & 1), t.index[1] + ((n >> 1) & 1),
                                        t.index[2] + (n >> 2)) *
                  (1 << c.lerp_extra_bits);
  }
  const int b = c.fade_bits;
  const auto lerp = [&t, b](int32_t lo, int32_t hi, uint32_t weight) {
    const int64_t product = static_cast<int64_t>(weight) * (int64_t{hi} - lo);
    if ((product & ((int64_t{1} << b) - 1)) == (int64_t{1} << (b - 1))) t.tie = true;
    if (weight > 0 && hi < lo) t.step_down = true;
    return perlin::lerp(lo, hi, weight, b);
  };
  for (size_t n = 0; n < 4; ++n) t.x[n] = lerp(t.corner[2 * n], t.corner[2 * n + 1], t.fade[0]);
  for (size_t n = 0; n < 2; ++n) t.y[n] = lerp(t.x[2 * n], t.x[2 * n + 1], t.fade[1]);
  t.p = lerp(t.y[0], t.y[1], t.fade[2]);
  return t;
}

NoiseBlock::NoiseBlock(const BlockOptions&) : DescribedBlockOf(D::table()) {
  add_level("hls", hls_level<desc::noise_sc, hls::NoiseSc>());
  TMU_ADD_RTL_LEVELS(noise, variant());
}

std::vector<Txn> NoiseBlock::directed_items() const { return solid::directed_items(); }

std::vector<Txn> NoiseBlock::random_items(std::mt19937_64& rng, size_t count) const {
  return solid::random_items(rng, count);
}

std::unique_ptr<Model> NoiseBlock::golden() const { return std::make_unique<GoldenNoise>(); }
std::unique_ptr<Model> NoiseBlock::ideal() const { return std::make_unique<IdealNoise>(); }

std::vector<std::string> NoiseBlock::coverage_cases() const {
  std::vector<std::string> cases = {kLatticePoint, kOneFracZero,  kFracFFF, kFrac001,
                                    kLowBits,      kFade0Nonzero, kFade255, kFade128};
  cases.insert(cases.end(), kEveryFade.begin(), kEveryFade.end());
  cases.insert(cases.end(), {kIndexWrap, kLarge, kCornerMin, kCornerMax, kPMinusOne, kPZero,
                             kPPositive, kPNegative, kPLarge, kTie, kStepDown});
  for (const std::string& c : solid::coord_cases()) cases.push_back(c);
  return cases;
}

void NoiseBlock::cover(const std::vector<Txn>& items, size_t index, const Txn&,
                       Coverage& cov) const {
  if (index == 0 || index != cover_next_) {
    for (auto& s : seen_fade_) s.reset();
  }
  cover_next_ = index + 1;
  const std::array<int32_t, 3> c = solid::coords(items[index], D::in_u);
  const NoiseTrace t = trace_noise(c[0], c[1], c[2]);
  solid::cover_coords(c, cov);
  int zero_fracs = 0;
  for (size_t a = 0; a < 3; ++a) {
    const uint32_t f = t.frac[a];
    if (f == 0) ++zero_fracs;
    if (f == 0xFFF) ++cov[kFracFFF];
    if (f == 0x001) ++cov[kFrac001];
    if ((f & 0xF) != 0) ++cov[kLowBits];
    if (t.fade_index[a] == 0 && f != 0) ++cov[kFade0Nonzero];
    if (t.fade_index[a] == 255) ++cov[kFade255];
    if (t.fade_index[a] == 128) ++cov[kFade128];
    if (t.index[a] == kLatticeMask) ++cov[kIndexWrap];
    if (std::abs(c[a]) >= 0x100000) ++cov[kLarge];
    if (!seen_fade_[a].test(t.fade_index[a])) {
      seen_fade_[a].set(t.fade_index[a]);
      if (seen_fade_[a].all()) ++cov[kEveryFade[a]];
    }
  }
  if (zero_fracs == 3) ++cov[kLatticePoint];
  if (zero_fracs > 0 && zero_fracs < 3) ++cov[kOneFracZero];
  const int32_t one16 = 1 << NoiseConfig{}.lerp_extra_bits;  // a lattice value's LSB in P
  if (std::find(t.corner.begin(), t.corner.end(), -128 * one16) != t.corner.end())
    ++cov[kCornerMin];
  if (std::find(t.corner.begin(), t.corner.end(), 127 * one16) != t.corner.end()) ++cov[kCornerMax];
  if (t.p == -kNoiseOne) ++cov[kPMinusOne];
  if (t.p == 0) ++cov[kPZero];
  if (t.p > 0) ++cov[kPPositive];
  if (t.p < 0) ++cov[kPNegative];
  if (std::abs(t.p) >= kNoiseOne / 2) ++cov[kPLarge];
  if (t.tie) ++cov[kTie];
  if (t.step_down) ++cov[kStepDown];
}

}  // namespace tmu::tb

TMU_REGISTER_BLOCK(noise, NoiseBlock)
