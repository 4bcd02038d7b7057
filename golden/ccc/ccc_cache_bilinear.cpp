#include "ccc/ccc_cache_bilinear.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "ccc/ccc_decoder.hpp"
#include "fixed/blend.hpp"
#include "formats/formats.hpp"

namespace tmu::ccc {
namespace {

constexpr int kFrac = formats::kTexCoord.frac_bits;
static_assert(kFrac == 8, "footprint() takes the weights straight from 8 fraction bits");

int64_t clamp_texel(int64_t i, uint32_t size) {
  return std::clamp<int64_t>(i, 0, int64_t{size} - 1);
}

}  // namespace

Footprint footprint(int32_t u_raw, int32_t v_raw, uint32_t width, uint32_t height) {
  const int64_t half = int64_t{1} << (kFrac - 1);
  const int64_t su = int64_t{u_raw} - half;  // u - 0.5
  const int64_t sv = int64_t{v_raw} - half;
  const int64_t x0 = fx::shift_right_round(su, kFrac, fx::Round::kFloor);
  const int64_t y0 = fx::shift_right_round(sv, kFrac, fx::Round::kFloor);
  Footprint fp;
  fp.x0 = static_cast<uint32_t>(clamp_texel(x0, width));
  fp.x1 = static_cast<uint32_t>(clamp_texel(x0 + 1, width));
  fp.y0 = static_cast<uint32_t>(clamp_texel(y0, height));
  fp.y1 = static_cast<uint32_t>(clamp_texel(y0 + 1, height));
  // The weights are the dropped fraction bits: exactly the UQ0.8 filter weight format.
  static_assert(formats::kFilterWeight.frac_bits == kFrac);
  fp.fx = static_cast<uint32_t>(su - (x0 << kFrac));
  fp.fy = static_cast<uint32_t>(sv - (y0 << kFrac));
  return fp;
}

BlockList footprint_blocks(const Footprint& fp) {
  BlockList list;
  const BlockXY cand[4] = {{fp.x0 / 4, fp.y0 / 4},
                           {fp.x1 / 4, fp.y0 / 4},
                           {fp.x0 / 4, fp.y1 / 4},
                           {fp.x1 / 4, fp.y1 / 4}};
  for (const BlockXY& b : cand) {
    if (std::find(list.at.begin(), list.at.begin() + list.count, b) ==
        list.at.begin() + list.count) {
      list.at[list.count++] = b;
    }
  }
  return list;
}

BlockList lookahead_blocks(int32_t u_raw, int32_t v_raw, uint32_t width, uint32_t height) {
  const int64_t tu = fx::shift_right_round(u_raw, kFrac, fx::Round::kFloor);
  const int64_t tv = fx::shift_right_round(v_raw, kFrac, fx::Round::kFloor);
  const auto tx = static_cast<uint32_t>(clamp_texel(tu, width));
  const auto ty = static_cast<uint32_t>(clamp_texel(tv, height));
  const int64_t bx = tx / 4, by = ty / 4;
  const int64_t nx = bx + ((tx & 2u) ? 1 : -1);
  const int64_t ny = by + ((ty & 2u) ? 1 : -1);
  const int64_t bw = (width + 3) / 4, bh = (height + 3) / 4;
  const bool x_in = nx >= 0 && nx < bw;
  const bool y_in = ny >= 0 && ny < bh;
  BlockList list;
  auto push = [&](int64_t x, int64_t y) {
    list.at[list.count++] = {static_cast<uint32_t>(x), static_cast<uint32_t>(y)};
  };
  if (x_in) push(nx, by);
  if (y_in) push(bx, ny);
  if (x_in && y_in) push(nx, ny);
  return list;
}

uint32_t bilerp_rgb(uint32_t c00, uint32_t c10, uint32_t c01, uint32_t c11, uint32_t fx,
                    uint32_t fy) {
  uint32_t out = 0;
  for (int shift = 16; shift >= 0; shift -= 8) {
    auto ch = [shift](uint32_t c) { return (c >> shift) & 0xFFu; };
    out |= fx::bilerp_u8(ch(c00), ch(c10), ch(c01), ch(c11), fx, fy) << shift;
  }
  return out;
}

void BilinearCache::reset() {
  entries_ = {};
  stats_ = {};
}

void BilinearCache::write_clut(uint8_t index, uint32_t rgb) {
  clut_[index] = rgb & 0xFFFFFFu;
  for (CacheEntry& e : entries_) e.valid = false;  // the decoded colours are stale
}

BlockList BilinearCache::missing(const BlockList& list, uint32_t width) const {
  BlockList out;
  for (uint32_t i = 0; i < list.count; ++i) {
    const CacheEntry& e = entries_[cache_slot(list.at[i])];
    if (!e.valid || e.tag != block_address(list.at[i], width)) out.at[out.count++] = list.at[i];
  }
  return out;
}

BlockList BilinearCache::look_up(const Footprint& fp, uint32_t width) {
  const BlockList need = footprint_blocks(fp);
  const BlockList miss = missing(need, width);
  stats_.hits += need.count - miss.count;
  stats_.misses += miss.count;
  return miss;
}

BlockList BilinearCache::look_ahead(int32_t u_raw, int32_t v_raw, uint32_t width, uint32_t height) {
  const BlockList miss = missing(lookahead_blocks(u_raw, v_raw, width, height), width);
  stats_.prefetches += miss.count;
  return miss;
}

void BilinearCache::fill(BlockXY b, uint32_t address, uint32_t word) {
  const Block blk = Block::from_word(word);
  entries_[cache_slot(b)] = {true, address, clut_[blk.a], clut_[blk.b], blk.bits};
}

uint32_t BilinearCache::blend(const Footprint& fp) const {
  auto texel = [&](uint32_t x, uint32_t y) {
    return entry_texel(entries_[cache_slot({x / 4, y / 4})], x, y);
  };
  return bilerp_rgb(texel(fp.x0, fp.y0), texel(fp.x1, fp.y0), texel(fp.x0, fp.y1),
                    texel(fp.x1, fp.y1), fp.fx, fp.fy);
}

CacheBilinearUnit::CacheBilinearUnit(uint32_t width, uint32_t height, bool lookahead, FetchFn fetch)
    : fetch_(std::move(fetch)) {
  configure(width, height, lookahead);
}

void CacheBilinearUnit::configure(uint32_t width, uint32_t height, bool lookahead) {
  if (width == 0 || height == 0 || width > formats::kMaxTexSize || height > formats::kMaxTexSize) {
    throw std::invalid_argument("CacheBilinearUnit: texture size out of range");
  }
  width_ = width;
  height_ = height;
  lookahead_ = lookahead;
}

void CacheBilinearUnit::write_clut(uint8_t index, uint32_t rgb) { cache_.write_clut(index, rgb); }

void CacheBilinearUnit::fetch(const BlockList& blocks) {
  for (uint32_t i = 0; i < blocks.count; ++i) {
    const uint32_t address = block_address(blocks.at[i], width_);
    cache_.fill(blocks.at[i], address, fetch_(address));
  }
}

uint32_t CacheBilinearUnit::sample(int32_t u_raw, int32_t v_raw) {
  const Footprint fp = footprint(u_raw, v_raw, width_, height_);
  fetch(cache_.look_up(fp, width_));
  const uint32_t rgb = cache_.blend(fp);
  if (lookahead_) fetch(cache_.look_ahead(u_raw, v_raw, width_, height_));
  return rgb;
}

std::array<double, 3> ideal_bilinear(const Texture& tex, double u, double v) {
  const double su = u - 0.5, sv = v - 0.5;
  const double fx0 = std::floor(su), fy0 = std::floor(sv);
  const double wx = su - fx0, wy = sv - fy0;
  auto clampd = [](double i, uint32_t size) {
    return static_cast<uint32_t>(std::clamp(i, 0.0, static_cast<double>(size) - 1.0));
  };
  const uint32_t x0 = clampd(fx0, tex.width), x1 = clampd(fx0 + 1, tex.width);
  const uint32_t y0 = clampd(fy0, tex.height), y1 = clampd(fy0 + 1, tex.height);
  auto texel = [&](uint32_t x, uint32_t y) {
    return tex.clut[texel_index(tex.block_word(x / 4, y / 4), 4 * (y % 4) + x % 4)];
  };
  const Rgb8 c[4] = {texel(x0, y0), texel(x1, y0), texel(x0, y1), texel(x1, y1)};
  std::array<double, 3> out{};
  for (int ch = 0; ch < 3; ++ch) {
    auto get = [ch](const Rgb8& p) {
      return static_cast<double>(ch == 0 ? p.r : ch == 1 ? p.g : p.b);
    };
    const double top = get(c[0]) * (1 - wx) + get(c[1]) * wx;
    const double bot = get(c[2]) * (1 - wx) + get(c[3]) * wx;
    out[ch] = top * (1 - wy) + bot * wy;
  }
  return out;
}

}  // namespace tmu::ccc
