#include "texram/trilinear.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "ccc/ccc_decoder.hpp"
#include "fixed/fixed.hpp"
#include "formats/formats.hpp"

namespace tmu::texram {
namespace {

constexpr int kPortFrac = formats::kTexCoord.frac_bits;  // 8
constexpr int kLodFrac = formats::kLod.frac_bits;        // 8
static_assert(kPortFrac == 8 && kLodFrac == 8, "widths are at most the ports' 8 fraction bits");

void check_widths(const Widths& w) {
  auto ok = [](int b) { return b >= 1 && b <= 8; };
  if (!ok(w.sub_texel) || !ok(w.weight) || !ok(w.lod_frac)) {
    throw std::invalid_argument("texram widths must be 1..8 bits");
  }
}

// A `from`-bit fraction as a `to`-bit weight: truncated, or widened with zeros.
uint32_t to_width(uint32_t f, int from, int to) {
  return from >= to ? f >> (from - to) : f << (to - from);
}

int64_t floor_shift(int64_t v, int shift) {
  return fx::shift_right_round(v, shift, fx::Round::kFloor);
}

// The stored grid coordinate that serves texel coordinate `x` for a tap whose unresolved
// coordinate was `raw`: a one-cell-wide grid is stored twice, and the replica is chosen by the
// parity of the unresolved grid position so that neighbouring taps use different banks.
uint32_t stored(uint32_t x, int64_t raw, uint32_t grid, bool blocks) {
  const uint32_t g = blocks ? x >> 2 : x;
  if (grid > 1) return g;
  return static_cast<uint32_t>((blocks ? raw >> 2 : raw) & 1);
}

// One axis of a sphere map: (c + 1) / 2 or, flipped, (1 - c) / 2 of 2^log2 texels.
int32_t sphere_axis(int32_t port, bool flip, int log2) {
  const auto c = static_cast<int32_t>(fx::fit(port, formats::kUnitComp, fx::Overflow::kWrap));
  const int64_t one = int64_t{1} << formats::kUnitComp.frac_bits;
  const int64_t half_turns = flip ? one - c : one + c;  // 2 (texel coordinate / side), SQ.14
  // texels = half_turns / 2^15 * 2^log2, in TexCoord's 8 fraction bits
  constexpr int kShift = formats::kUnitComp.frac_bits + 1 - kPortFrac;  // 7
  return static_cast<int32_t>(log2 >= kShift ? half_turns << (log2 - kShift)
                                             : floor_shift(half_turns, kShift - log2));
}

}  // namespace

Resolved resolve_border(int64_t x, uint32_t n, Border border) {
  const auto nn = static_cast<int64_t>(n);
  switch (border) {
    case Border::kWrap:
      return {false, static_cast<uint32_t>(x & (nn - 1))};
    case Border::kClamp:
      return {false, static_cast<uint32_t>(std::clamp<int64_t>(x, 0, nn - 1))};
    case Border::kMirror: {
      const int64_t m = x & (2 * nn - 1);
      return {false, static_cast<uint32_t>(m < nn ? m : 2 * nn - 1 - m)};
    }
    case Border::kBorder:
      if (x < 0 || x >= nn) return {true, 0};
      return {false, static_cast<uint32_t>(x)};
  }
  return {true, 0};
}

// Bilinear rounds the coordinate to S fraction bits at the level (half up): the weights are then
// within half a step of the exact ones, which bounds the sample's error by 2 levels against the
// ideal (tests/texram_trilinear_test.cpp); truncating them erred by up to a whole step, toward
// the first tap, at every level above 0. Nearest takes the texel the coordinate is in: floor.
Axis axis_taps(int32_t coord, int level, bool nearest, const Widths& widths) {
  const int s = widths.sub_texel;
  const int drop = kPortFrac - s + level;  // S fraction bits at `level`
  if (nearest) return {floor_shift(coord, drop + s), 0};
  const int64_t c = fx::shift_right_round(coord, drop, fx::Round::kHalfUp);
  const int64_t sc = c - (int64_t{1} << (s - 1));  // minus half a texel
  const int64_t t0 = floor_shift(sc, s);
  return {t0, to_width(static_cast<uint32_t>(sc - (t0 << s)), s, widths.weight)};
}

Request texel_request(const Geometry& g, Addressing addressing, const Request& request) {
  if (addressing == Addressing::kTexel) return request;
  Request r = request;
  r.u = sphere_axis(request.u, false, g.log2_width());
  r.v = sphere_axis(request.v, true, g.log2_height());
  return r;
}

LevelChoice choose_levels(int top, const SamplerConfig& config, int32_t request_lambda) {
  const Widths& widths = config.widths;
  check_widths(widths);
  LevelChoice plan;
  // lambda with its top L fraction bits (floor), still scaled by 2^8.
  const int64_t lambda = floor_shift(request_lambda, kLodFrac - widths.lod_frac)
                         << (kLodFrac - widths.lod_frac);
  plan.trilinear = config.filter == Filter::kTrilinear;
  if (plan.trilinear) {
    if (lambda <= 0) {
      plan.level = {0, 0};  // magnification: level 0, the second level weighs nothing
    } else if (lambda >= int64_t{top} << kLodFrac) {
      plan.level = {top, top};
    } else {
      const int l0 = static_cast<int>(lambda >> kLodFrac);
      plan.level = {l0, l0 + 1};
      const auto frac =
          static_cast<uint32_t>(lambda - (int64_t{l0} << kLodFrac)) >> (kLodFrac - widths.lod_frac);
      plan.wl = to_width(frac, widths.lod_frac, widths.weight);
    }
    plan.levels_read = plan.wl != 0 ? 2 : 1;  // a level of weight 0 is not read
  } else {
    const int d = static_cast<int>(
        std::clamp<int64_t>(floor_shift(lambda + (1 << (kLodFrac - 1)), kLodFrac), 0, top));
    plan.level = {d, d};
    plan.levels_read = 1;
  }
  plan.taps_per_level = config.filter == Filter::kNearest ? 1 : 4;
  return plan;
}

SamplePlan plan_sample(const Geometry& g, const SamplerConfig& config, const Request& port) {
  const Request request = texel_request(g, config.addressing, port);
  const Widths& widths = config.widths;
  const bool nearest = config.filter == Filter::kNearest;
  SamplePlan plan;
  static_cast<LevelChoice&>(plan) = choose_levels(g.levels() - 1, config, request.lambda);
  plan.planes = g.planes();

  for (int j = 0; j < plan.levels_read; ++j) {
    const int l = plan.level[static_cast<size_t>(j)];
    const Axis ax = axis_taps(request.u, l, nearest, widths);
    const Axis ay = axis_taps(request.v, l, nearest, widths);
    plan.wx[static_cast<size_t>(j)] = ax.w;
    plan.wy[static_cast<size_t>(j)] = ay.w;
    for (int k = 0; k < plan.taps_per_level; ++k) {
      const int64_t rx = ax.t0 + (k & 1), ry = ay.t0 + (k >> 1);
      const Resolved x = resolve_border(rx, g.texel_width(l), config.border_u);
      const Resolved y = resolve_border(ry, g.texel_height(l), config.border_v);
      Tap& tap = plan.taps[static_cast<size_t>(j)][static_cast<size_t>(k)];
      tap.outside = x.outside || y.outside;
      tap.x = x.x;
      tap.y = y.x;
      if (tap.outside) continue;
      tap.cell = g.cell(l, stored(x.x, rx, g.grid_width(l), g.block_grid()),
                        stored(y.x, ry, g.grid_height(l), g.block_grid()));
      auto& slot = plan.bank_address[tap.cell.bank];
      if (slot && *slot != tap.cell.address) {
        throw std::logic_error("plan_sample: two taps need different cells of bank " +
                               std::to_string(tap.cell.bank));
      }
      slot = tap.cell.address;
    }
  }
  return plan;
}

uint32_t tap_colour(const Tap& tap, const AccessData& data, TexelKind kind,
                    const SamplerConfig& config, const Clut32& clut) {
  if (tap.outside) return config.border_rgba;
  const auto& b = data[tap.cell.bank];
  switch (kind) {
    case TexelKind::kLuminance:
      return rgba(b[0], b[0], b[0], 255);
    case TexelKind::kSingle: {
      const int c = config.single_channel;
      return c == 3 ? rgba(0, 0, 0, b[0]) : (uint32_t{b[0]} << (24 - 8 * c)) | 0xFFu;
    }
    case TexelKind::kIndex:
      return clut[b[0]];
    case TexelKind::kTrueColour:
      return rgba(b[0], b[1], b[2], b[3]);
    case TexelKind::kCcc: {
      const uint32_t word = rgba(b[0], b[1], b[2], b[3]);  // the block word, 31:24 first
      return clut[ccc::texel_index(word, 4 * (tap.y & 3) + (tap.x & 3))];
    }
  }
  return 0;
}

uint32_t blend_taps(const SamplePlan& plan, const std::array<std::array<uint32_t, 4>, 2>& colours,
                    const Widths& widths) {
  if (plan.taps_per_level == 1) return colours[0][0];  // nearest: no blend
  const int w = widths.weight;
  const uint32_t one = uint32_t{1} << w;
  // Trilinear weighs its levels (2^W - wl, wl) and drops 3W bits, even when wl = 0 (then the
  // result equals the bilinear one: the extra factor 2^W cancels exactly).
  const uint32_t level_weight[2] = {plan.trilinear ? one - plan.wl : 1, plan.wl};
  const int drop = plan.trilinear ? 3 * w : 2 * w;
  uint32_t out = 0;
  for (int c = 0; c < 4; ++c) {
    int64_t sum = 0;
    for (int j = 0; j < plan.levels_read; ++j) {
      const uint32_t wl = level_weight[j];
      const uint32_t wx = plan.wx[static_cast<size_t>(j)], wy = plan.wy[static_cast<size_t>(j)];
      const uint32_t wxs[2] = {one - wx, wx}, wys[2] = {one - wy, wy};
      for (int k = 0; k < 4; ++k) {
        sum += int64_t{wl} * wys[k >> 1] * wxs[k & 1] *
               channel(colours[static_cast<size_t>(j)][static_cast<size_t>(k)], c);
      }
    }
    out |= static_cast<uint32_t>(fx::shift_right_round(sum, drop, fx::Round::kHalfUp))
           << (24 - 8 * c);
  }
  return out;
}

uint32_t combine(uint32_t t, const SamplerConfig& config, uint32_t shade) {
  if (config.combine == Combine::kOne) return t;
  const uint32_t m = config.combine == Combine::kConstant ? config.constant_rgba : shade;
  uint32_t out = 0;
  for (int c = 0; c < 4; ++c) out |= mul255(channel(t, c), channel(m, c)) << (24 - 8 * c);
  return out;
}

AccessData read_access(const TexramTexture& texture, const SamplePlan& plan) {
  AccessData data{};
  for (unsigned b = 0; b < 8; ++b) {
    if (!plan.bank_address[b]) continue;
    for (int p = 0; p < plan.planes; ++p) {
      data[b][static_cast<size_t>(p)] =
          texture.banks[b][*plan.bank_address[b] + static_cast<uint32_t>(p)];
    }
  }
  return data;
}

uint32_t sample(const TexramTexture& texture, const SamplerConfig& config, const Request& request,
                SamplePlan* plan_out) {
  const SamplePlan plan = plan_sample(texture.geometry, config, request);
  const AccessData data = read_access(texture, plan);
  std::array<std::array<uint32_t, 4>, 2> colours{};
  for (int j = 0; j < plan.levels_read; ++j) {
    for (int k = 0; k < plan.taps_per_level; ++k) {
      colours[static_cast<size_t>(j)][static_cast<size_t>(k)] =
          tap_colour(plan.taps[static_cast<size_t>(j)][static_cast<size_t>(k)], data, texture.kind,
                     config, texture.clut);
    }
  }
  if (plan_out) *plan_out = plan;
  return combine(blend_taps(plan, colours, config.widths), config, request.shade);
}

uint32_t texel_rgba(const TexramTexture& t, const SamplerConfig& config, int level, uint32_t x,
                    uint32_t y) {
  const Geometry& g = t.geometry;
  Tap tap;
  tap.x = x;
  tap.y = y;
  tap.cell = g.block_grid() ? g.cell(level, x >> 2, y >> 2) : g.cell(level, x, y);
  AccessData data{};
  for (int p = 0; p < g.planes(); ++p) {
    data[tap.cell.bank][static_cast<size_t>(p)] =
        t.banks[tap.cell.bank][tap.cell.address + static_cast<uint32_t>(p)];
  }
  return tap_colour(tap, data, t.kind, config, t.clut);
}

}  // namespace tmu::texram
