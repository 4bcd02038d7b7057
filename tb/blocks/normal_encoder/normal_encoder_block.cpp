#include "blocks/normal_encoder/normal_encoder_block.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <map>
#include <optional>
#include <stdexcept>

#include "blocks/unit_vectors.hpp"
#include "formats/formats.hpp"
#include "harness/described_engines.hpp"
#include "harness/described_hls.hpp"
#include "hls/deflect/normal_encoder_sc.hpp"
#include "rtl_models_normal_encoder.hpp"

TMU_DESCRIBE_SC(normal_encoder)

namespace tmu::tb {
namespace fmts = tmu::formats;
using deflect::EncoderConfig;
using deflect::EncoderTrace;
using D = desc::normal_encoder;

namespace {

constexpr auto kOne = static_cast<int16_t>(1 << fmts::kUnitComp.frac_bits);  // 1.0, SQ2.14
constexpr uint32_t kRatioOne = 1u << deflect::kRatioFrac;

class GoldenEncoder : public Model {
 public:
  explicit GoldenEncoder(std::shared_ptr<const deflect::NormalEncoder> encoder)
      : encoder_(std::move(encoder)) {}
  void step(const Txn& item, Sink& sink) override {
    const deflect::SphereAngle a = encoder_->encode(normal_x(item), normal_y(item), normal_z(item));
    Txn out;
    out.f[D::out_phi] = a.phi;
    out.f[D::out_theta] = a.theta;
    sink.output(out);
  }

