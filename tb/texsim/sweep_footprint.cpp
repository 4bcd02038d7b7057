// `texsim sweep footprint`: footprint assembly against isotropic trilinear, the ideal
// footprint unit and OpenImageIO's anisotropic filter, on the same fragments of a scene seen
// at grazing angles, each measured against a supersampled reference.
//
// The reference (the pixel's box filter, made as exact as the texture allows): the scene is
// rasterized again at k x k times the resolution; every sub-pixel of the same material as the
// pixel's fragment contributes footprint::supersampled() of its own exact footprint (its
// parallelogram box-filtered by a grid of samples that each cover at most one level-0 texel,
// up to 64 x 64), and the pixel is their mean. The k x k grid follows the perspective inside
// the pixel (a pixel's footprint is a parallelogram only to first order); the per-sub-pixel
// footprint keeps the reference sharp at any anisotropy (isotropic trilinear sub-samples would
// blur by the ratio over k). k = 1 is per-pixel supersampled(). Only the texture's filter is
// measured: sub-pixels of another material or of the background are left out (coverage
// anti-aliasing is not the texture unit's business), and the statistics run over the interior
// pixels, those whose every sub-pixel sees the pixel's material.
#include "texsim/sweep_footprint.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <limits>
#include <optional>
#include <sstream>
#include <thread>

#include "blocks/trilinear/texram_memory.hpp"
#include "common/error.hpp"
#include "common/image.hpp"
#include "common/test_patterns.hpp"
#include "footprint/footprint.hpp"
#include "footprint/footprint_ideal.hpp"
#include "geometry/mesh.hpp"
#include "raster/rasterizer.hpp"
#include "render/pipeline.hpp"
#include "scene/scene.hpp"
#include "texram/oiio_sampler.hpp"
#include "texram/trilinear.hpp"
#include "texsim/ideal_rgba.hpp"
#include "texsim/sweep_support.hpp"

namespace tmu::texsim {
namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

constexpr int kMaxProbeLog2 = 4;  // N max 16 for the ideal and OIIO variants
// PSNR columns by elongation (the ratio of the footprint ellipse's axes): [4, 16), where N max 16
// can match the ratio, and [16, inf), where every variant is clamped.
constexpr double kAnisoLow = 4.0, kAnisoHigh = 16.0;
constexpr double kErrorFullScale = 64.0;  // error maps: white at this many 8-bit levels

// The scene's fragments and the textures they read.
struct Frame {
  host::Scene scene;
  std::vector<render::MaterialTexture> textures;
  std::vector<texram::IdealTexture> ideal;  // per material: the ideal model's levels
  std::vector<host::Mesh> meshes;
  std::vector<host::Fragment> fragments;
  std::vector<host::FragmentRecord> records;
  std::vector<int> fragment_at;  // per pixel: its fragment, or -1

