#include "texsim/sweep_deflection.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <numbers>
#include <sstream>

#include "common/error.hpp"
#include "common/image.hpp"
#include "deflect/bump_map.hpp"
#include "deflect/coord_tables.hpp"
#include "deflect/deflect_ideal.hpp"
#include "deflect/normal_encoder.hpp"
#include "deflect/s2s_map.hpp"
#include "texsim/sweep_support.hpp"

namespace tmu::texsim {
namespace {

using deflect::SphereAngle;
using deflect::SphereGrid;
using glm::dvec3;

struct Setting {
  int phi_bits = 9, lut_exp = 4, lut_mant = 5, value_bits = 10;
  std::string name() const {
    return fmt::format("{},{},{},{}", phi_bits, lut_exp, lut_mant, value_bits);
  }
};

std::vector<Setting> parse_settings(const std::string& text) {
  std::vector<Setting> out;
  std::stringstream list(text);
  std::string item;
  while (std::getline(list, item, ';')) {
    Setting s;
    char c1 = 0, c2 = 0, c3 = 0;
    std::stringstream one(item);
    if (!(one >> s.phi_bits >> c1 >> s.lut_exp >> c2 >> s.lut_mant >> c3 >> s.value_bits) ||
        c1 != ',' || c2 != ',' || c3 != ',' || !(one >> std::ws).eof()) {
      throw InputError("--settings", item, "expected A,E,M,W (four integers)");
    }
    if (s.phi_bits < 6 || s.phi_bits > 11) throw InputError("--settings", item, "A must be 6..11");
    if (s.lut_exp < 1 || s.lut_exp > 8) throw InputError("--settings", item, "E must be 1..8");
    if (s.lut_mant < 2 || s.lut_mant > 10) throw InputError("--settings", item, "M must be 2..10");
    if (s.value_bits < 8 || s.value_bits > 16)
      throw InputError("--settings", item, "W must be 8..16");
    out.push_back(s);
  }
  if (out.empty()) throw InputError("--settings", "", "no setting given");
  return out;
}

// The view (object space; v_dir = v_side x v_up towards the viewer), the light and the sun.
deflect::ViewFrame sweep_view() {
  const dvec3 dir = glm::normalize(dvec3(0.3, 0.35, 1.0));
  const dvec3 side = glm::normalize(glm::cross(dvec3(0, 1, 0), dir));
  const dvec3 up = glm::cross(dir, side);
  return {{side.x, side.y, side.z}, {up.x, up.y, up.z}, {dir.x, dir.y, dir.z}};
}
const dvec3 kLight = glm::normalize(dvec3(-0.4, 0.7, 0.6));

// The height field on the sphere, h = a cos^2(theta) sin(12 phi) sin(12 theta) (cos^2 fades
// it out at the poles), as the bump frame's slopes (dh/du, dh/dv) per unit arc length.
glm::dvec2 bump_slopes(double phi, double theta) {
  constexpr double a = 0.04, f = 12;
  const double c = std::cos(theta), s = std::sin(theta);
  const double du = a * c * f * std::cos(f * phi) * std::sin(f * theta);
  const double dv = a * (-2 * c * s * std::sin(f * phi) * std::sin(f * theta) +
                         c * c * std::sin(f * phi) * f * std::cos(f * theta));
  return {du, dv};
}

// What the reflection picture looks up: a sky brightening towards the zenith, a checkered
// ground below the horizon (sharp edges show direction errors) and a sun.
Rgb8 environment(const dvec3& r_object) {
  const dvec3 r = glm::normalize(r_object);
  if (glm::dot(r, glm::normalize(dvec3(0.5, 0.6, 0.4))) > 0.995) return {255, 240, 200};
  if (r.y >= 0) {
    const auto b = static_cast<uint8_t>(150 + 100 * r.y);
    return {static_cast<uint8_t>(90 + 60 * r.y), static_cast<uint8_t>(130 + 80 * r.y), b};
  }
  const double az = std::atan2(r.x, r.z) / std::numbers::pi * 8,
               el = std::asin(-r.y) / std::numbers::pi * 16;
  const bool dark = (static_cast<int>(std::floor(az)) + static_cast<int>(std::floor(el))) & 1;
  return dark ? Rgb8{60, 50, 40} : Rgb8{200, 180, 140};
}

Rgb8 diffuse(const dvec3& n) {
  const auto v = static_cast<uint8_t>(
      std::lround(25 + 230 * std::max(0.0, glm::dot(glm::normalize(n), kLight))));
  return {v, v, v};
}

double psnr(const ImageRgb8& a, const ImageRgb8& b, const std::vector<bool>& mask) {
  double se = 0;
  size_t n = 0;
  for (size_t i = 0; i < a.pixels.size(); ++i) {
    if (!mask[i]) continue;
    const Rgb8 p = a.pixels[i], q = b.pixels[i];
    for (const double d : {double{p.r} - q.r, double{p.g} - q.g, double{p.b} - q.b}) se += d * d;
    n += 3;
  }
  return se == 0 ? 99.0 : 10 * std::log10(255.0 * 255.0 * static_cast<double>(n) / se);
}

struct Stats {
  double max = 0, sum = 0;
  size_t n = 0;
  void add(double e) {
    max = std::max(max, e);
    sum += e;
    ++n;
  }
  double mean() const { return n ? sum / static_cast<double>(n) : 0; }
};

struct SettingResult {
  Stats normal, reflection;
  double psnr_diffuse = 0, psnr_reflect = 0;
  uint64_t hits = 0, misses = 0, bypasses = 0, pixels = 0;
  uint64_t flat_hits = 0, flat_misses = 0;  // the same sphere without bumps
  double ns_per_pixel = 0;
};

SettingResult run_setting(const Setting& s, const DeflectionSweepArgs& args) {
  deflect::EncoderConfig ec;
  ec.grid.phi_bits = s.phi_bits;
  ec.lut_exp = s.lut_exp;
  ec.lut_mant = s.lut_mant;
  const deflect::NormalEncoder encoder(ec);
  const deflect::S2sMap map(ec.grid);
  deflect::DeflectionUnit unit(map), flat_unit(map);
  const deflect::ViewFrame view = sweep_view();
  const deflect::CoordTables tables(deflect::TableConfig{ec.grid, s.value_bits}, view);
  const dvec3 side(view.side[0], view.side[1], view.side[2]),
      up(view.up[0], view.up[1], view.up[2]), dir(view.dir[0], view.dir[1], view.dir[2]);

  const int n = args.size;
  ImageRgb8 gd(n, n), id(n, n), gr(n, n), ir(n, n);
  std::vector<bool> mask(size_t(n) * n, false);
  SettingResult r;
  double golden_seconds = 0;
  for (int y = 0; y < n; ++y) {
    for (int x = 0; x < n; ++x) {
      const double a = (2.0 * x + 1) / n - 1, b = 1 - (2.0 * y + 1) / n;
      if (a * a + b * b >= 0.98) continue;
      const dvec3 normal = a * side + b * up + std::sqrt(1 - a * a - b * b) * dir;
      const deflect::ideal::Angles na = deflect::ideal::to_angles(normal);
      const glm::dvec2 slope = bump_slopes(na.phi, na.theta);
      const deflect::ideal::Angles ba = deflect::ideal::bump_angles(dvec3(-slope.x, -slope.y, 1));
      const dvec3 exact = deflect::ideal::deflect(na, ba);
      const deflect::ideal::Coords xc = deflect::ideal::map_coords(view, exact);

      const auto t0 = std::chrono::steady_clock::now();
      const auto q = [](double v) { return static_cast<int16_t>(std::lround(v * 16384)); };
      const SphereAngle nq = encoder.encode(q(normal.x), q(normal.y), q(normal.z));
      const deflect::Deflected d = unit.deflect(nq, deflect::bump_texel(ec.grid, slope.x, slope.y));
      const deflect::MapCoords gc = tables.eval(d.normal);
      golden_seconds +=
          std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

      const deflect::MapAccess flat = flat_unit.deflect(nq, SphereAngle{0, 0}).access;
      r.flat_hits += flat == deflect::MapAccess::kHit;
      r.flat_misses += flat == deflect::MapAccess::kMiss;
      ++r.pixels;
      r.hits += d.access == deflect::MapAccess::kHit;
      r.misses += d.access == deflect::MapAccess::kMiss;
      r.bypasses += d.access == deflect::MapAccess::kBypass;
      const dvec3 golden_n = deflect::ideal::grid_vector(ec.grid, d.normal);
      r.normal.add(deflect::ideal::angle_deg(golden_n, exact));
      const dvec3 golden_r_view = dvec3(gc.ur, gc.vr, gc.wr) / 16384.0;
      r.reflection.add(deflect::ideal::angle_deg(golden_r_view, dvec3(xc.ur, xc.vr, xc.wr)));

      const size_t i = size_t(y) * n + x;
      mask[i] = true;
      gd.pixels[i] = diffuse(golden_n);
      id.pixels[i] = diffuse(exact);
      const auto to_object = [&](const dvec3& v) { return v.x * side + v.y * up + v.z * dir; };
      gr.pixels[i] = environment(to_object(golden_r_view));
      ir.pixels[i] = environment(to_object(dvec3(xc.ur, xc.vr, xc.wr)));
    }
  }
  r.psnr_diffuse = psnr(gd, id, mask);
  r.psnr_reflect = psnr(gr, ir, mask);
  r.ns_per_pixel = golden_seconds / static_cast<double>(r.pixels) * 1e9;
  if (!args.out_dir.empty()) {
    std::filesystem::create_directories(args.out_dir);
    const std::string stem = fmt::format("{}/deflection_a{}e{}m{}w{}", args.out_dir, s.phi_bits,
                                         s.lut_exp, s.lut_mant, s.value_bits);
    write_image(stem + "_diffuse.png", gd);
    write_image(stem + "_reflect.png", gr);
    write_image(args.out_dir + "/deflection_ideal_diffuse.png", id);
    write_image(args.out_dir + "/deflection_ideal_reflect.png", ir);
  }
  return r;
}

}  // namespace

void sweep_deflection(const DeflectionSweepArgs& args) {
  const std::vector<Setting> settings = parse_settings(args.settings);
  SweepTable table({"A,E,M,W", "grid", "N max deg", "N mean deg", "R max deg", "R mean deg",
                    "diffuse dB", "reflect dB", "table bits", "hit rate", "cyc/px", "hit rate flat",
                    "golden ns/px", "enc cells", "defl cells", "coord cells"});
  for (const Setting& s : settings) {
    const SettingResult r = run_setting(s, args);
    const SphereGrid g{s.phi_bits};
    const uint64_t q = g.quarter();
    // Angle table (entries of A-2 bits), seed table (2^7 x 16), the first-octant map,
    // the seven coordinate tables (3 x 2Q + 4 x Q entries of W bits).
    const uint64_t bits =
        (uint64_t{static_cast<uint64_t>(s.lut_exp)} << s.lut_mant) * (s.phi_bits - 2) + 128 * 16 +
        q * q * (2 * s.phi_bits - 3) + 10 * q * s.value_bits;
    const uint64_t lookups = r.hits + r.misses;
    // The RTL's ports are the package formats: the 512 x 256 grid at most, W <= 10.
    const bool in_rtl = s.phi_bits <= 9 && s.value_bits <= 10;
    const auto synth = [&](const std::string& top, std::vector<std::pair<std::string, int>> p) {
      if (!args.synth) return std::string("-");
      return in_rtl ? synthesize(top, p).cells : std::string("n/a");
    };
    table.add(
        {s.name(), fmt::format("{}x{}", g.phi_count(), g.phi_count() / 2),
         fmt::format("{:.3f}", r.normal.max), fmt::format("{:.3f}", r.normal.mean()),
         fmt::format("{:.3f}", r.reflection.max), fmt::format("{:.3f}", r.reflection.mean()),
         fmt::format("{:.2f}", r.psnr_diffuse), fmt::format("{:.2f}", r.psnr_reflect),
         fmt::format("{}", bits),
         fmt::format("{:.3f}", lookups ? double(r.hits) / double(lookups) : 1.0),
         fmt::format("{:.3f}", 1.0 + double(r.misses * static_cast<uint64_t>(args.miss_cycles)) /
                                         double(r.pixels)),
         fmt::format("{:.3f}", double(r.flat_hits) /
                                   double(std::max<uint64_t>(1, r.flat_hits + r.flat_misses))),
         fmt::format("{:.0f}", r.ns_per_pixel),
         synth("tmu_normal_encoder",
               {{"PhiBits", s.phi_bits}, {"LutExp", s.lut_exp}, {"LutMant", s.lut_mant}}),
         synth("tmu_deflect", {{"PhiBits", s.phi_bits}}),
         synth("tmu_coord_gen", {{"PhiBits", s.phi_bits}, {"ValueBits", s.value_bits}})});
    fmt::print("{}\n", table.last_row_text());
  }
  table.print(args.markdown);
}

}  // namespace tmu::texsim
