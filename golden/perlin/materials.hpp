// Golden model of the six procedural materials (002 §4.2) on top of the noise unit
// (noise.hpp): solid texture coordinates (u, v, w) (SolidCoord SQ12.12 raw, already scaled by
// the host) -> RGB888. This file is the specification the hls and rtl models match.
//
// Coordinates are taken as SolidCoord: their low 24 bits, sign-extended.
// Registers are raw fixed-point values the host loads once per material (MaterialRegs); the
// colour tables are 128 x RGB888 (ColourTables; brick has a second, the mortar's).
//
// Colour index: an index value is IQ7.8 taken mod 2^15 (the 128 entries wrap, 002's "mod
// 128"); its bits 14:8 address the table (no blending between entries). Products are exact;
// each term is shifted down to 8 fraction bits with floor (arithmetic shift), then summed mod
// 2^15:
//   marble (turbulence)  i = T g_t >> 14  +  v g_v >> 12
//   wood   (turbulence)  i = (u^2 + v^2) g_r >> 24  +  w g_w >> 12  +  T g_t >> 14
//   brick  (turbulence)  i = T g_t >> 14, from the brick table or the mortar table
//   fire   (fractal sum) i = clamp(F g_t >> 14 + offset, 0, 2^15 - 1)   (saturates: a flame's
//                        spectrum has no wrap)
// T = turbulence(u, v, w), F = a fractal sum (noise.hpp, as the ports carry them: port_sums,
// SQ2.14); g_t, g_v, g_r UQ8.8 (entries
// per unit), g_w, offset SQ8.8 / IQ7.8.
//
// Brick (002 §4.2.1, Fig. 4.12): the brick period (W + 2 M_W) x (H + 2 M_H) is a power of two
// in each direction (2^pw, 2^ph raw units: a divider-free choice; the thesis does not say),
// row = v >> ph; an even row is shifted by half a period, u' = u + 2^(pw-1) (= W/2 + M_W);
// u_r = u' mod 2^pw, v_r = v mod 2^ph; the point is brick when M_W < u_r < W + M_W and
// M_H < v_r < H + M_H (the thesis's text pairs u_r with M_H and v_r with M_W: a slip, the
// figure's geometry is as here), else mortar.
//
// Gases (002 §4.2.2), level = F g_l >> 22 (8-bit levels; g_l UQ8.8 levels per unit):
//   fog    F = fractal sum(u, v, w);          r = g = b = min(255, |level|)
//   cloud  F = fractal sum(2u, v, w);         r = g = min(255, level) if F > cutoff else 0; b = 255
//   fire   F = fractal sum(u, e^-v, w)        (v shaped by the table below), colour table at i
// Fire's shaping: e^-v from a table of 512 entries round(e^(-k/32) 2^12) (UQ1.12, k = 0..511)
// indexed by floor(v 32) clamped to 0..511: v <= 0 reads e^0 = 1 (the shaping starts at the
// flame's base), v beyond 16 reads the last entry (e^-15.97, 0 at 12 bits).
//
// The registers and the colour tables are definitions, shared with the ideal model:
// material_definition.hpp.
#pragma once

#include <cstdint>

#include "perlin/material_definition.hpp"
#include "perlin/noise.hpp"

namespace tmu::perlin {

constexpr int kFireTableEntries = 512;
constexpr int kFireTableFracBits = 5;  // v steps of 1/32
constexpr int kIndexBits = 15;         // IQ7.8

// Throws std::invalid_argument naming the register for a value out of range.
void check(const MaterialRegs& regs);

// Entry k of fire's e^-v table (UQ1.12).
uint32_t fire_entry(uint32_t k);
// v (SolidCoord raw) -> e^-v (SolidCoord raw, 0..4096).
int64_t fire_shape(int64_t v);

// The brick test on raw coordinates.
bool in_brick(const MaterialRegs& regs, int64_t u, int64_t v);

// The colour index (bits 14:8 of the index value) of marble, wood, brick and fire; the raw
// index value (IQ7.8 mod 2^15) too, for the tests.
uint32_t index_value(const NoiseConfig& config, const MaterialRegs& regs, int64_t u, int64_t v,
                     int64_t w);

// RGB888.
uint32_t shade_material(const NoiseConfig& config, const MaterialRegs& regs,
                        const ColourTables& tables, int64_t u, int64_t v, int64_t w);

}  // namespace tmu::perlin