  const texram::TexramTexture& texture(size_t i) const {
    return *textures[static_cast<size_t>(fragments[i].material)].texram;
  }
  const texram::IdealTexture& ideal_texture(size_t i) const {
    return ideal[static_cast<size_t>(fragments[i].material)];
  }
  const texram::SamplerConfig& sampler(size_t i) const {
    return scene.materials[static_cast<size_t>(fragments[i].material)].sampler;
  }
};

enum class Kind { kTrilinear, kFootprint, kIdeal, kOiio };

struct Variant {
  std::string name;  // the table's row and the picture's label
  std::string file;  // file stem
  Kind kind;
  int log2_max = kMaxProbeLog2;
  footprint::Direction direction = footprint::Direction::kLongerSide;
  footprint::QRule q_rule = footprint::QRule::kHeights;  // golden footprint variants
};

struct Outcome {
  std::vector<uint32_t> rgba;      // per fragment, RGBA8888 (ideal and OIIO rounded to 8 bits)
  std::optional<double> probes;    // trilinear probes per textured pixel
  std::optional<uint64_t> cycles;  // page-model periods (golden only)
  double seconds = 0;              // the sampling loop, one core
};

// The best of a few runs of `loop` (seconds): the machine is shared, the loops are short.
constexpr int kTimingRuns = 3;
template <class Loop>
double best_time(const Loop& loop) {
  double best = INFINITY;
  for (int run = 0; run < kTimingRuns; ++run) {
    const auto t = Clock::now();
    loop();
    best = std::min(best, since(t));
  }
  return best;
}

footprint::Request footprint_request(const host::FragmentRecord& r) {
  return {r.u, r.v, r.r1[0], r.r1[1], r.r2[0], r.r2[1], r.shade};
}

// One page model per material, as the renderer has one unit per material; its prediction is
// the renderer's for golden: one period per access, a second when a bank faults.
struct PageLogs {
  explicit PageLogs(size_t materials) : pages(materials) {}
  void add(int material, const texram::SamplePlan& plan) {
    for (const tb::BankAccess& a : tb::sample_accesses(plan)) {
      pages[static_cast<size_t>(material)].access(a.cells);
    }
  }
  uint64_t cycles() const {
    uint64_t total = 0;
    for (const texram::PageModel& p : pages) total += p.stats().accesses + p.stats().slow_accesses;
    return total;
  }
  std::vector<texram::PageModel> pages;
};

Outcome run_trilinear(const Frame& f) {
  Outcome o;
  o.rgba.resize(f.records.size());
  o.seconds = best_time([&] {
    for (size_t i = 0; i < f.records.size(); ++i) {
      const host::FragmentRecord& r = f.records[i];
      o.rgba[i] = texram::sample(f.texture(i), f.sampler(i), {r.u, r.v, r.lambda, r.shade});
    }
  });
  PageLogs logs(f.scene.materials.size());  // again with the plans, outside the timing
  for (size_t i = 0; i < f.records.size(); ++i) {
    const host::FragmentRecord& r = f.records[i];
    texram::SamplePlan plan;
    texram::sample(f.texture(i), f.sampler(i), {r.u, r.v, r.lambda, r.shade}, &plan);
    logs.add(r.material, plan);
  }
  o.probes = 1.0;
  o.cycles = logs.cycles();
  return o;
}

Outcome run_footprint(const Frame& f, int log2_max, footprint::QRule q_rule) {
  footprint::Config config;
  config.log2_max_probes = log2_max;
  config.q_rule = q_rule;
  Outcome o;
  o.rgba.resize(f.records.size());
  o.seconds = best_time([&] {
    for (size_t i = 0; i < f.records.size(); ++i) {
      o.rgba[i] =
          footprint::sample(f.texture(i), f.sampler(i), config, footprint_request(f.records[i]));
    }
  });
  PageLogs logs(f.scene.materials.size());
  uint64_t probes = 0;
  std::vector<texram::SamplePlan> plans;
  for (size_t i = 0; i < f.records.size(); ++i) {
    plans.clear();
    footprint::sample(f.texture(i), f.sampler(i), config, footprint_request(f.records[i]), &plans);
    probes += plans.size();
    for (const texram::SamplePlan& p : plans) logs.add(f.records[i].material, p);
  }
  o.probes = static_cast<double>(probes) / static_cast<double>(f.records.size());
  o.cycles = logs.cycles();
  return o;
}

Outcome run_ideal(const Frame& f, footprint::Direction direction) {
  footprint::IdealConfig config;
  config.log2_max_probes = kMaxProbeLog2;
  config.direction = direction;
  Outcome o;
  o.rgba.resize(f.records.size());
  o.seconds = best_time([&] {
    for (size_t i = 0; i < f.records.size(); ++i) {
      const host::Fragment& g = f.fragments[i];
      o.rgba[i] = round_rgba(footprint::ideal_sample(f.ideal_texture(i), f.sampler(i), config, g.uv,
                                                     g.r1, g.r2, f.records[i].shade));
    }
  });
  uint64_t probes = 0;
  for (const host::Fragment& g : f.fragments) {
    probes += uint64_t{1} << footprint::ideal_plan(g.r1, g.r2, config).log2_n;
  }
  o.probes = static_cast<double>(probes) / static_cast<double>(f.records.size());
  return o;
}

// OIIO's own count: "Average anisotropic probes : X" of its statistics text.
std::optional<double> oiio_average_probes(texram::OiioAnisoSampler& ts) {
  std::istringstream stats(ts.statistics());
  const std::string key = "Average anisotropic probes :";
  for (std::string line; std::getline(stats, line);) {
    const size_t at = line.find(key);
    if (at == std::string::npos) continue;
    try {
      return std::stod(line.substr(at + key.size()));
    } catch (const std::exception&) {
      return std::nullopt;
    }
  }
  return std::nullopt;
}

// OpenImageIO's TextureSystem: each material's level 0 made into a MIP-mapped texture by
// make_texture, anisotropic (at most 16 probes), bilinear within a level, the material's wrap
// modes; derivatives in OIIO's normalized s, t units; eq. 5 applied in double like the ideal.
Outcome run_oiio(const Frame& f, const std::filesystem::path& dir, double* make_seconds) {
  auto t = Clock::now();
  std::vector<std::string> files;
  for (size_t m = 0; m < f.scene.materials.size(); ++m) {
    files.push_back((dir / fmt::format("material{}.exr", m)).string());
    texram::make_oiio_texture(files.back(), *f.textures[m].texram, f.scene.materials[m].sampler);
  }
  *make_seconds = since(t);
  std::vector<texram::OiioTextureFile> textures;
  for (size_t m = 0; m < files.size(); ++m) {
    const texram::SamplerConfig& s = f.scene.materials[m].sampler;
    textures.push_back({files[m], s.border_u, s.border_v});
  }
  const auto ts = texram::make_oiio_aniso_sampler(textures, 1 << kMaxProbeLog2);
  Outcome o;
  o.rgba.resize(f.records.size());
  o.seconds = best_time([&] {
    for (size_t i = 0; i < f.records.size(); ++i) {
      const host::Fragment& g = f.fragments[i];
      const auto m = static_cast<size_t>(g.material);
      const double w = f.textures[m].size.x, h = f.textures[m].size.y;
      float got[4] = {0, 0, 0, 0};
      if (!ts->lookup(m, static_cast<float>(g.uv.x / w), static_cast<float>(g.uv.y / h),
                      static_cast<float>(g.r1.x / w), static_cast<float>(g.r1.y / h),
                      static_cast<float>(g.r2.x / w), static_cast<float>(g.r2.y / h), got)) {
        throw InputError(files[m], "", "OpenImageIO texture lookup failed: " + ts->error());
      }
      const texram::SamplerConfig& s = f.sampler(i);
      std::array<double, 4> c{};
      for (size_t ch = 0; ch < 4; ++ch) {
        c[ch] = 255.0 * got[ch];
        if (s.combine != texram::Combine::kOne) {
          const uint32_t by =
              s.combine == texram::Combine::kConstant ? s.constant_rgba : f.records[i].shade;
          c[ch] *= texram::channel(by, static_cast<int>(ch)) / 255.0;
        }
      }
      o.rgba[i] = round_rgba(c);
    }
  });
  o.probes = oiio_average_probes(*ts);
  return o;
}

// The reference colour of every fragment (module comment). A fragment whose sub-pixels are not
// all of its material is an edge pixel: there the error is coverage, not filtering, and the
// statistics leave it out; one with none of them (a sliver) takes supersampled() of its own
// footprint.
struct Reference {
  std::vector<glm::dvec4> rgba;
  std::vector<bool> interior;
  uint64_t sub_pixels = 0;  // sub-pixel footprints filtered
  uint64_t edge = 0;        // fragments that are not interior
};

Reference reference(const Frame& f, int k) {
  host::Scene hi = f.scene;
  hi.camera.width *= k;
  hi.camera.height *= k;
  const int width = f.scene.camera.width, height = f.scene.camera.height;
  std::vector<glm::ivec2> sizes;
  for (const render::MaterialTexture& t : f.textures) sizes.push_back(t.size);
  Reference ref;
  ref.rgba.assign(f.records.size(), glm::dvec4(0));
  std::vector<uint32_t> count(f.records.size(), 0);
  // Output rows interleaved over the cores; each row's fragments belong to one worker.
  const int workers = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  std::vector<uint64_t> taken(static_cast<size_t>(workers), 0);
  const auto work = [&](int id) {
    for (int y = id; y < height; y += workers) {
      const auto subs = host::rasterize(hi, f.meshes, sizes, y * k, (y + 1) * k);
      for (const host::Fragment& s : subs) {
        const int at = f.fragment_at[static_cast<size_t>(y) * static_cast<size_t>(width) +
                                     static_cast<size_t>(s.x / k)];
        if (at < 0 || f.fragments[static_cast<size_t>(at)].material != s.material) continue;
        const auto i = static_cast<size_t>(at);
        const auto c = footprint::supersampled(f.ideal_texture(i), f.sampler(i), s.uv, s.r1, s.r2,
                                               host::quantize(s).shade);
        ref.rgba[i] += glm::dvec4(c[0], c[1], c[2], c[3]);
        ++count[i];
        ++taken[static_cast<size_t>(id)];
      }
    }
  };
  std::vector<std::thread> threads;
  for (int id = 1; id < workers; ++id) threads.emplace_back(work, id);
  work(0);
  for (std::thread& th : threads) th.join();
  for (uint64_t n : taken) ref.sub_pixels += n;
  ref.interior.assign(f.records.size(), false);
  for (size_t i = 0; i < f.records.size(); ++i) {
    ref.interior[i] = count[i] == static_cast<uint32_t>(k * k);
    ref.edge += ref.interior[i] ? 0 : 1;
    if (count[i] > 0) {
      ref.rgba[i] /= static_cast<double>(count[i]);
      continue;
    }
    const host::Fragment& g = f.fragments[i];
    const auto c = footprint::supersampled(f.ideal_texture(i), f.sampler(i), g.uv, g.r1, g.r2,
                                           f.records[i].shade);
    ref.rgba[i] = glm::dvec4(c[0], c[1], c[2], c[3]);
  }
  return ref;
}

// The footprint's elongation: the ratio of the ellipse's axes (M = [r1 r2]'s singular
// values); infinite for a line, 1 for a point.
double anisotropy(const host::Fragment& g) {
  const double a11 = g.r1.x * g.r1.x + g.r2.x * g.r2.x, a12 = g.r1.x * g.r1.y + g.r2.x * g.r2.y,
               a22 = g.r1.y * g.r1.y + g.r2.y * g.r2.y;
  const double mean = (a11 + a22) / 2, radius = std::hypot((a11 - a22) / 2, a12);
  const double major = std::sqrt(mean + radius), minor = std::sqrt(std::max(mean - radius, 0.0));
  if (major == 0) return 1;
  return minor > 0 ? major / minor : std::numeric_limits<double>::infinity();
}

// Squared error over a set of 8-bit samples.
struct Group {
  double se = 0;
  uint64_t samples = 0;
  void add(double d) {
    se += d * d;
    ++samples;
  }
  std::string psnr() const {
    if (samples == 0) return "-";
    return se > 0 ? fmt::format("{:.2f}",
                                10 * std::log10(255.0 * 255.0 * static_cast<double>(samples) / se))
                  : "inf";
  }
};

struct Errors {
  Group all, mid, high;         // the interior pixels; those in [kAnisoLow, kAnisoHigh), beyond
  std::vector<Group> material;  // the interior pixels of each material
  double max = 0, mean = 0;     // over the interior pixels
};

// RGB against the reference. `worst` receives every fragment's largest channel error.
Errors errors(const Frame& f, const std::vector<uint32_t>& rgba, const Reference& ref,
              const std::vector<double>& aniso, std::vector<double>* worst) {
  Errors e;
  e.material.resize(f.scene.materials.size());
  double sum = 0;
  worst->assign(rgba.size(), 0);
  for (size_t i = 0; i < rgba.size(); ++i) {
    double px = 0;
    for (int c = 0; c < 3; ++c) {
      const double d = texram::channel(rgba[i], c) - ref.rgba[i][c];
      px = std::max(px, std::abs(d));
      if (!ref.interior[i]) continue;
      e.all.add(d);
      e.material[static_cast<size_t>(f.fragments[i].material)].add(d);
      if (aniso[i] >= kAnisoHigh) {
        e.high.add(d);
      } else if (aniso[i] >= kAnisoLow) {
        e.mid.add(d);
      }
      sum += std::abs(d);
    }
    (*worst)[i] = px;
    if (ref.interior[i]) e.max = std::max(e.max, px);
  }
  e.mean = sum / static_cast<double>(std::max<uint64_t>(e.all.samples, 1));
  return e;
}

Rgb8 rgb_of(uint32_t rgba) {
  return {static_cast<uint8_t>(rgba >> 24), static_cast<uint8_t>(rgba >> 16),
          static_cast<uint8_t>(rgba >> 8)};
}

// Background and every fragment's colour, as the renderer composes its frame.
ImageRgb8 compose(const Frame& f, const std::vector<uint32_t>& rgba) {
  const auto bg = [](double v) {
    return static_cast<uint8_t>(std::lround(std::clamp(v, 0.0, 1.0) * 255));
  };
  ImageRgb8 img(f.scene.camera.width, f.scene.camera.height);
  std::fill(img.pixels.begin(), img.pixels.end(),
            Rgb8{bg(f.scene.background.r), bg(f.scene.background.g), bg(f.scene.background.b)});
  for (size_t i = 0; i < rgba.size(); ++i) img.at(f.records[i].x, f.records[i].y) = rgb_of(rgba[i]);
  return img;
}

// A "hot" ramp for error maps: black, red, yellow, white as t goes 0 -> 1 (as the renderer's).
Rgb8 hot(double t) {
  auto c = [](double v) {
    return static_cast<uint8_t>(std::lround(255 * std::clamp(v, 0.0, 1.0)));
  };
  return {c(3 * t), c(3 * t - 1), c(3 * t - 2)};
}

ImageRgb8 error_map(const Frame& f, const std::vector<double>& worst) {
  ImageRgb8 img(f.scene.camera.width, f.scene.camera.height);
  for (size_t i = 0; i < worst.size(); ++i)
    img.at(f.records[i].x, f.records[i].y) = hot(worst[i] / kErrorFullScale);
  return img;
}

// Tiles in a grid of `columns`, each under a label in the built-in 5 x 7 font.
ImageRgb8 labelled_grid(const std::vector<std::pair<std::string, ImageRgb8>>& tiles, int columns) {
  const int w = tiles.front().second.width, h = tiles.front().second.height;
  const int label_h = w >= 240 ? 18 : 9, dot = std::max(1, label_h / 9), gap = 2;
  const int rows = (static_cast<int>(tiles.size()) + columns - 1) / columns;
  const Rgb8 paper{24, 24, 28}, ink{240, 240, 240};
  ImageRgb8 out(columns * w + (columns - 1) * gap, rows * (label_h + h) + (rows - 1) * gap);
  std::fill(out.pixels.begin(), out.pixels.end(), paper);
  for (size_t t = 0; t < tiles.size(); ++t) {
    const int x0 = static_cast<int>(t % static_cast<size_t>(columns)) * (w + gap);
    const int y0 = static_cast<int>(t / static_cast<size_t>(columns)) * (label_h + h + gap);
    const size_t fits = static_cast<size_t>(std::max(1, (w - 2 * dot) / (6 * dot)));
    const std::string text = tiles[t].first.substr(0, fits);
    const ImageRgb8 label =
        patterns::text(static_cast<int>(text.size()) * 6 * dot, label_h, text, ink, paper);
    for (int y = 0; y < label.height; ++y) {
      for (int x = 0; x < label.width; ++x) out.at(x0 + 2 * dot + x, y0 + y) = label.at(x, y);
    }
    for (int y = 0; y < h; ++y) {
      for (int x = 0; x < w; ++x) out.at(x0 + x, y0 + label_h + y) = tiles[t].second.at(x, y);
    }
  }
  return out;
}

Frame make_frame(const FootprintSweepArgs& args) {
  Frame f;
  const std::string path =
      args.scene.empty() ? std::string(TMU_SOURCE_DIR) + "/scenes/grazing.json" : args.scene;
  f.scene = host::load_scene(path);
  if (args.quick) {
    f.scene.camera.width = std::max(1, f.scene.camera.width / 2);
    f.scene.camera.height = std::max(1, f.scene.camera.height / 2);
  }
  for (const host::Material& m : f.scene.materials) {
    if (m.unit != host::Material::Unit::kTrilinear) {
      throw InputError(path, "materials." + m.name + ".unit",
                       "the footprint sweep needs the trilinear unit (not lowcost)");
    }
  }
  {
    const render::Pipeline pipe(f.scene, render::Level::kGolden);  // for its textures
    f.textures = pipe.textures();
  }
  for (const render::MaterialTexture& t : f.textures)
    f.ideal.push_back(t.texram ? texram::ideal_texture(t.texram->source) : texram::IdealTexture{});
  std::vector<glm::ivec2> sizes;
  for (const render::MaterialTexture& t : f.textures) sizes.push_back(t.size);
  for (const host::Object& obj : f.scene.objects) f.meshes.push_back(host::make_mesh(obj));
  f.fragments = host::rasterize(f.scene, f.meshes, sizes);
  if (f.fragments.empty()) throw InputError(path, "objects", "no fragment is visible");
  f.fragment_at.assign(
      static_cast<size_t>(f.scene.camera.width) * static_cast<size_t>(f.scene.camera.height), -1);
  for (size_t i = 0; i < f.fragments.size(); ++i) {
    f.records.push_back(host::quantize(f.fragments[i]));
    f.fragment_at[static_cast<size_t>(f.fragments[i].y) *
                      static_cast<size_t>(f.scene.camera.width) +
                  static_cast<size_t>(f.fragments[i].x)] = static_cast<int>(i);
  }
  f.scene.path = path;
  return f;
}

std::string fixed(std::optional<double> v, int digits) {
  return v ? fmt::format("{:.{}f}", *v, digits) : "-";
}

}  // namespace

