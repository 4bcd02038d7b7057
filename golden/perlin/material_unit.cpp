#include "perlin/material_unit.hpp"

#include <algorithm>

namespace tmu::perlin {
namespace {

int32_t signed16(uint32_t v) {
  const auto low = static_cast<int32_t>(v & 0xFFFF);
  return low >= 0x8000 ? low - 0x10000 : low;
}

}  // namespace

void MaterialUnit::write_reg(MaterialReg reg, uint32_t value) {
  const uint32_t u = value & 0xFFFF;
  const int32_t s = signed16(value);
  MaterialRegs& r = regs_;
  switch (reg) {
    case MaterialReg::kKind:
      r.kind = static_cast<MaterialKind>(std::min<uint32_t>(u, 5));
      break;
    case MaterialReg::kGt:
      r.g_t = u;
      break;
    case MaterialReg::kGv:
      r.g_v = u;
      break;
    case MaterialReg::kGr:
      r.g_r = u;
      break;
    case MaterialReg::kGw:
      r.g_w = s;
      break;
    case MaterialReg::kOffset:
      r.offset = s;
      break;
    case MaterialReg::kGl:
      r.g_l = u;
      break;
    case MaterialReg::kCutoff:
      r.cutoff = s;
      break;
    case MaterialReg::kPw:
      r.pw = std::clamp<int>(static_cast<int>(u), 1, 20);
      r.mortar_w = std::min<int32_t>(r.mortar_w, (1 << (r.pw - 1)) - 1);
      break;
    case MaterialReg::kPh:
      r.ph = std::clamp<int>(static_cast<int>(u), 1, 20);
      r.mortar_h = std::min<int32_t>(r.mortar_h, (1 << (r.ph - 1)) - 1);
      break;
    case MaterialReg::kMortarW:
      r.mortar_w = std::min<int32_t>(static_cast<int32_t>(u), (1 << (r.pw - 1)) - 1);
      break;
    case MaterialReg::kMortarH:
      r.mortar_h = std::min<int32_t>(static_cast<int32_t>(u), (1 << (r.ph - 1)) - 1);
      break;
    default:
      break;  // no such register: ignored
  }
}

void MaterialUnit::write_table(uint32_t table, uint32_t index, uint32_t rgb) {
  if (index >= kColourEntries) return;  // beyond the table: ignored
  auto& t = (table & 1) ? tables_.mortar : tables_.main;
  t[index] = rgb & 0xFFFFFF;
}

uint32_t MaterialUnit::sample(int64_t u, int64_t v, int64_t w) const {
  return shade_material(config_, regs_, tables_, u, v, w);
}

}  // namespace tmu::perlin
