#include "blocks/noise/solid_stimulus.hpp"

namespace tmu::tb::solid {
namespace {

constexpr uint32_t kLatticeMask = (1u << perlin::kLatticeBits) - 1;
constexpr uint64_t mask(int width) { return (uint64_t{1} << width) - 1; }
constexpr int32_t kSearch = 16;  // directed searches look at the lattice points [-16, 16)^3

constexpr const char* kNegative = "negative coordinate";
constexpr const char* kAllNegative = "every coordinate negative";
constexpr const char* kMinCoord = "coordinate -2^23";
constexpr const char* kMaxCoord = "coordinate 2^23 - 1";
constexpr const char* kEqual = "u = v = w";

// --- random coordinates --------------------------------------------------------------------

enum class AxisKind { kUniform, kSmall, kLattice, kBoundary, kLarge, kLowBits, kCount };

// Raw fractions at and next to a cell boundary and the fade index's edges.
constexpr std::array<int32_t, 8> kBoundaryFractions = {0, 1, 15, 16, 0x7FF, 0x800, 0xFF0, 0xFFF};

int32_t random_axis(std::mt19937_64& rng, AxisKind kind) {
  const auto index = [&rng] { return static_cast<int32_t>(rng() % 4096) - 2048; };
  switch (kind) {
    case AxisKind::kSmall:  // within 8 units of the origin
      return static_cast<int32_t>(rng() % (16 * kUnit)) - 8 * kUnit;
    case AxisKind::kLattice:
      return index() * kUnit;
    case AxisKind::kBoundary:  // always in range: at most 2047 units + 0xFFF
      return index() * kUnit + kBoundaryFractions[rng() % kBoundaryFractions.size()];
    case AxisKind::kLarge: {  // |x| >= 2^20: octave 3 (and for 2^22, octave 1) wraps
      const auto mag = static_cast<int32_t>(0x100000 + rng() % (kCoordMax - 0x100000 + 1));
      return rng() % 2 ? mag : -mag;
    }
    case AxisKind::kLowBits: {  // the bits below the fade index all zero or all one
      const int32_t x = wrap24(static_cast<int64_t>(rng()));
      return rng() % 2 ? (x & ~0xF) : (x | 0xF);
    }
    default:
      return wrap24(static_cast<int64_t>(rng()));
  }
}

AxisKind random_kind(std::mt19937_64& rng) {
  return static_cast<AxisKind>(rng() % static_cast<uint64_t>(AxisKind::kCount));
}

}  // namespace

bool in_range(int64_t x) { return x >= kCoordMin && x <= kCoordMax; }

int32_t wrap24(int64_t x) {
  const auto low = static_cast<uint32_t>(static_cast<uint64_t>(x) & mask(kCoordW));
  return static_cast<int32_t>(low << (32 - kCoordW)) >> (32 - kCoordW);
}

Txn item(int32_t u, int32_t v, int32_t w, int first) {
  Txn t;
  const auto s = static_cast<size_t>(first);
  t.f[s] = static_cast<uint32_t>(u) & mask(kCoordW);
  t.f[s + 1] = static_cast<uint32_t>(v) & mask(kCoordW);
  t.f[s + 2] = static_cast<uint32_t>(w) & mask(kCoordW);
  return t;
}

std::array<int32_t, 3> coords(const Txn& item, int first) {
  const auto s = static_cast<size_t>(first);
  return {wrap24(static_cast<int64_t>(item.f[s])), wrap24(static_cast<int64_t>(item.f[s + 1])),
          wrap24(static_cast<int64_t>(item.f[s + 2]))};
}

void add(std::vector<Txn>& items, int64_t u, int64_t v, int64_t w) {
  if (in_range(u) && in_range(v) && in_range(w)) {
    items.push_back(
        item(static_cast<int32_t>(u), static_cast<int32_t>(v), static_cast<int32_t>(w)));
  }
}

int32_t lattice_value_at(int32_t i, int32_t j, int32_t k) {
  return perlin::lattice_value(static_cast<uint32_t>(i) & kLatticeMask,
                               static_cast<uint32_t>(j) & kLatticeMask,
                               static_cast<uint32_t>(k) & kLatticeMask);
}

// The first n lattice points of the search cube that satisfy `want` (in a fixed order).
std::vector<Lattice> lattice_points_where(const std::function<bool(const Lattice&)>& want,
                                          size_t n) {
  std::vector<Lattice> found;
  for (int32_t i = -kSearch; i < kSearch && found.size() < n; ++i) {
    for (int32_t j = -kSearch; j < kSearch && found.size() < n; ++j) {
      for (int32_t k = -kSearch; k < kSearch && found.size() < n; ++k) {
        if (want({i, j, k})) found.push_back({i, j, k});
      }
    }
  }
  return found;
}

std::vector<Txn> directed_items() {
  std::vector<Txn> items;
  const auto add = [&items](int64_t u, int64_t v, int64_t w) { solid::add(items, u, v, w); };
  // Lattice points around the origin (every fade weight 0: P is a corner's value).
  for (int32_t i = -2; i <= 2; ++i) {
    for (int32_t j = -2; j <= 2; ++j) {
      for (int32_t k = -2; k <= 2; ++k) add(i * kUnit, j * kUnit, k * kUnit);
    }
  }
  // Lattice points whose value is -1.0 (P = -1.0, |P| one bit wider than P) or 127/128, and
  // one LSB to either side of them (the cell below on every axis; a fraction of 1/4096).
  for (const int32_t value : {-128, 127}) {
    const auto points = lattice_points_where(
        [value](const Lattice& l) { return lattice_value_at(l[0], l[1], l[2]) == value; }, 4);
    for (const Lattice& l : points) {
      const int64_t u = int64_t{l[0]} * kUnit, v = int64_t{l[1]} * kUnit, w = int64_t{l[2]} * kUnit;
      add(u, v, w);
      add(u - 1, v - 1, w - 1);
      add(u + 1, v + 1, w + 1);
      add(u + 16, v, w - 16);
    }
  }
  // Cell boundaries: raw fractions ..FFF, ..000, ..001, the fade index's edges (15 | 16:
  // index 0 | 1; 0xFEF | 0xFF0: index 254 | 255), the middle, on each axis and on all three;
  // at the origin, next to it, and at the ends of the range.
  for (const int32_t base : {0, 1, -1, 5, -7, 2047, -2048}) {
    for (const int32_t d : {-1, 0, 1, 15, 16, 0x7FF, 0x800, 0xFEF, 0xFF0, 0xFFF}) {
      const int64_t x = int64_t{base} * kUnit + d;
      add(x, 3 * kUnit + 0x5A0, -2 * kUnit + 0x3C0);
      add(9 * kUnit + 0x1F0, x, 0x777);
      add(-0x2345, 0x6789, x);
      add(x, x, x);
    }
  }
  // Every fade index on every axis (u k, v k, w 255 - k), with the bits below it varying.
  for (int32_t k = 0; k < 256; ++k) {
    add(k * 16 + k % 16, 3 * kUnit + k * 16, -5 * kUnit + (255 - k) * 16 + 15);
  }
  // Negative coordinates: -1 LSB, -1, -1 - 1 LSB, -1/2, -3/2, -1/256 (fade index 255), -17 LSB.
  for (const int32_t x : {-1, -kUnit, -kUnit - 1, -kUnit / 2, -3 * kUnit / 2, -16, -17}) {
    add(x, 0, 0);
    add(0, x, 0);
    add(0, 0, x);
    add(x, 2 * x, 3 * x);
  }
  // The SolidCoord extremes -2^23, 2^23 - 1 against each other, -1 LSB and 0.
  for (const int32_t a : {kCoordMin, kCoordMax, -1, 0}) {
    for (const int32_t b : {kCoordMin, kCoordMax, -1, 0}) {
      for (const int32_t c : {kCoordMin, kCoordMax, -1, 0}) add(a, b, c);
    }
  }
  // u = v = w.
  for (const int32_t x : {1, 0x800, 7 * kUnit + 0x9A0, 0x123456, -0x123456, -kUnit - 0x10}) {
    add(x, x, x);
  }
  // Coordinates whose octave shifts leave 24 bits (|x| >= 2^20, 2^21, 2^22).
  for (const int32_t x : {0x0FFFFF, 0x100000, 0x1FFFFF, 0x200000, 0x3FFFFF, 0x400000, -0x400000,
                          -0x400001, 0x555555, -0x2AAAAB, 0x7FF800, -0x7FF800}) {
    add(x, 0x12345, -x / 3);
    add(-0x54321, x, x / 5);
    add(x / 7, -0x3210, x);
    add(x, x, x);
  }
  return items;
}

std::vector<Txn> random_items(std::mt19937_64& rng, size_t count) {
  std::vector<Txn> items;
  items.reserve(count);
  for (size_t i = 0; i < count; ++i) {
    const uint64_t kind = rng() % 16;
    std::array<int32_t, 3> c{};
    if (kind < 6) {
      for (auto& x : c) x = random_axis(rng, AxisKind::kUniform);
    } else if (kind < 8) {
      for (auto& x : c) x = random_axis(rng, AxisKind::kSmall);
    } else if (kind < 10) {
      for (auto& x : c) x = random_axis(rng, AxisKind::kLattice);
    } else if (kind < 12) {
      for (auto& x : c) x = random_axis(rng, AxisKind::kBoundary);
    } else if (kind < 13) {
      c[0] = c[1] = c[2] = random_axis(rng, random_kind(rng));
    } else if (kind < 14) {
      for (auto& x : c) x = random_axis(rng, AxisKind::kLarge);
    } else {
      for (auto& x : c) x = random_axis(rng, random_kind(rng));
    }
    items.push_back(item(c[0], c[1], c[2]));
  }
  return items;
}

std::vector<std::string> coord_cases() {
  return {kNegative, kAllNegative, kMinCoord, kMaxCoord, kEqual};
}

void cover_coords(const std::array<int32_t, 3>& c, Coverage& cov) {
  int negative = 0;
  for (const int32_t x : c) {
    if (x < 0) ++negative;
    if (x == kCoordMin) ++cov[kMinCoord];
    if (x == kCoordMax) ++cov[kMaxCoord];
  }
  if (negative > 0) ++cov[kNegative];
  if (negative == 3) ++cov[kAllNegative];
  if (c[0] == c[1] && c[1] == c[2]) ++cov[kEqual];
}

}  // namespace tmu::tb::solid
