// The TEXRAM chip's one memory (000 §5, §14): eight banks of 8-bit cells shared by every map of
// the chip. A map sits at one base, the same in every bank: its own layout (texram/layout.hpp)
// from cell 0 becomes base + cell, so each map keeps the property that any trilinear footprint
// reads each bank once, and the maps never overlap.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "formats/formats.hpp"
#include "texram/texture.hpp"

namespace tmu::texram::chip {

// Cells per bank: every address a BankAddr can hold (2^21 cells, 16 MiB in all).
inline constexpr uint32_t kBankCells = uint32_t{1} << formats::kBankAddr.width();

class ChipMemory {
 public:
  ChipMemory();

  // Copies `texture`'s banks into cells base .. base + bank_cells() - 1 of every bank. Throws
  // std::out_of_range when the map does not fit below kBankCells.
  void place(const TexramTexture& texture, uint32_t base);

  uint8_t cell(int bank, uint32_t address) const { return banks_[bank][address]; }
  const BankImage& banks() const { return banks_; }

 private:
  BankImage banks_;
};

}  // namespace tmu::texram::chip
