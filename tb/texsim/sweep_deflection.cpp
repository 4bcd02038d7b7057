#include "texsim/sweep_deflection.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <map>
#include <optional>
#include <sstream>

#include "common/error.hpp"
#include "common/image.hpp"
#include "deflect/bump_map.hpp"
#include "deflect/coord_tables.hpp"
#include "deflect/deflect_ideal.hpp"
#include "deflect/normal_encoder.hpp"
#include "deflect/s2s_map.hpp"
#include "deflect/view_maps.hpp"
#include "geometry/mesh.hpp"
#include "raster/rasterizer.hpp"
#include "render/effect_maps.hpp"
#include "render/pipeline.hpp"
#include "render/texture_source.hpp"
#include "scene/scene.hpp"
#include "texsim/sweep_support.hpp"

namespace tmu::texsim {
namespace {

using deflect::SphereAngle;
using deflect::SphereGrid;
using glm::dvec3;

struct DeflectionSetting {
  int phi_bits = 9, lut_exp = 4, lut_mant = 5, value_bits = 10;
  std::string name() const {
    return fmt::format("{},{},{},{}", phi_bits, lut_exp, lut_mant, value_bits);
  }
};

std::vector<DeflectionSetting> parse_deflection_settings(const std::string& text) {
  std::vector<DeflectionSetting> out;
  std::stringstream list(text);
  std::string item;
  while (std::getline(list, item, ';')) {
    DeflectionSetting s;
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
    for (const int d : {p.r - q.r, p.g - q.g, p.b - q.b}) se += double(d) * d;
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
  uint64_t hits = 0, misses = 0, bypasses = 0, pixels = 0, bumped = 0;
  uint64_t flat_hits = 0, flat_misses = 0;  // the same sphere without bumps
  double ns_per_pixel = 0;
};

// One pixel of the workload: its exact normal and, when bumped, the bump frame's slopes.
struct Sample {
  size_t pixel = 0;
  int group = 0;  // a new group starts a new deflection unit (render: one per material)
  dvec3 normal{0, 0, 1};
  std::optional<glm::dvec2> slope;
};

struct Workload {
  std::string name;
  int width = 0, height = 0;
  deflect::ViewFrame view;
  std::vector<Sample> samples;  // in the order the units see them
};

// The synthetic sphere: a bump-mapped sphere filling the view, in raster order.
Workload sphere_workload(int n) {
  Workload w{fmt::format("a bump-mapped sphere, {0} x {0} pixels", n), n, n, sweep_view(), {}};
  const deflect::ViewFrame& v = w.view;
  const dvec3 side(v.side[0], v.side[1], v.side[2]), up(v.up[0], v.up[1], v.up[2]),
      dir(v.dir[0], v.dir[1], v.dir[2]);
  for (int y = 0; y < n; ++y) {
    for (int x = 0; x < n; ++x) {
      const double a = (2.0 * x + 1) / n - 1, b = 1 - (2.0 * y + 1) / n;
      if (a * a + b * b >= 0.98) continue;
      const dvec3 normal = a * side + b * up + std::sqrt(1 - a * a - b * b) * dir;
      const deflect::ideal::Angles na = deflect::ideal::to_angles(normal);
      w.samples.push_back({size_t(y) * n + x, 0, normal, bump_slopes(na.phi, na.theta)});
    }
  }
  return w;
}

// A texel index of a nearest sample under a border mode (border: the clamp's texel).
int border_texel(int i, int size, texram::Border mode) {
  if (mode == texram::Border::kWrap) return ((i % size) + size) % size;
  if (mode == texram::Border::kMirror) {
    const int m = ((i % (2 * size)) + 2 * size) % (2 * size);
    return m < size ? m : 2 * size - 1 - m;
  }
  return std::clamp(i, 0, size - 1);
}

// A scene's fragments of the materials with a deflection chain, material by material in frame
// order (as the renderer feeds its units), with the bump texel a nearest sample reads.
Workload scene_workload(const std::string& path) {
  const host::Scene scene = host::load_scene(path);
  Workload w{
      path, scene.camera.width, scene.camera.height, render::camera_view_frame(scene.camera), {}};
  std::vector<glm::ivec2> sizes;
  {
    const render::Pipeline pipe(scene, render::Level::kGolden);
    sizes = pipe.texture_sizes();
  }
  std::vector<host::Mesh> meshes;
  for (const host::Object& obj : scene.objects) meshes.push_back(host::make_mesh(obj));
  const std::vector<host::Fragment> fragments = host::rasterize(scene, meshes, sizes);
  for (size_t m = 0; m < scene.materials.size(); ++m) {
    const host::Material& mat = scene.materials[m];
    if (!mat.uses_normal()) continue;
    const ImageRgb8 heights = mat.bump ? render::source_image(mat.bump->heights) : ImageRgb8();
    for (const host::Fragment& f : fragments) {
      if (f.material != static_cast<int>(m)) continue;
      Sample s{size_t(f.y) * size_t(w.width) + size_t(f.x), static_cast<int>(m),
               glm::normalize(f.normal), std::nullopt};
      if (mat.bump) {
        const host::FragmentRecord r = host::quantize(f);
        const int x = border_texel(r.u >> 8, heights.width, mat.sampler.border_u);
        const int y = border_texel(r.v >> 8, heights.height, mat.sampler.border_v);
        s.slope = deflect::bump_slope(heights, x, y, mat.bump->depth);
      }
      w.samples.push_back(s);
    }
  }
  if (w.samples.empty()) {
    throw InputError(path, "materials",
                     "no visible material has a bump, shading maps or an environment");
  }
  return w;
}

SettingResult run_setting(const DeflectionSetting& s, const Workload& work,
                          const DeflectionSweepArgs& args) {
  deflect::EncoderConfig ec;
  ec.grid.phi_bits = s.phi_bits;
  ec.lut_exp = s.lut_exp;
  ec.lut_mant = s.lut_mant;
  const deflect::NormalEncoder encoder(ec);
  const deflect::S2sMap map(ec.grid);
  std::optional<deflect::DeflectionUnit> unit, flat_unit;
  const deflect::ViewFrame& view = work.view;
  const deflect::CoordTables tables(deflect::TableConfig{ec.grid, s.value_bits}, view);
  const dvec3 side(view.side[0], view.side[1], view.side[2]),
      up(view.up[0], view.up[1], view.up[2]), dir(view.dir[0], view.dir[1], view.dir[2]);

  ImageRgb8 gd(work.width, work.height), id = gd, gr = gd, ir = gd;
  std::vector<bool> mask(gd.pixels.size(), false);
  SettingResult r;
  double golden_seconds = 0;
  int group = -1;
  for (const Sample& sample : work.samples) {
    if (sample.group != group) {  // a new material: its own deflection unit, an empty MBR
      unit.emplace(map);
      flat_unit.emplace(map);
      group = sample.group;
    }
    const dvec3& normal = sample.normal;
    const deflect::ideal::Angles na = deflect::ideal::to_angles(normal);
    const glm::dvec2 slope = sample.slope.value_or(glm::dvec2(0));
    const deflect::ideal::Angles ba = deflect::ideal::bump_angles(dvec3(-slope.x, -slope.y, 1));
    const dvec3 exact = sample.slope ? deflect::ideal::deflect(na, ba) : normal;
    const deflect::ideal::Coords xc = deflect::ideal::map_coords(view, exact);

    const auto t0 = std::chrono::steady_clock::now();
    const auto q = [](double v) { return static_cast<int16_t>(std::lround(v * 16384)); };
    const SphereAngle nq = encoder.encode(q(normal.x), q(normal.y), q(normal.z));
    std::optional<deflect::Deflected> d;
    if (sample.slope) d = unit->deflect(nq, deflect::bump_texel(ec.grid, slope.x, slope.y));
    const SphereAngle deflected = d ? d->normal : nq;
    const deflect::MapCoords gc = tables.eval(deflected);
    golden_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

    ++r.pixels;
    if (d) {  // the deflection unit works for bumped pixels only
      ++r.bumped;
      const deflect::MapAccess flat = flat_unit->deflect(nq, SphereAngle{0, 0}).access;
      r.flat_hits += flat == deflect::MapAccess::kHit;
      r.flat_misses += flat == deflect::MapAccess::kMiss;
      r.hits += d->access == deflect::MapAccess::kHit;
      r.misses += d->access == deflect::MapAccess::kMiss;
      r.bypasses += d->access == deflect::MapAccess::kBypass;
    }
    const dvec3 golden_n = deflect::ideal::grid_vector(ec.grid, deflected);
    r.normal.add(deflect::ideal::angle_deg(golden_n, exact));
    const dvec3 golden_r_view = dvec3(gc.ur, gc.vr, gc.wr) / 16384.0;
    r.reflection.add(deflect::ideal::angle_deg(golden_r_view, dvec3(xc.ur, xc.vr, xc.wr)));

    const size_t i = sample.pixel;
    mask[i] = true;
    gd.pixels[i] = diffuse(golden_n);
    id.pixels[i] = diffuse(exact);
    const auto to_object = [&](const dvec3& v) { return v.x * side + v.y * up + v.z * dir; };
    gr.pixels[i] = deflect::sky_room(to_object(golden_r_view));
    ir.pixels[i] = deflect::sky_room(to_object(dvec3(xc.ur, xc.vr, xc.wr)));
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

// The three units' hardware at a setting against golden (sweep_support.hpp: check_rtl), on
// each block's own stimulus: the encoder's ports carry the grid A = 9 only, the deflection
// unit's block holds the A = 9 map; Verilator at the variants rtl/blocks.cmake builds, Icarus
// at the encoder's and the coordinate generator's other widths.
struct UnitChecks {
  RtlCheck encoder, deflect, coord;
  std::string text() const {
    return fmt::format("enc {}; defl {}; coord {}", encoder.verdict(), deflect.verdict(),
                       coord.verdict());
  }
};

constexpr size_t kUnitItems = 20000;

// Settings share units (every A = 9 setting the deflection unit): each unit at each of its
// parameters runs once, `done` keeping the checks by unit and parameters.
UnitChecks check_units(const DeflectionSetting& s, std::map<std::string, RtlCheck>& done) {
  const auto once = [&done](const std::string& key, const std::string& block,
                            const tb::BlockOptions& o) {
    auto it = done.find(key);
    if (it == done.end()) it = done.emplace(key, check_rtl(block, o, kUnitItems)).first;
    return it->second;
  };
  UnitChecks c;
  tb::BlockOptions enc;
  enc.encoder.grid.phi_bits = s.phi_bits;
  enc.encoder.lut_exp = s.lut_exp;
  enc.encoder.lut_mant = s.lut_mant;
  c.encoder =
      once(fmt::format("enc {},{},{}", s.phi_bits, s.lut_exp, s.lut_mant), "normal_encoder", enc);
  if (s.phi_bits == deflect::SphereGrid{}.phi_bits) c.deflect = once("defl", "deflect", {});
  tb::BlockOptions coord;
  coord.coord_tables.grid.phi_bits = s.phi_bits;
  coord.coord_tables.value_bits = s.value_bits;
  c.coord = once(fmt::format("coord {},{}", s.phi_bits, s.value_bits), "coord_gen", coord);
  return c;
}

}  // namespace

void sweep_deflection(const DeflectionSweepArgs& args) {
  const std::vector<DeflectionSetting> settings = parse_deflection_settings(args.settings);
  // The errors, hit rates and speed are the golden units'; the cycles a formula on golden's
  // misses (one per bumped pixel plus the map memory's latency per miss), not a timed run.
  SweepTable table({"A,E,M,W",
                    "grid",
                    {"N max deg", Mark::kModel},
                    {"N mean deg", Mark::kModel},
                    {"R max deg", Mark::kModel},
                    {"R mean deg", Mark::kModel},
                    {"diffuse dB", Mark::kModel},
                    {"reflect dB", Mark::kModel},
                    {"table bits", Mark::kFormula},
                    {"hit rate", Mark::kModel},
                    {"cyc/px", Mark::kFormula},
                    {"hit rate flat", Mark::kModel},
                    {"golden ns/px", Mark::kModel},
                    {"rtl = golden", Mark::kSim},
                    {"enc cells", Mark::kSynth},
                    {"defl cells", Mark::kSynth},
                    {"coord cells", Mark::kSynth}});
  const Workload work =
      args.scene.empty() ? sphere_workload(args.size) : scene_workload(args.scene);
  fmt::print("workload: {} ({} pixels through the chain)\n", work.name, work.samples.size());
  std::map<std::string, RtlCheck> unit_checks;
  for (const DeflectionSetting& s : settings) {
    const SettingResult r = run_setting(s, work, args);
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
    const UnitChecks checks = in_rtl ? check_units(s, unit_checks) : UnitChecks{};
    const auto synth = [&](const std::string& top, std::vector<std::pair<std::string, int>> p,
                           const RtlCheck& check) {
      if (!args.synth) return Cell("-");
      return in_rtl ? synth_cell(synthesize(top, p).cells, check.simulated()) : Cell("n/a");
    };
    table.add(
        {s.name(), fmt::format("{}x{}", g.phi_count(), g.phi_count() / 2),
         fmt::format("{:.3f}", r.normal.max), fmt::format("{:.3f}", r.normal.mean()),
         fmt::format("{:.3f}", r.reflection.max), fmt::format("{:.3f}", r.reflection.mean()),
         fmt::format("{:.2f}", r.psnr_diffuse), fmt::format("{:.2f}", r.psnr_reflect),
         fmt::format("{}", bits),
         fmt::format("{:.3f}", lookups ? double(r.hits) / double(lookups) : 1.0),
         fmt::format("{:.3f}", 1.0 + double(r.misses * static_cast<uint64_t>(args.miss_cycles)) /
                                         double(std::max<uint64_t>(1, r.bumped))),
         fmt::format("{:.3f}", double(r.flat_hits) /
                                   double(std::max<uint64_t>(1, r.flat_hits + r.flat_misses))),
         fmt::format("{:.0f}", r.ns_per_pixel), in_rtl ? checks.text() : "n/a",
         synth("tmu_normal_encoder",
               {{"PhiBits", s.phi_bits}, {"LutExp", s.lut_exp}, {"LutMant", s.lut_mant}},
               checks.encoder),
         synth("tmu_deflect", {{"PhiBits", s.phi_bits}}, checks.deflect),
         synth("tmu_coord_gen", {{"PhiBits", s.phi_bits}, {"ValueBits", s.value_bits}},
               checks.coord)});
    fmt::print("{}\n", table.last_row_text());
  }
  table.print(args.markdown);
}

}  // namespace tmu::texsim
