#include "texram/chip/chip_memory.hpp"

#include <algorithm>
#include <stdexcept>

namespace tmu::texram::chip {

ChipMemory::ChipMemory() {
  for (auto& bank : banks_) bank.assign(kBankCells, 0);
}

void ChipMemory::place(const TexramTexture& texture, uint32_t base) {
  const uint64_t end = uint64_t{base} + texture.geometry.bank_cells();
  if (end > kBankCells) {
    throw std::out_of_range("a map of " + std::to_string(texture.geometry.bank_cells()) +
                            " cells a bank at base " + std::to_string(base) +
                            " ends beyond the bank's " + std::to_string(kBankCells) + " cells");
  }
  for (size_t b = 0; b < banks_.size(); ++b) {
    const std::vector<uint8_t>& src = texture.banks[b];
    std::copy(src.begin(), src.end(), banks_[b].begin() + base);
  }
}

}  // namespace tmu::texram::chip
