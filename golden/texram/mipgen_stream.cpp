#include "texram/mipgen_stream.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "formats/formats.hpp"

namespace tmu::texram {
namespace {

const MipgenConfig& checked(const MipgenConfig& c) {
  if (c.log2_w < 0 || c.log2_w > formats::kMaxMipLog2 || c.log2_h < 0 ||
      c.log2_h > formats::kMaxMipLog2) {
    throw std::invalid_argument("MipgenStream: log2 sizes must be 0.." +
                                std::to_string(formats::kMaxMipLog2));
  }
  if (c.planes != 1 && c.planes != formats::kPlanes) {
    throw std::invalid_argument("MipgenStream: a texture has 1 or 4 planes");
  }
  if (c.plane < 0 || c.plane >= c.planes) {
    throw std::invalid_argument("MipgenStream: plane " + std::to_string(c.plane) + " outside 0.." +
                                std::to_string(c.planes - 1));
  }
  return c;
}

}  // namespace

MipgenStream::MipgenStream(const MipgenConfig& config, int carry)
    : config_(checked(config)),
      carry_(carry),
      geometry_(config.log2_w, config.log2_h, config.planes),
      interlaced_(config.interlaced && config.log2_h > 0) {
  if (carry < 0 || carry > kExactCarry) {
    throw std::invalid_argument("MipgenStream: carry must be 0.." + std::to_string(kExactCarry));
  }
}

const MipgenStream::Stage& MipgenStream::stage_at(int level) const {
  if (level < 0 || level + 1 >= geometry_.levels()) {
    throw std::out_of_range("MipgenStream: no stage for level " + std::to_string(level));
  }
  return stages_[static_cast<size_t>(level)];
}

uint32_t MipgenStream::fifo_depth(int level) const {
  stage_at(level);
  return std::max(geometry_.texel_width(level) / 2, 1u);
}

void MipgenStream::advance() {
  if (++x_ < width()) return;
  x_ = 0;
  if (!interlaced_) {
    if (++y_ == height()) y_ = 0;
    return;
  }
  y_ += 2;
  if (y_ >= height()) y_ = (y_ & 1u) ? 0 : 1;  // field 1 done: field 2; field 2 done: next frame
}

void MipgenStream::emit(int level, uint32_t x, uint32_t y, uint8_t value,
                        std::vector<CellWrite>& out) const {
  const bool rep_x = geometry_.grid_width(level) < 2, rep_y = geometry_.grid_height(level) < 2;
  for (uint32_t ys = rep_y ? 0 : y; ys <= (rep_y ? 1 : y); ++ys) {
    for (uint32_t xs = rep_x ? 0 : x; xs <= (rep_x ? 1 : x); ++xs) {
      out.push_back({level, xs, ys, value, geometry_.cell(level, xs, ys, config_.plane)});
    }
  }
}

bool MipgenStream::stage_step(int level, uint32_t x, uint32_t y, uint32_t v, uint32_t& sum) {
  Stage& s = stages_[static_cast<size_t>(level)];
  const bool wide = geometry_.texel_width(level) >= 2, high = geometry_.texel_height(level) >= 2;
  uint32_t pair;  // horizontal pair sum (adder 1402)
  if (!wide) {
    pair = 2 * v;  // one texel wide: the column repeats
  } else if ((x & 1u) == 0) {
    s.hold = v;  // register 1404
    return false;
  } else {
    pair = s.hold + v;
  }
  if (!high) {
    sum = 2 * pair;  // one texel high: the row repeats
    return true;
  }
  if ((y & 1u) == 0) {  // even line: to the line FIFO
    s.line.push_back(pair);
    s.peak = std::max(s.peak, s.line.size());
    return false;
  }
  if (s.line.empty()) throw std::logic_error("MipgenStream: line FIFO underflow");
  sum = s.line.front() + pair;  // adder 1410
  s.line.pop_front();
  return true;
}

bool MipgenStream::interlaced_level1_step(uint32_t x, uint32_t y, const MipgenInput& in,
                                          uint32_t& sum) {
  if ((y & 1u) == 0) return false;  // field 1: written only
  Stage& s = stages_[0];
  const uint32_t pair = uint32_t{in.texel} + in.above;  // vertical pair (adder 1402)
  if (geometry_.texel_width(0) < 2) {
    sum = 2 * pair;  // one texel wide: the column repeats
    return true;
  }
  if ((x & 1u) == 0) {
    s.hold = pair;  // FIFO 1408 as a one-entry register
    return false;
  }
  sum = s.hold + pair;  // adder 1410
  return true;
}

void MipgenStream::step(const MipgenInput& in, std::vector<CellWrite>& out) {
  last_sums_.clear();
  uint32_t x = x_, y = y_;
  advance();
  emit(0, x, y, in.texel, out);
  const int top = geometry_.levels() - 1;
  if (top == 0) return;
  uint32_t sum = 0;
  bool more =
      interlaced_ ? interlaced_level1_step(x, y, in, sum) : stage_step(0, x, y, in.texel, sum);
  for (int level = 1; more; ++level) {
    const int k = carried_bits(level - 1, carry_);  // of the four values summed
    last_sums_.push_back({sum, k});
    x >>= 1;
    y >>= 1;
    emit(level, x, y, box_texel(sum, k), out);
    const uint32_t carried = box_carry(sum, k, carried_bits(level, carry_));
    more = level < top && stage_step(level, x, y, carried, sum);
  }
}

std::vector<MipgenInput> mipgen_source(const Level8& level0, bool interlaced) {
  std::vector<MipgenInput> items;
  items.reserve(level0.texels.size());
  auto line = [&](uint32_t y, bool field2) {
    for (uint32_t x = 0; x < level0.width; ++x) {
      items.push_back({level0.at(x, y), field2 ? level0.at(x, y - 1) : uint8_t{0}});
    }
  };
  if (!interlaced || level0.height < 2) {
    for (uint32_t y = 0; y < level0.height; ++y) line(y, false);
  } else {
    for (uint32_t y = 0; y < level0.height; y += 2) line(y, false);
    for (uint32_t y = 1; y < level0.height; y += 2) line(y, true);
  }
  return items;
}

std::vector<CellWrite> mipgen_frame(const MipgenConfig& config, const Level8& level0, int carry) {
  MipgenStream stream(config, carry);
  if (level0.width != stream.width() || level0.height != stream.height() ||
      level0.texels.size() != stream.items_per_frame()) {
    throw std::invalid_argument("mipgen_frame: level 0 is not the configured size");
  }
  std::vector<CellWrite> out;
  out.reserve(level0.texels.size() * 3 / 2 + 64);
  for (const MipgenInput& in : mipgen_source(level0, config.interlaced)) stream.step(in, out);
  return out;
}

// ---- BankMemory ------------------------------------------------------------------------

BankMemory::BankMemory(const Geometry& geometry) : geometry_(geometry) {
  for (size_t b = 0; b < cells_.size(); ++b) {
    cells_[b].assign(geometry.bank_cells(), 0);
    count_[b].assign(geometry.bank_cells(), 0);
  }
}

void BankMemory::write(const CellWrite& w) {
  if (w.cell.bank >= cells_.size() || w.cell.address >= cells_[w.cell.bank].size()) {
    throw std::out_of_range("BankMemory: write to bank " + std::to_string(w.cell.bank) +
                            " address " + std::to_string(w.cell.address) +
                            " outside the layout's " + std::to_string(geometry_.bank_cells()) +
                            " cells per bank");
  }
  cells_[w.cell.bank][w.cell.address] = w.value;
  ++count_[w.cell.bank][w.cell.address];
}

Level8 BankMemory::read_level(int level, int plane) const {
  Level8 out(geometry_.texel_width(level), geometry_.texel_height(level));
  const uint32_t sw = geometry_.stored_width(level), sh = geometry_.stored_height(level);
  for (uint32_t y = 0; y < sh; ++y) {
    for (uint32_t x = 0; x < sw; ++x) {
      const BankCell c = geometry_.cell(level, x, y, plane);
      auto where = [&] {
        return "BankMemory: level " + std::to_string(level) + " cell (" + std::to_string(x) + ", " +
               std::to_string(y) + ") plane " + std::to_string(plane) + " = bank " +
               std::to_string(c.bank) + " address " + std::to_string(c.address);
      };
      if (writes_to(c) == 0) throw std::runtime_error(where() + " never written");
      const uint32_t tx = x % out.width, ty = y % out.height;
      if (x == tx && y == ty) {
        out.at(tx, ty) = at(c);
      } else if (at(c) != out.at(tx, ty)) {
        throw std::runtime_error(where() + " holds " + std::to_string(at(c)) + ", its texel " +
                                 std::to_string(out.at(tx, ty)));
      }
    }
  }
  return out;
}

Pyramid8 BankMemory::read_pyramid(int plane) const {
  Pyramid8 p;
  for (int l = 0; l < geometry_.levels(); ++l) p.push_back(read_level(l, plane));
  return p;
}

size_t BankMemory::cells_not_written_once(int plane) const {
  size_t n = 0;
  for (int l = 0; l < geometry_.levels(); ++l) {
    for (uint32_t y = 0; y < geometry_.stored_height(l); ++y) {
      for (uint32_t x = 0; x < geometry_.stored_width(l); ++x) {
        n += writes_to(geometry_.cell(l, x, y, plane)) != 1;
      }
    }
  }
  return n;
}

}  // namespace tmu::texram
