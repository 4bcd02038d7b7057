// Real-time mipmap generation (000 §12, Fig. 14) as the chip does it: a stream of level-0
// texels in, a stream of bank-cell writes out. This model defines the order of the writes the
// hls and rtl generators must reproduce; its values are those of build_pyramid (mipmap.hpp)
// and its cells those of Geometry::cell (layout.hpp).
//
// Input, in source order, one item per level-0 texel:
// - non-interlaced: raster order (line 0 left to right, then line 1, ...);
// - interlaced: field 1 (lines 0, 2, 4, ...) then field 2 (lines 1, 3, ...), each line left to
//   right. A field-2 item also carries `above`, the level-0 texel at the same column of the line
//   above (y - 1): the chip reads that line back from its banks into the shift registers 826.
//   A one-line frame has no field 2: interlaced or not, it is the same stream.
//
// Output, per input item: the level-0 write(s) of the texel, then each higher-level texel the
// item completes, ascending level (an item completes at most one texel per level). A texel of
// a level narrower (lower) than 2 is written to every replica cell the layout stores, in
// row-major order of the stored coordinates: (0,y) (1,y) for a one-texel-wide level, (x,0)
// (x,1) for a one-texel-high one, (0,0) (1,0) (0,1) (1,1) for the 1 x 1 top level.
//
// Arithmetic (Fig. 14), per stage l (level l in, level l + 1 out), on the carried values of
// mipmap.hpp's rounding rule: sums exact; when a level-(l+1) texel is complete its texel is
// box_texel(sum) and its carried value, which goes on to stage l + 1, box_carry(sum):
// - non-interlaced, and every level above 0: horizontal pairs first (an even column's carried
//   value waits in register 1404), then vertical pairs: the pair sums of an even line wait in
//   the line FIFO 1408 (half a line of level l deep) for the odd line below. A one-texel-wide
//   (-high) level repeats its column (row): the pair sum is twice the texel (twice the pair sum).
// - interlaced level 0 -> 1 (Fig. 14(a)): in field 2 adder 1402 adds texel + above (a
//   vertical pair); an even column's sum waits in FIFO 1408, used as a one-entry register; the
//   odd column completes the level-1 texel. Field 1 is only written. Level 1 then comes out in
//   raster order, so every higher stage is the non-interlaced one.
// Every pair completes within its frame (the sides are powers of two), so the next frame
// starts with empty registers and FIFOs.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <vector>

#include "texram/layout.hpp"
#include "texram/mipmap.hpp"

namespace tmu::texram {

struct MipgenConfig {
  int log2_w = 0;           // level-0 width 2^log2_w, 0..MaxMipLog2
  int log2_h = 0;           // level-0 height 2^log2_h, 0..MaxMipLog2
  bool interlaced = false;  // source order: fields (see above)
  int planes = 1;           // byte planes of the texture (1 or 4); only for the addresses
  int plane = 0;            // the plane this stream fills, 0..planes-1; only for the addresses
  friend bool operator==(const MipgenConfig&, const MipgenConfig&) = default;
};

struct MipgenInput {
  uint8_t texel = 0;  // the level-0 texel
  uint8_t above = 0;  // interlaced field 2: the level-0 texel above (x, y - 1); else unused
};

// One bank-cell write: a texel of `level` at stored coordinates (x, y), and its cell.
struct CellWrite {
  int level = 0;
  uint32_t x = 0, y = 0;
  uint8_t value = 0;
  BankCell cell;
  friend bool operator==(const CellWrite&, const CellWrite&) = default;
};

// A complete 2 x 2 box: its sum, of four carried values with `frac_bits` fraction bits.
struct BoxSum {
  uint32_t sum = 0;
  int frac_bits = 0;
};

class MipgenStream {
 public:
  // Throws std::invalid_argument for sizes beyond 0..MaxMipLog2, planes other than 1 or 4,
  // a plane outside 0..planes-1, or a carry outside 0..kExactCarry (mipmap.hpp's rule: a
  // design parameter of the unit, not a port).
  explicit MipgenStream(const MipgenConfig& config, int carry = kExactCarry);

