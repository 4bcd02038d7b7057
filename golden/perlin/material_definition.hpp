// What the host loads into the material unit, as data: the material's kind, its registers
// (raw fixed-point values) and its colour tables. Definitions only, no arithmetic: golden
// (materials.hpp gives what the registers mean) and the ideal model (materials_ideal.hpp)
// read the same registers and tables, each by its own code.
#pragma once

#include <array>
#include <cstdint>

namespace tmu::perlin {

enum class MaterialKind : uint8_t { kMarble, kWood, kBrick, kFog, kCloud, kFire };
constexpr int kColourEntries = 128;

struct MaterialRegs {
  MaterialKind kind = MaterialKind::kMarble;
  uint32_t g_t = 32 << 8;                  // UQ8.8: entries per unit of T or F
  uint32_t g_v = 8 << 8;                   // UQ8.8, marble: entries per unit of v
  uint32_t g_r = 16 << 8;                  // UQ8.8, wood: entries per unit of u^2 + v^2
  int32_t g_w = 2 << 8;                    // SQ8.8, wood: entries per unit of w (the cones' slope)
  int32_t offset = 0;                      // IQ7.8, fire: index offset
  uint32_t g_l = 255 << 8;                 // UQ8.8, fog and cloud: 8-bit levels per unit of F
  int32_t cutoff = 0;                      // SQ2.14, cloud
  int pw = 12, ph = 11;                    // brick: log2 of the periods in raw units (12: one unit)
  int32_t mortar_w = 205, mortar_h = 205;  // brick: M_W, M_H in raw units (about 0.05)
  friend bool operator==(const MaterialRegs&, const MaterialRegs&) = default;
};

struct ColourTables {
  std::array<uint32_t, kColourEntries> main{};    // RGB888
  std::array<uint32_t, kColourEntries> mortar{};  // brick only
};

}  // namespace tmu::perlin
