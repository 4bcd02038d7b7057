// Golden model of the TEXRAM's volume unit (000 §13, Fig. 15): per resample location the
// corner voxels (and in raw mode their gradient neighbours) read from the four level-0 banks
// (layout.hpp) in a fixed schedule of accesses, the trilinear blend at W weight bits and the
// gradient. This file is the specification a later RTL matches access for access.
//
// Position (VoxelPos, marcher.hpp) -> corners, per axis of n voxels:
//   p is clamped to 0 .. n - 1 (a location outside the volume takes the nearest face's);
//   i0 = floor(p), i1 = min(i0 + 1, n - 1) (i1 = i0 only at p = n - 1, where its weight is 0),
//   w = the top W bits of p's 16 fraction bits (truncated, as the 2-D unit does), the weight of
//   i1; the pair (2^W - w, w).
// Access schedule (accesses of the four banks; each reads voxels of one slice, four banks):
//   1: (i0|i1, j0|j1, k0)        2: (i0|i1, j0|j1, k1)          the corners: the value
//   3: (i0-1|i0+2, j0|j1, k0)    4: (i0-1|i0+2, j0|j1, k1)      x-gradient neighbours
//   5: (i0|i1, j0-1|j0+2, k0)    6: (i0|i1, j0-1|j0+2, k1)      y-gradient neighbours
//   7: (i0|i1, j0|j1, k0-1)      8: (i0|i1, j0|j1, k0+2)        z-gradient neighbours
// Value mode (a pre-classified RGBA set, one component per chip) performs accesses 1-2, raw
// mode all eight; the patent's order: the value after 1-2, x after 3-4, y and z after 5-8.
// A voxel outside the volume is not read (its bank idles in that access); two corners that
// are one voxel (i1 = i0) share the read. Every access takes its period whatever it reads.
// Gradient at a node (central differences, 000 §13 Fig. 15): D = f(i+1) - f(i-1), the
// gradient being D / 2 voxel values per voxel; outside the volume the field continues
// linearly from its two edge voxels (f(-1) = 2 f(0) - f(1), f(n) = 2 f(n-1) - f(n-2)), so a
// node on a face gets the one-sided difference D = 2 (f(1) - f(0)) and a linear field has its
// exact gradient everywhere. D: -510 .. 510, integers (the gradient with 1 fraction bit).
// Blend: the project's one rule (fx::trilerp, golden/fixed/blend.hpp): value = the eight
// corner voxels, the exact weighted sum rounded once half up by 3W bits to 0..255 (Channel);
// gradient component = the eight corners' D, the exact weighted sum rounded once half up by
// 3W - 3 bits to VolumeGrad SQ9.4 (voxel values per voxel, 4 fraction bits; raw -4080 ..
// 4080 = 8 D). Rounding to D's own half units (SQ9.1) would double the direction's error on
// a smooth field (docs/volume.md: 1.6 degrees mean on the sphere against 0.9).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "texram/page_model.hpp"
#include "volume/layout.hpp"
#include "volume/marcher.hpp"
#include "volume/voxels.hpp"

namespace tmu::volume {

enum class Mode { kValue = 0, kRaw = 1 };  // VolumeMode

inline constexpr int kValueAccesses = 2;
inline constexpr int kGradFrac = 4;  // VolumeGrad's fraction bits; D has 1: keep 3 more
inline constexpr int kRawAccesses = 8;
inline constexpr int accesses_per_resample(Mode mode) {
  return mode == Mode::kRaw ? kRawAccesses : kValueAccesses;
}

struct Config {
  Mode mode = Mode::kValue;
  int weight_bits = 8;  // W, 1..8
  friend bool operator==(const Config&, const Config&) = default;
};

// The volume in the four level-0 banks.
struct VolumeMemory {
  VolumeGeometry geometry;
  std::array<std::vector<uint8_t>, kVolumeBanks> banks;
};
VolumeMemory load(const VoxelGrid& grid);  // throws std::invalid_argument as VolumeGeometry

// One axis of a location: corner indices and the W-bit weight of i1.
struct AxisCorners {
  uint32_t i0 = 0, i1 = 0;
  uint32_t w = 0;
};
AxisCorners axis_corners(int32_t pos, uint32_t n, int weight_bits);

struct Voxel {
  uint32_t x = 0, y = 0, z = 0;
  friend bool operator==(const Voxel&, const Voxel&) = default;
};

// One access: per bank the voxel read and its address (nothing where the bank idles).
struct Access {
  std::array<std::optional<Voxel>, kVolumeBanks> voxel;
  std::array<std::optional<uint32_t>, kVolumeBanks> address;
  friend bool operator==(const Access&, const Access&) = default;
};

// The accesses of one location, in order. Throws std::logic_error if an access would need two
// different cells of one bank (the layout guarantees it never does).
std::vector<Access> plan_accesses(const VolumeGeometry& geometry, const Position& pos, Mode mode);

struct Resample {
  uint8_t value = 0;                  // Channel
  std::array<int32_t, 3> gradient{};  // VolumeGrad SQ9.4 raw (raw mode; zero in value mode)
  friend bool operator==(const Resample&, const Resample&) = default;
};

// The bytes one access delivered: bank b's in slot b (anything where the bank idled).
using AccessData = std::array<uint8_t, kVolumeBanks>;

// The blends of one location from what its accesses (plan_accesses' order and count for the
// mode) delivered, as a unit with a memory port gets them back (the hls model): the corner
// values and, in raw mode, the central differences, through fx::trilerp. A byte of a bank
// that idled is never read. std::logic_error if the schedule missed a voxel the blends need,
// std::invalid_argument for a weight width outside 1..8 or an access count that is not the
// mode's.
Resample blend(const VolumeGeometry& geometry, const Config& config, const Position& pos,
               const std::vector<Access>& accesses, const std::vector<AccessData>& data);

// The unit: accesses (recorded in `accesses` when given, appended), the blends; the page
// model (when given) sees every access. The arithmetic reads only what the accesses
// delivered (blend(); std::logic_error if the schedule missed a voxel it needs).
Resample resample(const VolumeMemory& memory, const Config& config, const Position& pos,
                  texram::PageModel* pages = nullptr, std::vector<Access>* accesses = nullptr);

// A whole ray through the marcher, its resamples in order.
std::vector<Resample> cast(const VolumeMemory& memory, const Config& config, const Ray& ray,
                           texram::PageModel* pages = nullptr,
                           std::vector<Access>* accesses = nullptr);

// The page model's view of an access: bank b's address in slot b (banks 4-7 idle).
std::array<std::optional<uint32_t>, 8> page_addresses(const Access& access);

}  // namespace tmu::volume
