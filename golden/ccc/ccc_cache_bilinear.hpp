// Golden model of the low-cost texture unit of 000 §4 (Figs. 6, 7): a 4-entry
// direct-mapped cache of decoded CCC blocks feeding a bilinear interpolator.
//
// Behaviour, defined here and matched bit for bit by hls/ and rtl/:
// - A request is a point (u, v) in texels of level 0 (TexCoord, SQ16.8), texel centres at
//   i + 0.5. Border mode is clamp-to-edge (the trilinear unit adds the others).
// - Footprint: x0 = floor(u - 0.5), x1 = x0 + 1, fx = the 8 fraction bits of u - 0.5 (same in
//   v); x0, x1, y0, y1 clamped to the texture. Blend: fx::bilerp_u8 per channel.
// - Cache: entry (slot) of block (bx, by) is (bx & 1) + 2 (by & 1), so the up to four blocks
//   of a footprint always sit in different entries; tag = the block's memory address
//   by * ceil(w/4) + bx. An entry holds the two decoded colours and the decision bits (64 bits).
// - Lookup order: the footprint's distinct blocks in the order (x0,y0), (x1,y0), (x0,y1),
//   (x1,y1); each is a hit or a miss; a miss fetches the block word and looks up its two
//   colours in the CLUT (one port, two cycles, as the 2:1 multiplexer of Fig. 6).
// - Lookahead (when enabled): after the output colour is computed the memory is idle, and the
//   unit fetches the three blocks adjacent to the quadrant of the point's texel
//   (t = clamped floor(u); the bit t & 2 picks right or left, as in §4: "two bits"), in the
//   order horizontal, vertical, diagonal; blocks outside the texture or already present are
//   skipped. Because the lookahead completes before the next request is looked up, the hit,
//   miss and prefetch counts do not depend on timing, so golden predicts them exactly.
// - A CLUT write invalidates every entry (the decoded colours are stale).
#pragma once

#include <array>
#include <cstdint>
#include <functional>

#include "ccc/ccc_texture.hpp"

namespace tmu::ccc {

struct Footprint {
  uint32_t x0 = 0, x1 = 0, y0 = 0, y1 = 0;  // clamped texel coordinates
  uint32_t fx = 0, fy = 0;                  // UQ0.8 weights of x1 and y1
};

// Bilinear footprint of the point (u_raw, v_raw) (SQ16.8 raw) in a width x height texture.
Footprint footprint(int32_t u_raw, int32_t v_raw, uint32_t width, uint32_t height);

struct BlockXY {
  uint32_t bx = 0, by = 0;
  friend bool operator==(const BlockXY&, const BlockXY&) = default;
};

struct BlockList {
  uint32_t count = 0;
  std::array<BlockXY, 4> at{};
};

// The footprint's distinct blocks in lookup order.
BlockList footprint_blocks(const Footprint& fp);

// The lookahead candidates of the point: neighbours of its quadrant inside the texture.
BlockList lookahead_blocks(int32_t u_raw, int32_t v_raw, uint32_t width, uint32_t height);

// Direct-mapped interleaved slot (Fig. 7).
constexpr unsigned cache_slot(BlockXY b) { return (b.bx & 1u) + 2u * (b.by & 1u); }

// Memory address (tag) of a block.
constexpr uint32_t block_address(BlockXY b, uint32_t width) {
  return b.by * ((width + 3) / 4) + b.bx;
}

struct CacheEntry {
  bool valid = false;
  uint32_t tag = 0;       // block address
  uint32_t colour_a = 0;  // Rgb888
  uint32_t colour_b = 0;  // Rgb888
  uint16_t bits = 0;      // decision bits
};

// Colour of texel (x, y) of the block the entry holds.
constexpr uint32_t entry_texel(const CacheEntry& e, uint32_t x, uint32_t y) {
  return ((e.bits >> (4 * (y & 3) + (x & 3))) & 1u) ? e.colour_b : e.colour_a;
}

// The bilinear blend of four Rgb888 texels, per channel with fx::bilerp_u8.
uint32_t bilerp_rgb(uint32_t c00, uint32_t c10, uint32_t c01, uint32_t c11, uint32_t fx,
                    uint32_t fy);

struct CacheStats {
  uint64_t hits = 0;        // footprint blocks found in the cache
  uint64_t misses = 0;      // footprint blocks fetched from memory
  uint64_t prefetches = 0;  // lookahead blocks fetched from memory
  friend bool operator==(const CacheStats&, const CacheStats&) = default;
};

// The cache's state and policy, split where the memory is, so that the golden unit (which
// runs the steps back to back) and the hls model (which clocks the memory port between them)
// share every decision. A request is: look_up, the footprint's missing blocks in fetch order;
// fill for each as its word arrives; blend; then, with lookahead, look_ahead and its fills.
// The blocks of one step sit in different entries, so deciding them all before fetching any
// is the same as deciding each just before its fetch.
class BilinearCache {
 public:
  void reset();                                  // entries and statistics; the CLUT is a RAM
  void write_clut(uint8_t index, uint32_t rgb);  // also invalidates every entry
  // The missing blocks of the footprint; counts hits and misses.
  BlockList look_up(const Footprint& fp, uint32_t width);
  // The missing lookahead blocks of the point; counts prefetches.
  BlockList look_ahead(int32_t u_raw, int32_t v_raw, uint32_t width, uint32_t height);
  // The block word fetched from `address` decoded into b's entry.
  void fill(BlockXY b, uint32_t address, uint32_t word);
  uint32_t blend(const Footprint& fp) const;  // Rgb888, once the footprint is present

  const CacheStats& stats() const { return stats_; }
  const std::array<CacheEntry, 4>& entries() const { return entries_; }

 private:
  BlockList missing(const BlockList& list, uint32_t width) const;

  std::array<uint32_t, 256> clut_{};
  std::array<CacheEntry, 4> entries_{};
  CacheStats stats_;
};

// The unit as a transaction-level state machine.
class CacheBilinearUnit {
 public:
  using FetchFn = std::function<uint32_t(uint32_t address)>;  // block word at an address

  CacheBilinearUnit(uint32_t width, uint32_t height, bool lookahead, FetchFn fetch);

  // A new configuration (texture size, lookahead) between batches, as the RTL's quasi-static
  // cfg ports: the entries and statistics stay. The entries' tags mean block addresses of the
  // old size until a CLUT write invalidates them, so a driver loads the CLUT after it.
  void configure(uint32_t width, uint32_t height, bool lookahead);

  void write_clut(uint8_t index, uint32_t rgb);   // also invalidates every entry
  uint32_t sample(int32_t u_raw, int32_t v_raw);  // Rgb888

  const CacheStats& stats() const { return cache_.stats(); }
  const std::array<CacheEntry, 4>& entries() const { return cache_.entries(); }

 private:
  void fetch(const BlockList& blocks);

  uint32_t width_ = 0, height_ = 0;
  bool lookahead_ = false;
  FetchFn fetch_;
  BilinearCache cache_;
};

// Ideal (double precision) bilinear sample of the decoded texture at real (u, v), with the
// same clamp-to-edge rule; per channel 0..255. Used to bound the golden model's error.
std::array<double, 3> ideal_bilinear(const Texture& tex, double u, double v);

}  // namespace tmu::ccc
