#include "texram/detail.hpp"

#include <algorithm>
#include <bit>
#include <stdexcept>
#include <string>

#include "fixed/fixed.hpp"
#include "formats/formats.hpp"

namespace tmu::texram {
namespace {

constexpr int kLambdaFrac = formats::kLod.frac_bits;   // 8
constexpr int32_t kLevel = int32_t{1} << kLambdaFrac;  // one level in raw SQ6.8
constexpr int kRegionLog2 = std::countr_zero(static_cast<unsigned>(kDetailRegionSide));  // 4

void check_side(uint32_t side, const char* what) {
  if (!std::has_single_bit(side) || side < uint32_t{kDetailRegionSide} ||
      side > (1u << kMaxDetailLog2)) {
    throw std::invalid_argument(std::string("detail map ") + what + " " + std::to_string(side) +
                                " is not a power of two from 16 to 256");
  }
}

// An offset map as a luminance texture: level 0 holds the offsets; the levels above are never
// read (the lookup is level 0's nearest texel) and hold zeros.
TexramTexture offset_texture(const Level8& offsets) {
  Pyramid8 pyramid{offsets};
  for (uint32_t w = offsets.width, h = offsets.height; w > 1 || h > 1;) {
    w = std::max(w / 2, 1u);
    h = std::max(h / 2, 1u);
    pyramid.emplace_back(w, h);
  }
  return texture_from_planes(TexelKind::kLuminance, {pyramid});
}

void record(std::vector<DetailAccess>* accesses, DetailMapId map, const SamplePlan& plan) {
  if (accesses) accesses->push_back({map, plan});
}

// The map must fit the texture: one offset per level-0 texel, texel coordinates.
void check_fit(const TexramTexture& texture, const SamplerConfig& config, const DetailMap& map) {
  const Geometry& g = texture.geometry;
  if (map.offset_u.geometry.texel_width(0) != g.texel_width(0) ||
      map.offset_u.geometry.texel_height(0) != g.texel_height(0)) {
    throw std::invalid_argument("sample_detail: the offset maps are not the texture's size");
  }
  if (config.addressing != Addressing::kTexel) {
    throw std::invalid_argument("sample_detail: a detail map needs texel addressing");
  }
}

}  // namespace

DetailMap make_detail_map(TexramTexture detail, const Level8& offset_u, const Level8& offset_v) {
  check_side(detail.geometry.texel_width(0), "width");
  check_side(detail.geometry.texel_height(0), "height");
  if (offset_u.width != offset_v.width || offset_u.height != offset_v.height) {
    throw std::invalid_argument("make_detail_map: the offset maps differ in size");
  }
  return {std::move(detail), offset_texture(offset_u), offset_texture(offset_v)};
}

int bank_accesses(const std::vector<DetailAccess>& accesses) {
  int n = 0;
  for (const DetailAccess& a : accesses) {
    const auto& banks = a.plan.bank_address;
    if (std::any_of(banks.begin(), banks.end(), [](const auto& b) { return b.has_value(); })) {
      n += a.plan.planes;
    }
  }
  return n;
}

DetailLevels detail_levels(const Widths& widths, int32_t lambda) {
  if (lambda >= 0) return {};
  const int drop = kLambdaFrac - widths.lod_frac;
  const int32_t lq = static_cast<int32_t>(fx::shift_right_round(lambda, drop, fx::Round::kFloor)
                                          << drop);  // L bits, floor
  if (lq <= -kLevel) return {true, lq + kDetailLevels * kLevel, 0};
  // -1 < lq < 0: detail level -1 (lambda_d = 3) against the texture's level 0.
  const auto f = static_cast<uint32_t>(lq + kLevel) >> drop;  // L-bit fraction, 1 .. 2^L - 1
  const int w = widths.weight, l = widths.lod_frac;
  const uint32_t wt = l >= w ? f >> (l - w) : f << (w - l);
  return {true, (kDetailLevels - 1) * kLevel, wt};
}

SamplerConfig offset_sampler(const SamplerConfig& texture_config) {
  SamplerConfig c;
  c.kind = TexelKind::kLuminance;
  c.filter = Filter::kNearest;
  c.border_u = texture_config.border_u;
  c.border_v = texture_config.border_v;
  c.widths = texture_config.widths;
  return c;
}

SamplerConfig detail_sampler(const DetailMap& map, const SamplerConfig& texture_config) {
  SamplerConfig c;
  c.kind = map.detail.kind;
  c.single_channel = texture_config.single_channel;
  c.filter = Filter::kTrilinear;            // §9: "the color value is tri-linearly interpolated"
  c.border_u = c.border_v = Border::kWrap;  // the map is toroidal: regions wrap at its sides
  c.widths = texture_config.widths;
  return c;
}

DetailRegion read_region(const DetailMap& map, const SamplerConfig& texture_config,
                         const Request& request, std::vector<DetailAccess>* accesses) {
  const SamplerConfig c = offset_sampler(texture_config);
  const Request at_level0{request.u, request.v, 0, 0};
  SamplePlan plan_u, plan_v;
  const uint32_t ou = channel(sample(map.offset_u, c, at_level0, &plan_u), 0);
  record(accesses, DetailMapId::kOffsetU, plan_u);
  const uint32_t ov = channel(sample(map.offset_v, c, at_level0, &plan_v), 0);
  record(accesses, DetailMapId::kOffsetV, plan_v);
  return {plan_u.taps[0][0].outside, ou, ov};
}

Request detail_request(const DetailRegion& region, const Request& request, int32_t lambda_d) {
  constexpr int kFrac = formats::kTexCoord.frac_bits;  // 8
  constexpr int32_t kFracMask = (int32_t{1} << kFrac) - 1;
  // ou + 16 frac(u): the fraction's 8 bits become 4 integer and 4 fraction bits, exactly.
  const auto axis = [](uint32_t offset, int32_t coord) {
    return static_cast<int32_t>(offset << kFrac) + ((coord & kFracMask) << kRegionLog2);
  };
  return {axis(region.ou, request.u), axis(region.ov, request.v), lambda_d, 0};
}

uint32_t replace_colour(uint32_t d, uint32_t t, uint32_t wt, int weight_bits) {
  const uint32_t one = uint32_t{1} << weight_bits;
  uint32_t out = 0;
  for (int c = 0; c < 4; ++c) {
    const uint32_t sum = (one - wt) * channel(d, c) + wt * channel(t, c);
    out |= ((sum + (one >> 1)) >> weight_bits) << (24 - 8 * c);
  }
  return out;
}

uint32_t modulate_colour(uint32_t d, uint32_t t, uint32_t wt, int weight_bits) {
  constexpr int kProductFrac = 7;  // T D / 128: 7 fraction bits
  constexpr uint32_t kSaturate = 255u << kProductFrac;
  const uint32_t one = uint32_t{1} << weight_bits;
  const int drop = weight_bits + kProductFrac;
  uint32_t out = channel(t, 3);  // alpha: the texture's
  for (int c = 0; c < 3; ++c) {
    const uint32_t tc = channel(t, c);
    const uint32_t p = std::min(tc * channel(d, c), kSaturate);
    const uint32_t sum = (one - wt) * p + wt * (tc << kProductFrac);
    out |= ((sum + (uint32_t{1} << (drop - 1))) >> drop) << (24 - 8 * c);
  }
  return out;
}

uint32_t sample_detail(const TexramTexture& texture, const SamplerConfig& config,
                       const DetailMap* map, const DetailConfig& detail_config,
                       const Request& request, std::vector<DetailAccess>* accesses) {
  if (map) check_fit(texture, config, *map);
  const DetailLevels levels = detail_levels(config.widths, request.lambda);
  if (!map || !levels.detail) {
    SamplePlan plan;
    const uint32_t colour = sample(texture, config, request, &plan);
    record(accesses, DetailMapId::kTexture, plan);
    return colour;
  }
  // 1. offset maps, 2. detail map, 3. texture (000 §9's order).
  const DetailRegion region = read_region(*map, config, request, accesses);
  SamplePlan plan;
  if (region.outside) {  // no texel, no region: the texture's level 0 (its border colour)
    const uint32_t colour =
        sample(texture, config, {request.u, request.v, 0, request.shade}, &plan);
    record(accesses, DetailMapId::kTexture, plan);
    return colour;
  }
  const uint32_t d = sample(map->detail, detail_sampler(*map, config),
                            detail_request(region, request, levels.lambda_d), &plan);
  record(accesses, DetailMapId::kDetail, plan);
  const bool modulate = detail_config.combine == DetailCombine::kModulate;
  uint32_t t = 0;
  if (modulate || levels.wt != 0) {
    SamplerConfig one = config;
    one.combine = Combine::kOne;
    t = sample(texture, one, {request.u, request.v, 0, 0}, &plan);
    record(accesses, DetailMapId::kTexture, plan);
  }
  const int w = config.widths.weight;
  const uint32_t c =
      modulate ? modulate_colour(d, t, levels.wt, w) : replace_colour(d, t, levels.wt, w);
  return combine(c, config, request.shade);
}

}  // namespace tmu::texram