 private:
  std::shared_ptr<const deflect::NormalEncoder> encoder_;
};

std::string encoder_options(const EncoderConfig& c) {
  return fmt::format("--encoder {},{},{}", c.seed_bits, c.lut_exp, c.lut_mant);
}

Txn scaled_item(const std::array<double, 3>& dir, double length) {
  const std::array<int16_t, 3> c = unit_comps(dir, length);
  return normal_item(c[0], c[1], c[2]);
}

// --- directed items ------------------------------------------------------------------------

// The ratio the encoder divides for a probe normal: phi's of (u, 0, ref) or theta's of
// (ref, u, 0); u <= ref keeps it unswapped (t = (u / ref)^2 through the golden divider).
Txn ratio_probe(bool theta, int32_t ref, int32_t u) {
  const auto r = static_cast<int16_t>(ref), v = static_cast<int16_t>(u);
  return theta ? normal_item(r, v, 0) : normal_item(v, 0, r);
}
uint32_t probe_ratio(const deflect::NormalEncoder& enc, bool theta, int32_t ref, int32_t u) {
  const Txn item = ratio_probe(theta, ref, u);
  EncoderTrace t;
  enc.encode(normal_x(item), normal_y(item), normal_z(item), &t);
  return theta ? t.t_theta : t.t_phi;
}

// A probe whose ratio satisfies `want`, searched around u = ref sqrt(t_aim / 2^16) at a few
// reference lengths (the ratio's step per u differs with each). Empty when none was found.
template <class Want>
std::optional<Txn> find_probe(const deflect::NormalEncoder& enc, bool theta, double t_aim,
                              const Want& want) {
  for (int32_t ref : {32767, 32749, 30011, 27361, 23170, 16384, 8191}) {
    const auto start = static_cast<int32_t>(std::lround(ref * std::sqrt(t_aim / kRatioOne)));
    for (int32_t d = 0; d <= 64; ++d) {
      for (int32_t u : {start + d, start - d}) {
        if (u >= 0 && u <= ref && want(probe_ratio(enc, theta, ref, u)))
          return ratio_probe(theta, ref, u);
      }
    }
  }
  return std::nullopt;
}

// Items reaching every reachable angle-table index, for phi and theta: one ratio inside each
// bucket, and one on each bucket's first value (else within one of it), where a divider one
// LSB off reads the neighbouring entry.
void add_angle_index_items(const deflect::NormalEncoder& enc, std::vector<Txn>& items) {
  const EncoderConfig& c = enc.config();
  std::map<uint32_t, uint32_t> first;  // index -> its bucket's first ratio
  for (uint32_t t = kRatioOne; t >= 1; --t) first[deflect::angle_index(c, t)] = t;
  for (const auto& [index, lo] : first) {
    const uint32_t e = index >> c.lut_mant;
    const uint32_t m = index & ((1u << c.lut_mant) - 1);
    const double mid = std::ldexp(m + 0.5, 16 - c.lut_mant - 2 * static_cast<int>(e));
    for (bool theta : {false, true}) {
      const auto inside = [&](uint32_t t) { return t != 0 && deflect::angle_index(c, t) == index; };
      if (auto item = find_probe(enc, theta, std::max(mid, static_cast<double>(lo)), inside)) {
        items.push_back(*item);
      }
      if (lo <= 1) continue;
      auto edge = find_probe(enc, theta, lo, [lo](uint32_t t) { return t == lo; });
      if (!edge)
        edge = find_probe(enc, theta, lo, [lo](uint32_t t) { return t + 1 >= lo && t <= lo + 1; });
      if (edge) items.push_back(*edge);
    }
  }
}

// Items reaching every seed-table index, for phi (den = z^2) and theta (den = y^2): the
// denominator's mantissa 1 + (i + 1/2) / 2^S, a magnitude in [2^14, 2^14 sqrt 2).
void add_seed_index_items(int seed_bits, std::vector<Txn>& items) {
  const double entries = std::ldexp(1.0, seed_bits);
  for (uint32_t i = 0; i < (1u << seed_bits); ++i) {
    const double mant = 1.0 + (i + 0.5) / entries;
    auto c = static_cast<int32_t>(std::lround(std::sqrt(mant) * 16384.0));
    for (int32_t d = 0; d <= 8; ++d) {
      if (encoder_seed_index(static_cast<uint32_t>(c + d) * static_cast<uint32_t>(c + d),
                             seed_bits) == i) {
        c += d;
        break;
      }
      if (encoder_seed_index(static_cast<uint32_t>(c - d) * static_cast<uint32_t>(c - d),
                             seed_bits) == i) {
        c -= d;
        break;
      }
    }
    const auto big = static_cast<int16_t>(c);
    // A smaller companion (a third, varied by the index) to make the ratios differ.
    const auto small = static_cast<int16_t>(c / 3 + static_cast<int32_t>(i % 97) * 11);
    items.push_back(normal_item(small, 0, big));               // phi: den = Z
    items.push_back(normal_item(small, big, 0));               // theta: den = Y > X
    items.push_back(normal_item(static_cast<int16_t>(-small),  // both, other signs
                                static_cast<int16_t>(-big), static_cast<int16_t>(-big)));
  }
}

}  // namespace

Txn normal_item(int16_t x, int16_t y, int16_t z) {
  return channel_item(
      D::table(), "in",
      {static_cast<uint16_t>(x), static_cast<uint16_t>(y), static_cast<uint16_t>(z)});
}
int16_t normal_x(const Txn& item) { return static_cast<int16_t>(item.f[D::in_x]); }
int16_t normal_y(const Txn& item) { return static_cast<int16_t>(item.f[D::in_y]); }
int16_t normal_z(const Txn& item) { return static_cast<int16_t>(item.f[D::in_z]); }

uint32_t encoder_seed_index(uint32_t den, int seed_bits) {
  if (den == 0) return 0;
  const uint32_t d = (den << std::countl_zero(den)) >> 16;
  return (d >> (15 - seed_bits)) & ((1u << seed_bits) - 1);
}

std::set<uint32_t> reachable_angle_indices(const EncoderConfig& config) {
  std::set<uint32_t> s;
  for (uint32_t t = 1; t <= kRatioOne; ++t) s.insert(deflect::angle_index(config, t));
  return s;
}

NormalEncoderBlock::NormalEncoderBlock(const BlockOptions& options)
    : DescribedBlockOf(D::table()),
      encoder_(std::make_shared<const deflect::NormalEncoder>(options.encoder)),
      reachable_angle_(
          std::make_shared<const std::set<uint32_t>>(reachable_angle_indices(options.encoder))) {
  if (options.encoder.grid.phi_bits != fmts::kSpherePhi.width()) {
    throw std::invalid_argument(
        fmt::format("normal_encoder: the ports are built for the grid A = {}, not {}",
                    fmts::kSpherePhi.width(), options.encoder.grid.phi_bits));
  }
  add_level("hls", hls_level<desc::normal_encoder_sc, hls::NormalEncoderSc>(options.encoder));
  TMU_ADD_RTL_LEVELS(normal_encoder, variant());
  // Widths no variant verilates have no rtl level (texsim cosim notes it); Icarus runs them
  // with the widths as the RTL's parameters.
  const std::vector<std::string> have = levels();
  if (std::find(have.begin(), have.end(), "rtl") == have.end()) {
    const EncoderConfig& c = config();
    add_level("icarus",
              icarus_level("tmu_normal_encoder", fmt::format("SeedBits={} LutExp={} LutMant={}",
                                                             c.seed_bits, c.lut_exp, c.lut_mant)));
  }
}

std::string NormalEncoderBlock::variant() const {
  const EncoderConfig& c = config();
  if (c == EncoderConfig{}) return "";
  const std::string key = fmt::format("e{}m{}", c.lut_exp, c.lut_mant);
  return c.seed_bits == EncoderConfig{}.seed_bits ? key : fmt::format("s{}{}", c.seed_bits, key);
}

std::string NormalEncoderBlock::repro_options() const {
  return config() == EncoderConfig{} ? "" : encoder_options(config());
}

std::unique_ptr<Model> NormalEncoderBlock::golden() const {
  return std::make_unique<GoldenEncoder>(encoder_);
}

std::vector<Txn> NormalEncoderBlock::directed_items() const {
  std::vector<Txn> items;
  // The zero normal, and every normal of components -2 .. 2 (1-LSB poles and diagonals).
  for (int16_t x = -2; x <= 2; ++x) {
    for (int16_t y = -2; y <= 2; ++y) {
      for (int16_t z = -2; z <= 2; ++z) items.push_back(normal_item(x, y, z));
    }
  }
  // Tiny normals of a few LSB in every octant (ratios of small integers).
  for (const auto& [x, y, z] : {std::array<int16_t, 3>{3, 1, 7},
                                {5, 9, 2},
                                {15, 15, 1},
                                {7, 11, 13},
                                {1, 12, 5},
                                {4, 3, 0},
                                {0, 15, 8}}) {
    for (int s = 0; s < 8; ++s) {
      items.push_back(normal_item(static_cast<int16_t>(s & 1 ? -x : x),
                                  static_cast<int16_t>(s & 2 ? -y : y),
                                  static_cast<int16_t>(s & 4 ? -z : z)));
    }
  }
  // The six poles at unit length, full scale, and the most negative component.
  for (int16_t v :
       {kOne, static_cast<int16_t>(-kOne), int16_t{32767}, int16_t{-32767}, int16_t{-32768}}) {
    items.push_back(normal_item(v, 0, 0));
    items.push_back(normal_item(0, v, 0));
    items.push_back(normal_item(0, 0, v));
  }
  // Octant boundaries: one zero component, the other two of each sign.
  for (const auto& [a, b] : {std::pair<int16_t, int16_t>{10000, 5000},
                             {3000, 15000},
                             {11585, 11585},
                             {32767, 1},
                             {1, -32768}}) {
    for (int s = 0; s < 4; ++s) {
      const auto p = static_cast<int16_t>(s & 1 ? -a : a);
      const auto q = static_cast<int16_t>(s & 2 ? -b : b);
      items.push_back(normal_item(0, p, q));
      items.push_back(normal_item(p, 0, q));
      items.push_back(normal_item(p, q, 0));
    }
  }
  // Just off the y-z plane on the -x side (|x| < z / 256: t_phi = 0, k_phi = 0), where the
  // expansion's 4Q - 0 must wrap to phi 0.
  for (const auto& [x, y, z] :
       {std::array<int16_t, 3>{-1, 0, kOne}, {-63, 5000, 16384}, {-127, -9000, 32767}}) {
    items.push_back(normal_item(x, y, z));
  }
  // Two equal largest components: |x| = |z| (t_phi = 1), y^2 = x^2 + z^2 from Pythagorean
  // triples (t_theta = 1), |y| = |x| with z = 0, and all three equal; each sign.
  for (int s = 0; s < 8; ++s) {
    const auto sg = [s](int bit, int32_t v) { return static_cast<int16_t>(s & bit ? -v : v); };
    items.push_back(normal_item(sg(1, 11585), sg(2, 3), sg(4, 11585)));
    items.push_back(normal_item(sg(1, 32767), sg(2, 0), sg(4, 32767)));
    items.push_back(normal_item(sg(1, 32768), sg(2, 32768), sg(4, 32768)));  // -32768 each
    items.push_back(normal_item(sg(1, 9459), sg(2, 9459), sg(4, 9459)));
    items.push_back(normal_item(sg(1, 6000), sg(2, 10000), sg(4, 8000)));  // 3 4 5
    items.push_back(normal_item(sg(1, 5 * 1200), sg(2, 13 * 1200), sg(4, 12 * 1200)));
    items.push_back(normal_item(sg(1, 15 * 1900), sg(2, 17 * 1900), sg(4, 8 * 1900)));
    items.push_back(normal_item(sg(1, 3), sg(2, 5), sg(4, 4)));  // tiny triple
    items.push_back(normal_item(sg(1, 16384), sg(2, 16384), sg(4, 0)));
  }
  // The extremes mixed: -32768 and 32767 against each other and small values.
  for (const auto& [x, y, z] : {std::array<int16_t, 3>{-32768, 32767, 1},
                                {32767, -32768, -1},
                                {-32768, 1, 32767},
                                {1, -32768, -32768},
                                {32767, 32767, -32768},
                                {-32768, -32768, 32767}}) {
    items.push_back(normal_item(x, y, z));
  }
  // Every octant at a generic direction.
  for (int s = 0; s < 8; ++s) {
    items.push_back(normal_item(static_cast<int16_t>(s & 1 ? -5000 : 5000),
                                static_cast<int16_t>(s & 2 ? -9000 : 9000),
                                static_cast<int16_t>(s & 4 ? -12000 : 12000)));
  }
  // Every angle-table index some ratio reaches (phi and theta), every seed-table index.
  add_angle_index_items(*encoder_, items);
  add_seed_index_items(config().seed_bits, items);
  return items;
}

std::vector<Txn> NormalEncoderBlock::random_items(std::mt19937_64& rng, size_t count) const {
  std::vector<Txn> items;
  items.reserve(count);
  std::uniform_real_distribution<double> log_length(-14.0, 1.0);
  for (size_t i = 0; i < count; ++i) {
    const uint64_t kind = rng() % 20;
    if (kind < 10) {  // a unit normal, quantized
      items.push_back(scaled_item(random_direction(rng), 1.0));
    } else if (kind < 17) {  // any length 2^-14 .. 2, saturated to the port's range
      items.push_back(scaled_item(random_direction(rng), std::exp2(log_length(rng))));
    } else if (kind < 19) {  // raw 16-bit components
      const uint64_t r = rng();
      items.push_back(normal_item(static_cast<int16_t>(r), static_cast<int16_t>(r >> 16),
                                  static_cast<int16_t>(r >> 32)));
    } else {  // on an octant boundary: a unit normal with one or two components zeroed
      const Txn t = scaled_item(random_direction(rng), 1.0);
      const uint64_t r = rng();
      items.push_back(
          normal_item(r & 1 ? 0 : normal_x(t), r & 2 ? 0 : normal_y(t), r & 4 ? 0 : normal_z(t)));
    }
  }
  return items;
}

namespace {
constexpr const char* kEveryAnglePhi = "every reachable angle-table index (phi)";
constexpr const char* kEveryAngleTheta = "every reachable angle-table index (theta)";
constexpr const char* kEverySeedPhi = "every seed-table index (phi)";
constexpr const char* kEverySeedTheta = "every seed-table index (theta)";
constexpr std::array<const char*, 8> kOctants = {
    "octant +x +y +z", "octant -x +y +z", "octant +x -y +z", "octant -x -y +z",
    "octant +x +y -z", "octant -x +y -z", "octant +x -y -z", "octant -x -y -z"};
}  // namespace

std::vector<std::string> NormalEncoderBlock::coverage_cases() const {
  std::vector<std::string> cases = {"zero normal (0, 0, 0)",
                                    "tiny normal (every |component| < 16 LSB, not zero)",
                                    "pole +x",
                                    "pole -x",
                                    "pole +y",
                                    "pole -y",
                                    "pole +z",
                                    "pole -z",
                                    "octant boundary: x = 0 only",
                                    "octant boundary: y = 0 only",
                                    "octant boundary: z = 0 only",
                                    "|x| = |z| != 0 (equal squares, no swap)",
                                    "y^2 = x^2 + z^2 != 0 (equal squares, no swap)",
                                    "t >= 1 - 2^-14 (equal squares; the divider never reaches 1)",
                                    "component -32768",
                                    "component +32767",
                                    "phi swapped (x^2 > z^2)",
                                    "theta swapped (y^2 > x^2 + z^2)",
                                    "theta at a pole (k = Q) saturated to Q - 1",
                                    "phi 0 from -x (4Q - 0 wraps)",
                                    "t_phi on a table bucket's first value",
                                    "t_theta on a table bucket's first value",
                                    "short normal (length < 1/4)",
                                    "long normal (length > 1.5)"};
  cases.insert(cases.end(), kOctants.begin(), kOctants.end());
  cases.insert(cases.end(), {kEveryAnglePhi, kEveryAngleTheta, kEverySeedPhi, kEverySeedTheta});
  return cases;
}

void NormalEncoderBlock::cover(const std::vector<Txn>& items, size_t index, const Txn&,
                               Coverage& cov) const {
  if (index == 0 || index != cover_next_) {
    for (auto& s : seen_angle_) s.clear();
    for (auto& s : seen_seed_) s.clear();
  }
  cover_next_ = index + 1;
  const int16_t x = normal_x(items[index]), y = normal_y(items[index]), z = normal_z(items[index]);
  EncoderTrace t;
  encoder_->encode(x, y, z, &t);
  const EncoderConfig& c = config();
  const auto mag = [](int16_t v) { return static_cast<uint32_t>(std::abs(int32_t{v})); };
  const uint32_t a = mag(x), b = mag(y), cz = mag(z);
  const uint32_t xx = a * a, yy = b * b, zz = cz * cz, hh = xx + zz;
  const int zeros = (x == 0) + (y == 0) + (z == 0);

  if (zeros == 3) ++cov["zero normal (0, 0, 0)"];
  if (zeros < 3 && std::max({a, b, cz}) < 16)
    ++cov["tiny normal (every |component| < 16 LSB, not zero)"];
  if (zeros == 2) {
    if (x != 0) ++cov[x > 0 ? "pole +x" : "pole -x"];
    if (y != 0) ++cov[y > 0 ? "pole +y" : "pole -y"];
    if (z != 0) ++cov[z > 0 ? "pole +z" : "pole -z"];
  }
  if (zeros == 1) {
    if (x == 0) ++cov["octant boundary: x = 0 only"];
    if (y == 0) ++cov["octant boundary: y = 0 only"];
    if (z == 0) ++cov["octant boundary: z = 0 only"];
  }
  if (xx == zz && xx != 0) ++cov["|x| = |z| != 0 (equal squares, no swap)"];
  if (yy == hh && yy != 0) ++cov["y^2 = x^2 + z^2 != 0 (equal squares, no swap)"];
  if (std::max(t.t_phi, t.t_theta) >= kRatioOne - 4)
    ++cov["t >= 1 - 2^-14 (equal squares; the divider never reaches 1)"];
  if (x == -32768 || y == -32768 || z == -32768) ++cov["component -32768"];
  if (x == 32767 || y == 32767 || z == 32767) ++cov["component +32767"];
  if (t.swap_phi) ++cov["phi swapped (x^2 > z^2)"];
  if (t.swap_theta) ++cov["theta swapped (y^2 > x^2 + z^2)"];
  if (t.k_theta == c.grid.quarter()) ++cov["theta at a pole (k = Q) saturated to Q - 1"];
  if (t.sx && !t.sz && t.k_phi == 0) ++cov["phi 0 from -x (4Q - 0 wraps)"];
  // A divider one LSB low would read the previous bucket's entry.
  const auto first_of_bucket = [&c](uint32_t r) {
    return r > 1 && deflect::angle_index(c, r) != deflect::angle_index(c, r - 1);
  };
  if (first_of_bucket(t.t_phi)) ++cov["t_phi on a table bucket's first value"];
  if (first_of_bucket(t.t_theta)) ++cov["t_theta on a table bucket's first value"];
  const double len2 =
      (static_cast<double>(xx) + static_cast<double>(yy) + static_cast<double>(zz)) /
      (double{kOne} * kOne);
  if (zeros < 3 && len2 < 1.0 / 16) ++cov["short normal (length < 1/4)"];
  if (len2 > 1.5 * 1.5) ++cov["long normal (length > 1.5)"];
  ++cov[kOctants[size_t{t.sx} | size_t{t.sy} << 1 | size_t{t.sz} << 2]];

  // The table indices: a case counts once, when its last index is reached.
  const auto reach = [&cov](std::set<uint32_t>& seen, uint32_t i, size_t all, const char* name) {
    if (seen.insert(i).second && seen.size() == all) ++cov[name];
  };
  // (t = 0 reads no table entry.)
  if (t.t_phi != 0) {
    reach(seen_angle_[0], deflect::angle_index(c, t.t_phi), reachable_angle_->size(),
          kEveryAnglePhi);
  }
  if (t.t_theta != 0) {
    reach(seen_angle_[1], deflect::angle_index(c, t.t_theta), reachable_angle_->size(),
          kEveryAngleTheta);
  }
  const size_t seeds = size_t{1} << c.seed_bits;
  reach(seen_seed_[0], encoder_seed_index(std::max(xx, zz), c.seed_bits), seeds, kEverySeedPhi);
  reach(seen_seed_[1], encoder_seed_index(std::max(yy, hh), c.seed_bits), seeds, kEverySeedTheta);
}

}  // namespace tmu::tb

TMU_REGISTER_BLOCK(normal_encoder, NormalEncoderBlock)