  const MipgenConfig& config() const { return config_; }
  const Geometry& geometry() const { return geometry_; }
  // Interlaced source order in effect (interlaced and more than one line).
  bool interlaced() const { return interlaced_; }
  uint32_t width() const { return geometry_.texel_width(0); }
  uint32_t height() const { return geometry_.texel_height(0); }
  size_t items_per_frame() const { return size_t{width()} * height(); }

  // The level-0 position of the next item, and whether it is the first of a frame or a
  // field-2 item (one that needs `above`).
  uint32_t next_x() const { return x_; }
  uint32_t next_y() const { return y_; }
  bool frame_start() const { return x_ == 0 && y_ == 0; }
  bool needs_above() const { return interlaced_ && (y_ & 1u) != 0; }

  // Consumes the next item; appends its writes, in output order, to `out`.
  void step(const MipgenInput& in, std::vector<CellWrite>& out);

  // The box sums of the texels the last step() completed, ascending level.
  const std::vector<BoxSum>& last_box_sums() const { return last_sums_; }

  // The line FIFO of stage `level` (level in, level + 1 out): its depth, half a line of
  // `level` (at least one entry), and the most pair sums it has held at once so far.
  uint32_t fifo_depth(int level) const;
  size_t fifo_peak(int level) const { return stage_at(level).peak; }
  // Pair sums in the line FIFO of stage `level` right now.
  size_t fifo_size(int level) const { return stage_at(level).line.size(); }

 private:
  struct Stage {
    uint32_t hold = 0;          // register 1404 (interlaced level 0: FIFO 1408 as a register)
    std::deque<uint32_t> line;  // FIFO 1408: pair sums of an even line, for the odd line below
    size_t peak = 0;
  };
  const Stage& stage_at(int level) const;
  void advance();
  void emit(int level, uint32_t x, uint32_t y, uint8_t value, std::vector<CellWrite>& out) const;
  // The box sum of the level-(level+1) texel that texel (x, y) of `level`, carried value v,
  // completes, if it completes one.
  bool stage_step(int level, uint32_t x, uint32_t y, uint32_t v, uint32_t& sum);
  bool interlaced_level1_step(uint32_t x, uint32_t y, const MipgenInput& in, uint32_t& sum);

  MipgenConfig config_;
  int carry_;
  Geometry geometry_;
  bool interlaced_;
  uint32_t x_ = 0, y_ = 0;
  std::array<Stage, kMaxLevels> stages_{};
  std::vector<BoxSum> last_sums_;
};

// One frame's items in source order; `above` is filled in for field-2 items (0 elsewhere).
std::vector<MipgenInput> mipgen_source(const Level8& level0, bool interlaced);

// Every write of one frame of `level0` (its size must be config's).
std::vector<CellWrite> mipgen_frame(const MipgenConfig& config, const Level8& level0,
                                    int carry = kExactCarry);

// The eight banks as the writes leave them, read back through Geometry::cell.
class BankMemory {
 public:
  explicit BankMemory(const Geometry& geometry);

  // Throws std::out_of_range when the write's bank or address is outside the layout.
  void write(const CellWrite& w);
  uint32_t writes_to(const BankCell& c) const { return count_.at(c.bank).at(c.address); }
  uint8_t at(const BankCell& c) const { return cells_.at(c.bank).at(c.address); }

  // Level `level` of plane `plane`: texel (x, y) from cell(level, x, y, plane). Throws
  // std::runtime_error naming the cell when a cell of the level (any replica) was never
  // written or a replica holds another value.
  Level8 read_level(int level, int plane) const;
  Pyramid8 read_pyramid(int plane) const;
  // Cells of plane `plane` written other than exactly once (0 after one clean frame).
  size_t cells_not_written_once(int plane) const;

 private:
  Geometry geometry_;
  std::array<std::vector<uint8_t>, 8> cells_;
  std::array<std::vector<uint32_t>, 8> count_;
};

}  // namespace tmu::texram
