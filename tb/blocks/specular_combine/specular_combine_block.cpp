#include "blocks/specular_combine/specular_combine_block.hpp"

#include <algorithm>
#include <array>
#include <stdexcept>

#include "harness/described_engines.hpp"
#include "harness/described_hls.hpp"
#include "hls/texram/specular_combine_sc.hpp"
#include "rtl_models_specular_combine.hpp"
#include "texram/specular_combine.hpp"

TMU_DESCRIBE_SC(specular_combine)

namespace tmu::tb {
using texram::mul255;
using D = desc::specular_combine;

namespace {

// Channel c of an RGBA8888 word: 0 R, 1 G, 2 B, 3 A.
constexpr uint32_t channel(uint32_t rgba, int c) { return (rgba >> (24 - 8 * c)) & 0xFFu; }
constexpr uint32_t with_channel(uint32_t rgba, int c, uint32_t v) {
  const int shift = 24 - 8 * c;
  return (rgba & ~(0xFFu << shift)) | ((v & 0xFFu) << shift);
}
constexpr uint32_t pack(uint32_t r, uint32_t g, uint32_t b, uint32_t a) {
  return (r & 0xFFu) << 24 | (g & 0xFFu) << 16 | (b & 0xFFu) << 8 | (a & 0xFFu);
}
uint32_t diffuse_of(const Txn& t) { return static_cast<uint32_t>(t.f[D::in_diffuse]); }
uint32_t specular_of(const Txn& t) { return static_cast<uint32_t>(t.f[D::in_specular]); }
uint32_t reflectance_of(const Txn& t) { return static_cast<uint32_t>(t.f[D::in_reflectance]); }

// The diffuse channel that puts d + mul255(e, r) at 255 + delta (clamped to 0..255).
uint32_t edge_diffuse(uint32_t e, uint32_t r, int delta) {
  return static_cast<uint32_t>(std::clamp(255 - static_cast<int>(mul255(e, r)) + delta, 0, 255));
}

class Golden : public Model {
 public:
  void step(const Txn& t, Sink& sink) override {
    Txn out;
    out.f[D::out_colour] =
        texram::specular_combine(diffuse_of(t), specular_of(t), reflectance_of(t));
    sink.output(out);
  }
};

// The (e, r) pair of channel c (0 R, 1 G, 2 B) of directed sweep item i: every pair once per
// channel over 65536 items, the channels on different pairs (an odd offset apart).
constexpr uint32_t sweep_pair(uint32_t i, int c) {
  return (i + static_cast<uint32_t>(c) * 21911u) & 0xFFFFu;
}

}  // namespace

Txn specular_combine_item(uint32_t diffuse, uint32_t specular, uint32_t reflectance) {
  return channel_item(D::table(), "in", {diffuse, specular, reflectance});
}

SpecularCombineBlock::SpecularCombineBlock(const BlockOptions&) : DescribedBlockOf(D::table()) {
  add_level("hls", hls_level<desc::specular_combine_sc, hls::SpecularCombineSc>());
  TMU_ADD_RTL_LEVELS(specular_combine, variant());
}

std::vector<Txn> SpecularCombineBlock::directed_items() const {
  std::vector<Txn> items;
  const auto add = [&items](uint32_t d, uint32_t e, uint32_t r) {
    items.push_back(specular_combine_item(d, e, r));
  };
  // Nothing and everything.
  add(0, 0, 0);
  add(0xFFFFFFFFu, 0xFFFFFFFFu, 0xFFFFFFFFu);
  // Zero reflectance (only R's alpha set): C = D whatever E is.
  for (uint32_t d : {0x00000000u, 0x12345678u, 0xFEFF01FFu, 0xFFFFFFFFu}) {
    add(d, 0xFFFFFFFFu, 0x000000FFu);
    add(d, 0x9C3A51E7u, 0x00000000u);
  }
  // Full reflectance: C = min(255, D + E); sums 0, 1, 254, 255, 256, 510 in each channel.
  for (const auto& [d, e] : std::array<std::array<uint32_t, 2>, 6>{
           {{0, 0}, {0, 1}, {127, 127}, {128, 127}, {128, 128}, {255, 255}}}) {
    add(pack(d, e, d, 0x11), pack(e, d, e, 0x22), 0xFFFFFF00u);
    add(pack(e, d, 0x40, 0x33), pack(d, e, 0x40, 0x44), 0xFFFFFF55u);
  }
  // E = 0 (C = D) and E = 255 (C = min(255, D + R)), over a few D and R.
  for (uint32_t d : {0x00000000u, 0x7F80FE01u, 0xFFFFFF00u}) {
    for (uint32_t r : {0x00000000u, 0x0180FFFFu, 0xFF7F00AAu}) {
      add(d, 0x000000FFu, r);
      add(d, 0xFFFFFF00u, r);
    }
  }
  // Each channel on its own at the saturation edge (D + ER = 253 .. 257) with the other two
  // unsaturated, then the other two saturated and this one just below or at 255.
  for (int c = 0; c < 3; ++c) {
    for (const auto& [e, r] : std::array<std::array<uint32_t, 2>, 5>{
             {{200, 100}, {255, 255}, {1, 128}, {127, 2}, {254, 253}}}) {
      for (int delta = -2; delta <= 2; ++delta) {
        const uint32_t d = edge_diffuse(e, r, delta);
        add(with_channel(0x0A141E5Au, c, d), with_channel(0x28323CA5u, c, e),
            with_channel(0x46505A3Cu, c, r));
        add(with_channel(0xF0F0F05Au, c, d), with_channel(0xC0C0C0A5u, c, e),
            with_channel(0xC0C0C03Cu, c, r));
      }
    }
  }
  // Alpha passes D's through whatever E's and R's are.
  for (const auto& [da, ea, ra] : std::array<std::array<uint32_t, 3>, 6>{{{0x00, 0xFF, 0xFF},
                                                                          {0xFF, 0x00, 0x00},
                                                                          {0x5A, 0xA5, 0x3C},
                                                                          {0x80, 0x7F, 0x81},
                                                                          {0x01, 0xFE, 0x00},
                                                                          {0xFE, 0x01, 0xFF}}}) {
    add(pack(0x10, 0x80, 0xF0, da), pack(0x40, 0xC0, 0xFF, ea), pack(0xFF, 0x80, 0x20, ra));
  }
  // The worked example of the RTL's header: 0xFFFF8020.
  add(0xF0804020u, 0x80FF40FFu, 0x40FFFF00u);
  // Every (e, r) pair in every colour channel, D at the saturation edge (D + ER = 253 .. 257,
  // clamped to D = 0 .. 255), the alphas varying.
  for (uint32_t i = 0; i < 65536; ++i) {
    uint32_t d = i & 0xFFu, e = ~i & 0xFFu, r = (i >> 8) & 0xFFu;  // the alphas
    for (int c = 0; c < 3; ++c) {
      const uint32_t p = sweep_pair(i, c), pe = p >> 8, pr = p & 0xFFu;
      d = with_channel(d, c, edge_diffuse(pe, pr, static_cast<int>((i + c) % 5) - 2));
      e = with_channel(e, c, pe);
      r = with_channel(r, c, pr);
    }
    add(d, e, r);
  }
  return items;
}

std::vector<Txn> SpecularCombineBlock::random_items(std::mt19937_64& rng, size_t count) const {
  std::vector<Txn> items;
  items.reserve(count);
  for (size_t i = 0; i < count; ++i) {
    const uint64_t bits = rng();
    auto d = static_cast<uint32_t>(bits), e = static_cast<uint32_t>(bits >> 32);
    auto r = static_cast<uint32_t>(rng());
    if (rng() % 4 != 0) {  // three in four: each colour channel of its own kind
      for (int c = 0; c < 3; ++c) {
        const uint64_t kind = rng() % 8;
        uint32_t cd = channel(d, c), ce = channel(e, c), cr = channel(r, c);
        switch (kind) {
          case 0:
            cr = 0;
            break;  // no reflection
          case 1:
            cr = 255;
            break;  // full reflectance
          case 2:
            ce = 0;
            break;  // black environment
          case 3:
            ce = 255;
            break;  // white environment
          case 4:
            cd = 255 * static_cast<uint32_t>(rng() % 2);
            break;  // black or white diffuse
          default:
            break;  // any
        }
        // Otherwise at the saturation edge half of the time.
        if (kind != 4 && rng() % 2 == 0) {
          cd = edge_diffuse(ce, cr, static_cast<int>(rng() % 7) - 3);
        }
        d = with_channel(d, c, cd);
        e = with_channel(e, c, ce);
        r = with_channel(r, c, cr);
      }
    }
    items.push_back(specular_combine_item(d, e, r));
  }
  return items;
}

std::unique_ptr<Model> SpecularCombineBlock::golden() const { return std::make_unique<Golden>(); }

namespace {
constexpr const char* kSaturated = "channel saturated (D + ER > 255)";
constexpr const char* kJustOver = "channel D + ER = 256 (clamps by one)";
constexpr const char* kExact = "channel D + ER = 255 (no clamp)";
constexpr const char* kJustBelow = "channel D + ER = 254";
constexpr const char* kUnsaturated = "channel unsaturated (D + ER < 255)";
constexpr std::array<const char*, 3> kChannelSaturated = {"R saturated", "G saturated",
                                                          "B saturated"};
constexpr std::array<const char*, 3> kChannelOnlySaturated = {
    "R alone saturated", "G alone saturated", "B alone saturated"};
constexpr const char* kAllSaturated = "R, G, B all saturated";
constexpr const char* kNoneSaturated = "no channel saturated, some ER > 0";
constexpr const char* kR0 = "r = 0 (C = D)";
constexpr const char* kR255 = "r = 255 (C = min(255, D + E))";
constexpr const char* kE0 = "e = 0 (C = D)";
constexpr const char* kE255 = "e = 255 (C = min(255, D + R))";
constexpr const char* kD0 = "d = 0 (C = ER)";
constexpr const char* kD255 = "d = 255 (stays 255)";
constexpr const char* kRoundUp = "ER rounded up (frac > 1/2)";
constexpr const char* kRoundDown = "ER rounded down (0 < frac < 1/2)";
constexpr const char* kExactProduct = "ER exact (255 divides e r > 0)";
constexpr const char* kAlphaDiffers = "alpha: D's differs from E's, R's";
constexpr const char* kAlpha0 = "D's alpha 0x00";
constexpr const char* kAlpha255 = "D's alpha 0xFF";
constexpr std::array<const char*, 3> kEveryPair = {
    "every (e, r) pair in R", "every (e, r) pair in G", "every (e, r) pair in B"};
}  // namespace

std::vector<std::string> SpecularCombineBlock::coverage_cases() const {
  std::vector<std::string> cases = {kSaturated, kJustOver, kExact, kJustBelow, kUnsaturated};
  cases.insert(cases.end(), kChannelSaturated.begin(), kChannelSaturated.end());
  cases.insert(cases.end(), kChannelOnlySaturated.begin(), kChannelOnlySaturated.end());
  cases.insert(cases.end(),
               {kAllSaturated, kNoneSaturated, kR0, kR255, kE0, kE255, kD0, kD255, kRoundUp,
                kRoundDown, kExactProduct, kAlphaDiffers, kAlpha0, kAlpha255});
  cases.insert(cases.end(), kEveryPair.begin(), kEveryPair.end());
  return cases;
}

void SpecularCombineBlock::cover(const std::vector<Txn>& items, size_t index, const Txn&,
                                 Coverage& cov) const {
  if (index == 0 || index != cover_next_) {
    for (auto& s : seen_pairs_) s.reset();
    std::fill(std::begin(seen_count_), std::end(seen_count_), 0);
  }
  cover_next_ = index + 1;
  const uint32_t dw = diffuse_of(items[index]), ew = specular_of(items[index]),
                 rw = reflectance_of(items[index]);
  int saturated = 0, lone = -1;
  bool some_product = false;
  for (int c = 0; c < 3; ++c) {
    const uint32_t d = channel(dw, c), e = channel(ew, c), r = channel(rw, c);
    const uint32_t m = mul255(e, r), sum = d + m;
    if (sum > 255) {
      ++cov[kSaturated];
      ++cov[kChannelSaturated[static_cast<size_t>(c)]];
      ++saturated;
      lone = c;
    } else {
      ++cov[sum < 255 ? kUnsaturated : kExact];
    }
    if (sum == 256) ++cov[kJustOver];
    if (sum == 254) ++cov[kJustBelow];
    if (m > 0) some_product = true;
    if (r == 0) ++cov[kR0];
    if (r == 255) ++cov[kR255];
    if (e == 0) ++cov[kE0];
    if (e == 255) ++cov[kE255];
    if (d == 0) ++cov[kD0];
    if (d == 255) ++cov[kD255];
    const uint32_t rem = (e * r) % 255;  // e r / 255 = q + rem / 255; never exactly a half
    if (rem > 127) ++cov[kRoundUp];
    if (rem > 0 && rem <= 127) ++cov[kRoundDown];
    if (rem == 0 && e * r > 0) ++cov[kExactProduct];
    // Every pair: a case counts once, when its last pair is reached.
    const size_t pair = size_t{e} << 8 | r;
    if (!seen_pairs_[c].test(pair)) {
      seen_pairs_[c].set(pair);
      if (++seen_count_[c] == seen_pairs_[c].size()) ++cov[kEveryPair[static_cast<size_t>(c)]];
    }
  }
  if (saturated == 1) ++cov[kChannelOnlySaturated[static_cast<size_t>(lone)]];
  if (saturated == 3) ++cov[kAllSaturated];
  if (saturated == 0 && some_product) ++cov[kNoneSaturated];
  const uint32_t da = channel(dw, 3);
  if (da != channel(ew, 3) && da != channel(rw, 3)) ++cov[kAlphaDiffers];
  if (da == 0) ++cov[kAlpha0];
  if (da == 255) ++cov[kAlpha255];
}

}  // namespace tmu::tb

TMU_REGISTER_BLOCK(specular_combine, SpecularCombineBlock)
