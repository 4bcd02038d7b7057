#include "blocks/cube_address/cube_address_block.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include "blocks/unit_vectors.hpp"
#include "deflect/cube_map.hpp"
#include "formats/formats.hpp"
#include "harness/described_engines.hpp"
#include "harness/described_hls.hpp"
#include "hls/deflect/cube_address_sc.hpp"
#include "rtl_models_cube_address.hpp"

TMU_DESCRIBE_SC(cube_address)

namespace tmu::tb {
namespace fmts = tmu::formats;
using D = desc::cube_address;

namespace {

constexpr int32_t kOne = 1 << fmts::kUnitComp.frac_bits;  // 1.0, SQ2.14
constexpr uint64_t kCoordMask = (uint64_t{1} << fmts::kTexCoord.width()) - 1;
constexpr std::array<const char*, 6> kFaceNames = {"+X", "-X", "+Y", "-Y", "+Z", "-Z"};

int16_t cube_x(const Txn& item) { return static_cast<int16_t>(item.f[D::in_x]); }
int16_t cube_y(const Txn& item) { return static_cast<int16_t>(item.f[D::in_y]); }
int16_t cube_z(const Txn& item) { return static_cast<int16_t>(item.f[D::in_z]); }
int cube_face_log2(const Txn& item) { return static_cast<int>(item.f[D::in_face_log2]); }

// The divider's seed-table index for the major component (golden divide_ratio's i for
// den = ma; 0 for ma = 0).
uint32_t cube_seed_index(uint32_t ma, int seed_bits) {
  if (ma == 0) return 0;
  const uint32_t d = (ma << std::countl_zero(ma)) >> 16;
  return (d >> (15 - seed_bits)) & ((1u << seed_bits) - 1);
}

class Golden : public Model {
 public:
  void step(const Txn& t, Sink& sink) override {
    const deflect::CubeAddress a = deflect::cube_address(
        cube_x(t), cube_y(t), cube_z(t), cube_face_log2(t), CubeAddressBlock::kSeedBits);
    Txn out;
    out.f[D::out_face] = a.face;
    out.f[D::out_u] = static_cast<uint64_t>(static_cast<int64_t>(a.u)) & kCoordMask;
    out.f[D::out_v] = static_cast<uint64_t>(static_cast<int64_t>(a.v)) & kCoordMask;
    sink.output(out);
  }
};

std::array<int32_t, 3> scaled(const std::array<double, 3>& dir, double length) {
  const std::array<int16_t, 3> c = unit_comps(dir, length);
  return {c[0], c[1], c[2]};
}

// The sizes every directed vector is addressed at: the smallest faces (1 and 2 texels, where
// u is mostly rounding), a typical one, and the two largest (every bit of s shows at L >= 8).
constexpr std::array<int, 5> kDirectedLog2 = {0, 1, 8, 9, 10};

// -m or m by a sign bit (-32768 is put directly: +32768 does not exist).
int32_t with_sign(bool negative, int32_t m) { return negative ? -m : m; }

// The hard vectors (without L).
std::vector<std::array<int32_t, 3>> hard_vectors() {
  std::vector<std::array<int32_t, 3>> v;
  const auto put = [&v](int32_t x, int32_t y, int32_t z) {
    if (std::max({x, y, z}) > 32767 || std::min({x, y, z}) < -32768)
      throw std::logic_error("cube_address: a directed component beyond SQ2.14");
    v.push_back({x, y, z});
  };
  // A vector with the components of a "pattern" (a, b, c) placed on the axes (i, j, k).
  const auto put_at = [&put](int i, int j, int k, int32_t a, int32_t b, int32_t c) {
    std::array<int32_t, 3> r{};
    r[static_cast<size_t>(i)] = a;
    r[static_cast<size_t>(j)] = b;
    r[static_cast<size_t>(k)] = c;
    put(r[0], r[1], r[2]);
  };
  constexpr std::array<std::array<int, 3>, 3> kPairs = {{{0, 1, 2}, {0, 2, 1}, {1, 2, 0}}};

  // The zero vector; each axis +- at 1 LSB, unit length, full scale, and -32768.
  put(0, 0, 0);
  for (int axis = 0; axis < 3; ++axis) {
    for (int32_t m : {1, kOne, 32767, -1, -kOne, -32767, -32768})
      put_at(axis, (axis + 1) % 3, (axis + 2) % 3, m, 0, 0);
  }
  // Cube edges: the two largest |components| equal (each pair, each sign), the third zero,
  // small of either sign, or one less than them.
  for (const auto& [i, j, k] : kPairs) {
    for (int32_t m : {1, 11585, kOne, 32767}) {
      for (int s = 0; s < 4; ++s) {
        for (int32_t c : {0, 3000 * m / 32767, -(3000 * m / 32767), m - 1}) {
          put_at(i, j, k, with_sign(s & 1, m), with_sign(s & 2, m), c);
        }
      }
    }
    // -32768 twice (|-32768| = 32768 is larger than every positive value).
    for (int32_t c : {0, 32767, -32767, 100}) put_at(i, j, k, -32768, -32768, c);
  }
  // Corners: three equal |components|, every sign.
  for (int32_t m : {1, 9459, kOne, 32767}) {
    for (int s = 0; s < 8; ++s) put(with_sign(s & 1, m), with_sign(s & 2, m), with_sign(s & 4, m));
  }
  put(-32768, -32768, -32768);
  // Near edges: the two largest |components| one LSB apart, either one larger, every sign.
  for (const auto& [i, j, k] : kPairs) {
    for (int32_t m : {11585, 32766}) {
      for (int s = 0; s < 4; ++s) {
        put_at(i, j, k, with_sign(s & 1, m + 1), with_sign(s & 2, m), 1000);
        put_at(i, j, k, with_sign(s & 1, m), with_sign(s & 2, m + 1), -1000);
      }
    }
    // 32767 against -32768: the negative one is larger.
    put_at(i, j, k, 32767, -32768, 0);
    put_at(i, j, k, -32768, 32767, 5);
  }
  // The largest component's sign: a generic direction with each axis major, every octant.
  for (const auto& p : std::array<std::array<int, 3>, 6>{
           {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}}) {
    for (int s = 0; s < 8; ++s) {
      put_at(p[0], p[1], p[2], with_sign(s & 1, 12000), with_sign(s & 2, 5000),
             with_sign(s & 4, 3000));
    }
  }
  // The extremes against each other and against small values.
  for (const auto& p : std::array<std::array<int, 3>, 3>{{{0, 1, 2}, {1, 2, 0}, {2, 0, 1}}}) {
    put_at(p[0], p[1], p[2], -32768, 32767, -32767);
    put_at(p[0], p[1], p[2], 32767, -32767, 1);
    put_at(p[0], p[1], p[2], -32768, 1, -1);
    put_at(p[0], p[1], p[2], 32767, -32768 + 1, 16384);
  }
  // Tiny vectors (ratios of small integers).
  for (const auto& t :
       std::array<std::array<int32_t, 3>, 4>{{{3, 1, 2}, {2, 5, -4}, {-1, 2, 7}, {7, 7, 3}}}) {
    put(t[0], t[1], t[2]);
    put(-t[0], -t[1], -t[2]);
  }
  return v;
}

}  // namespace

Txn cube_item(int32_t x, int32_t y, int32_t z, int face_log2) {
  return channel_item(D::table(), "in",
                      {static_cast<uint16_t>(x), static_cast<uint16_t>(y), static_cast<uint16_t>(z),
                       static_cast<uint64_t>(face_log2)});
}

CubeFaceCoords cube_face_coords(int32_t x, int32_t y, int32_t z) {
  const int32_t ax = std::abs(x), ay = std::abs(y), az = std::abs(z);
  CubeFaceCoords c;
  if (ax >= ay && ax >= az) {
    c = {x < 0 ? 1u : 0u, x < 0 ? z : -z, -y, ax};
  } else if (ay >= az) {
    c = {y < 0 ? 3u : 2u, x, y < 0 ? -z : z, ay};
  } else {
    c = {z < 0 ? 5u : 4u, z < 0 ? -x : x, -y, az};
  }
  return c;
}

CubeAddressBlock::CubeAddressBlock(const BlockOptions&) : DescribedBlockOf(D::table()) {
  add_level("hls", hls_level<desc::cube_address_sc, hls::CubeAddressSc>(kSeedBits));
  TMU_ADD_RTL_LEVELS(cube_address, variant());
}

std::vector<Txn> CubeAddressBlock::directed_items() const {
  std::vector<Txn> items;
  // Every hard vector at the smallest, a typical and the largest face sizes.
  for (const auto& [x, y, z] : hard_vectors()) {
    for (int l : kDirectedLog2) items.push_back(cube_item(x, y, z, l));
  }
  // One generic vector per face at every face size.
  for (int l = 0; l <= fmts::kMaxMipLog2; ++l) {
    for (uint32_t face = 0; face < 6; ++face) {
      std::array<int32_t, 3> r = {7001, -2999, 4567};
      std::rotate(r.begin(), r.begin() + (3 - face / 2) % 3, r.end());  // 7001 on axis face / 2
      if (face % 2) r[face / 2] = -r[face / 2];
      items.push_back(cube_item(r[0], r[1], r[2], l));
    }
  }
  // The port's sizes beyond the TEXRAM's faces, L = 11 .. 15 (the unit computes golden's
  // formula for every 4-bit L): the upper bits of u and v (docs/coverage.md).
  for (int l = fmts::kMaxMipLog2 + 1; l < 16; ++l) {
    for (const auto& [x, y, z] : hard_vectors()) items.push_back(cube_item(x, y, z, l));
  }
  // Every seed-table index of the dividers' denominator ma (the major |component| in
  // [2^14, 2^15): index (ma >> 7) & 127 at S = 7, here at the mantissa's bucket middle), the
  // faces and the face coordinates varied by the index, on the largest face.
  for (uint32_t i = 0; i < (1u << kSeedBits); ++i) {
    const auto ma = static_cast<int32_t>(
        std::lround(16384.0 * (1.0 + (i + 0.5) / static_cast<double>(1u << kSeedBits))));
    const int32_t sc = ma * static_cast<int32_t>((i * 37) % 101) / 101;
    const int32_t tc = ma * static_cast<int32_t>((i * 53) % 89) / 89;
    std::array<int32_t, 3> r{};
    const uint32_t face = i % 6;
    r[face / 2] = face % 2 ? -ma : ma;
    r[(face / 2 + 1) % 3] = i & 8 ? -sc : sc;
    r[(face / 2 + 2) % 3] = i & 16 ? -tc : tc;
    items.push_back(cube_item(r[0], r[1], r[2], fmts::kMaxMipLog2));
  }
  return items;
}

std::vector<Txn> CubeAddressBlock::random_items(std::mt19937_64& rng, size_t count) const {
  std::vector<Txn> items;
  items.reserve(count);
  std::uniform_real_distribution<double> log_length(-14.0, 1.0);
  for (size_t i = 0; i < count; ++i) {
    const uint64_t kind = rng() % 20;
    const int l = static_cast<int>(rng() % (fmts::kMaxMipLog2 + 1));
    std::array<int32_t, 3> r{};
    if (kind < 10) {  // a unit reflection vector, quantized (the coordinate generator's)
      r = scaled(random_direction(rng), 1.0);
    } else if (kind < 14) {  // any length 2^-14 .. 2, saturated to the port's range
      r = scaled(random_direction(rng), std::exp2(log_length(rng)));
    } else if (kind < 16) {  // raw 16-bit components
      const uint64_t b = rng();
      r = {static_cast<int16_t>(b), static_cast<int16_t>(b >> 16), static_cast<int16_t>(b >> 32)};
    } else if (kind < 18) {  // a cube edge or corner: |components| made equal, any sign
      r = scaled(random_direction(rng), 1.0);
      const uint64_t b = rng();
      const auto src = static_cast<size_t>(b % 3);
      const auto dst = static_cast<size_t>((src + 1 + (b >> 2) % 2) % 3);
      const int32_t m = std::abs(r[src]);
      r[dst] = b & 16 ? -m : m;
      if (b & 32) r[3 - src - dst] = b & 64 ? -m : m;  // all three: a corner
    } else {  // on a face's axis or in a coordinate plane: one or two components zeroed
      r = scaled(random_direction(rng), 1.0);
      const uint64_t b = rng() % 6;
      if (b < 3) {
        r[b] = 0;
      } else {
        r[(b + 1) % 3] = 0;
        r[(b + 2) % 3] = 0;
      }
    }
    items.push_back(cube_item(r[0], r[1], r[2], l));
  }
  return items;
}

std::unique_ptr<Model> CubeAddressBlock::golden() const { return std::make_unique<Golden>(); }

namespace {
constexpr const char* kZero = "zero vector (+X, the face's centre)";
constexpr const char* kAxis = "an axis (two components zero: the face's centre)";
constexpr const char* kEdgeXY = "edge |x| = |y| > |z| (to x)";
constexpr const char* kEdgeXZ = "edge |x| = |z| > |y| (to x)";
constexpr const char* kEdgeYZ = "edge |y| = |z| > |x| (to y)";
constexpr const char* kCorner = "corner |x| = |y| = |z| != 0 (to x)";
constexpr const char* kNearEdge = "near edge (the two largest |components| 1 LSB apart)";
constexpr const char* kBorder = "|sc| or |tc| = ma != 0 (the face's border)";
constexpr const char* kEverySeed = "every seed-table index (ma)";
}  // namespace

std::vector<std::string> CubeAddressBlock::coverage_cases() const {
  std::vector<std::string> cases;
  for (const char* f : kFaceNames) cases.push_back(fmt::format("face {}", f));
  cases.insert(cases.end(), {kZero, kAxis, kEdgeXY, kEdgeXZ, kEdgeYZ, kCorner, kNearEdge, kBorder,
                             "major component -32768", "component -32768", "component +32767",
                             "sc < 0 (u below the centre)", "sc > 0 (u above the centre)",
                             "tc < 0 (v below the centre)", "tc > 0 (v above the centre)",
                             "tiny vector (every |component| < 16 LSB, not zero)",
                             "short vector (length < 1/4)", "long vector (length > 1.5)"});
  for (int l = 0; l <= fmts::kMaxMipLog2; ++l) cases.push_back(fmt::format("face_log2 {}", l));
  cases.push_back(kEverySeed);
  return cases;
}

void CubeAddressBlock::cover(const std::vector<Txn>& items, size_t index, const Txn&,
                             Coverage& cov) const {
  if (index == 0 || index != cover_next_) seen_seed_.clear();
  cover_next_ = index + 1;
  const Txn& item = items[index];
  const int32_t x = cube_x(item), y = cube_y(item), z = cube_z(item);
  const int32_t a = std::abs(x), b = std::abs(y), c = std::abs(z);
  const CubeFaceCoords fc = cube_face_coords(x, y, z);
  const int zeros = (x == 0) + (y == 0) + (z == 0);

  ++cov[fmt::format("face {}", kFaceNames[fc.face])];
  if (zeros == 3) ++cov[kZero];
  if (zeros == 2) ++cov[kAxis];
  if (a != 0 && a == b && b == c) {
    ++cov[kCorner];
  } else {
    if (a == b && a > c) ++cov[kEdgeXY];
    if (a == c && a > b) ++cov[kEdgeXZ];
    if (b == c && b > a) ++cov[kEdgeYZ];
  }
  std::array<int32_t, 3> m = {a, b, c};
  std::sort(m.begin(), m.end());
  if (m[2] - m[1] == 1) ++cov[kNearEdge];
  if (fc.ma != 0 && (std::abs(fc.sc) == fc.ma || std::abs(fc.tc) == fc.ma)) ++cov[kBorder];
  if (fc.ma == 32768) ++cov["major component -32768"];
  if (x == -32768 || y == -32768 || z == -32768) ++cov["component -32768"];
  if (x == 32767 || y == 32767 || z == 32767) ++cov["component +32767"];
  if (fc.sc < 0) ++cov["sc < 0 (u below the centre)"];
  if (fc.sc > 0) ++cov["sc > 0 (u above the centre)"];
  if (fc.tc < 0) ++cov["tc < 0 (v below the centre)"];
  if (fc.tc > 0) ++cov["tc > 0 (v above the centre)"];
  if (zeros < 3 && m[2] < 16) ++cov["tiny vector (every |component| < 16 LSB, not zero)"];
  const double len2 =
      (static_cast<double>(a) * a + static_cast<double>(b) * b + static_cast<double>(c) * c) /
      (double{kOne} * kOne);
  if (zeros < 3 && len2 < 1.0 / 16) ++cov["short vector (length < 1/4)"];
  if (len2 > 1.5 * 1.5) ++cov["long vector (length > 1.5)"];
  const int l = cube_face_log2(item);
  if (l <= fmts::kMaxMipLog2) ++cov[fmt::format("face_log2 {}", l)];
  // The seed-table case counts once, when its last index is reached.
  if (seen_seed_.insert(cube_seed_index(static_cast<uint32_t>(fc.ma), kSeedBits)).second &&
      seen_seed_.size() == (size_t{1} << kSeedBits)) {
    ++cov[kEverySeed];
  }
}

}  // namespace tmu::tb

TMU_REGISTER_BLOCK(cube_address, CubeAddressBlock)