void sweep_footprint(const FootprintSweepArgs& args) {
  const auto t_start = Clock::now();
  const int k = args.k > 0 ? args.k : (args.quick ? 4 : 8);
  const Frame f = make_frame(args);
  const size_t n = f.records.size();

  std::vector<double> aniso(n);
  size_t at_least_low = 0, at_least_high = 0;
  double most = 0;
  for (size_t i = 0; i < n; ++i) {
    aniso[i] = anisotropy(f.fragments[i]);
    at_least_low += aniso[i] >= kAnisoLow ? 1 : 0;
    at_least_high += aniso[i] >= kAnisoHigh ? 1 : 0;
    if (std::isfinite(aniso[i])) most = std::max(most, aniso[i]);
  }
  fmt::print("sweep footprint: {} ({}x{}{}), {} textured pixels\n", f.scene.path,
             f.scene.camera.width, f.scene.camera.height, args.quick ? ", quick" : "", n);
  fmt::print(
      "  anisotropy (ratio of the footprint ellipse's axes): >= {:.0f} at {:.1f} %, >= {:.0f} at "
      "{:.1f} % of them, max {:.0f}\n",
      kAnisoLow, 100.0 * static_cast<double>(at_least_low) / static_cast<double>(n), kAnisoHigh,
      100.0 * static_cast<double>(at_least_high) / static_cast<double>(n), most);

  auto t = Clock::now();
  const Reference ref = reference(f, k);
  fmt::print(
      "  reference: {0}x{0} sub-pixels per pixel, each the box filter of its own footprint\n"
      "    (footprint::supersampled: a grid of ideal samples, each <= 1 texel), averaged: {1} "
      "sub-pixel footprints, {2:.1f} s;\n"
      "    statistics over the {3} interior pixels ({4} edge pixels, where some sub-pixels see "
      "another surface, left out)\n",
      k, ref.sub_pixels, since(t), n - ref.edge, ref.edge);
  size_t mid_pixels = 0, high_pixels = 0;
  for (size_t i = 0; i < n; ++i) {
    if (!ref.interior[i]) continue;
    high_pixels += aniso[i] >= kAnisoHigh ? 1 : 0;
    mid_pixels += aniso[i] >= kAnisoLow && aniso[i] < kAnisoHigh ? 1 : 0;
  }

  const std::vector<Variant> variants = {
      {"trilinear (isotropic)", "trilinear", Kind::kTrilinear},
      {"footprint N<=2", "footprint_n2", Kind::kFootprint, 1},
      {"footprint N<=4", "footprint_n4", Kind::kFootprint, 2},
      {"footprint N<=8", "footprint_n8", Kind::kFootprint, 3},
      {"footprint N<=16", "footprint_n16", Kind::kFootprint, 4},
      {"footprint N<=16 q sides", "footprint_n16_sides", Kind::kFootprint, 4,
       footprint::Direction::kLongerSide, footprint::QRule::kSides},
      {"ideal ellipse axis N<=16", "ideal_ellipse_n16", Kind::kIdeal, 4,
       footprint::Direction::kEllipseAxis},
      {"ideal longer side N<=16", "ideal_longer_n16", Kind::kIdeal, 4,
       footprint::Direction::kLongerSide},
      {"OIIO aniso 16", "oiio_aniso16", Kind::kOiio},
  };
  const auto tmp = std::filesystem::temp_directory_path() /
                   fmt::format("tmu_sweep_footprint_{}", static_cast<long>(::getpid()));
  std::filesystem::create_directories(tmp);
  struct RemoveTmp {
    std::filesystem::path path;
    ~RemoveTmp() {
      std::error_code ec;
      std::filesystem::remove_all(path, ec);
    }
  } remove_tmp{tmp};

  if (!args.out_dir.empty()) std::filesystem::create_directories(args.out_dir);
  const std::filesystem::path out(args.out_dir);
  std::vector<uint32_t> ref_rgba(n);
  for (size_t i = 0; i < n; ++i) {
    const glm::dvec4& c = ref.rgba[i];
    ref_rgba[i] = round_rgba({c[0], c[1], c[2], c[3]});
  }
  std::vector<std::pair<std::string, ImageRgb8>> pictures = {
      {fmt::format("reference k={}", k), compose(f, ref_rgba)}};
  std::vector<std::pair<std::string, ImageRgb8>> maps = {pictures.front()};

  // Every figure is a C++ model's (the row's model column names it), the cycles the page
  // model's prediction: no hardware runs in this sweep.
  std::vector<Column> header = {"variant", "model", {"PSNR dB", Mark::kModel}};
  if (f.scene.materials.size() > 1) {
    for (const host::Material& m : f.scene.materials)
      header.emplace_back("PSNR " + m.name, Mark::kModel);
  }
  header.emplace_back(fmt::format("PSNR ratio {:.0f}-{:.0f}", kAnisoLow, kAnisoHigh), Mark::kModel);
  header.emplace_back(fmt::format("PSNR ratio>={:.0f}", kAnisoHigh), Mark::kModel);
  for (const char* h : {"max err", "mean err", "probes/px", "cycles/px", "wall s"})
    header.emplace_back(h, Mark::kModel);
  SweepTable table(header);
  for (const Variant& v : variants) {
    Outcome o;
    std::string model = "golden";
    double make_seconds = 0;
    switch (v.kind) {
      case Kind::kTrilinear:
        o = run_trilinear(f);
        break;
      case Kind::kFootprint:
        o = run_footprint(f, v.log2_max, v.q_rule);
        break;
      case Kind::kIdeal:
        o = run_ideal(f, v.direction);
        model = "ideal";
        break;
      case Kind::kOiio:
        o = run_oiio(f, tmp, &make_seconds);
        model = "OIIO";
        break;
    }
    std::vector<double> worst;
    const Errors e = errors(f, o.rgba, ref, aniso, &worst);
    const std::optional<double> cycles =
        o.cycles ? std::optional<double>(static_cast<double>(*o.cycles) / static_cast<double>(n))
                 : std::nullopt;
    std::vector<Cell> row = {v.name, model, e.all.psnr()};
    if (f.scene.materials.size() > 1) {
      for (const Group& g : e.material) row.push_back(g.psnr());
    }
    row.push_back(e.mid.psnr());
    row.push_back(e.high.psnr());
    row.push_back(fmt::format("{:.1f}", e.max));
    row.push_back(fmt::format("{:.2f}", e.mean));
    row.push_back(fixed(o.probes, 2));
    row.push_back(fixed(cycles, 2));
    row.push_back(fmt::format("{:.3f}", o.seconds));
    table.add(std::move(row));
    fmt::print("{}{}\n", table.last_row_text(),
               v.kind == Kind::kOiio ? fmt::format("(make_texture {:.3f} s)", make_seconds) : "");
    ImageRgb8 picture = compose(f, o.rgba), map = error_map(f, worst);
    if (!args.out_dir.empty()) {
      write_image((out / ("footprint_" + v.file + ".png")).string(), picture);
      write_image((out / ("footprint_" + v.file + "_error.png")).string(), map);
    }
    pictures.emplace_back(v.name, std::move(picture));
    maps.emplace_back(v.name, std::move(map));
  }
  table.print(args.markdown);
  fmt::print(
      "PSNR, max and mean error: RGB against the reference over the interior pixels (8-bit "
      "levels; ideal and OIIO rounded\n"
      "  to 8 bits); PSNR <material>: its interior pixels; PSNR ratio: the interior pixels whose "
      "footprint ellipse's axes\n"
      "  have that ratio ({} pixels {:.0f}-{:.0f}, {} beyond).\n"
      "probes/px: trilinear probes per textured pixel (OIIO: its own statistic, sample positions "
      "per MIP level read).\n"
      "cycles/px: predicted by the page model per textured pixel, a unit per material as in the "
      "renderer: one period per\n"
      "  access (one per byte plane of every probe), a second when a bank faults.\n"
      "wall s: the variant's sampling loop on one core, best of {}.\n",
      mid_pixels, kAnisoLow, kAnisoHigh, high_pixels, kTimingRuns);
  if (!args.out_dir.empty()) {
    write_image((out / "footprint_reference.png").string(), pictures.front().second);
    write_image((out / "footprint_sweep.png").string(), labelled_grid(pictures, 3));
    write_image((out / "footprint_sweep_error.png").string(), labelled_grid(maps, 3));
    fmt::print(
        "wrote {}/footprint_sweep.png, footprint_sweep_error.png (largest channel error, white = "
        "{:.0f} levels) and each variant's picture and error map\n",
        args.out_dir, kErrorFullScale);
  }
  fmt::print("total {:.1f} s\n", since(t_start));
}

}  // namespace tmu::texsim
