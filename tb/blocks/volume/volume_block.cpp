#include "blocks/volume/volume_block.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

#include "blocks/trilinear/texram_memory.hpp"
#include "formats/formats.hpp"
#include "harness/described_engines.hpp"
#include "harness/described_hls.hpp"
#include "hls/volume/volume_sc.hpp"
#include "rtl_models_volume.hpp"
#include "texram/page_model.hpp"
#include "volume/layout.hpp"
#include "volume/ray_sets.hpp"
#include "volume/sources.hpp"

TMU_DESCRIBE_SC(volume)

namespace tmu::tb {
namespace fmts = tmu::formats;
using D = desc::volume;
using volume::Mode;
using volume::Position;
using volume::Ray;

namespace {

constexpr int kFrac = volume::kPosFrac;
constexpr int32_t kOne = int32_t{1} << kFrac;  // one voxel
constexpr int32_t kPosMax = static_cast<int32_t>(fmts::kVoxelPos.max_raw());
constexpr int32_t kPosMin = static_cast<int32_t>(fmts::kVoxelPos.min_raw());
constexpr int32_t kStepMax = static_cast<int32_t>(fmts::kVoxelStep.max_raw());
constexpr int32_t kStepMin = static_cast<int32_t>(fmts::kVoxelStep.min_raw());
constexpr uint32_t kMaxSide = 512;
// A random run draws a new volume after this many rays.
constexpr size_t kBatch = 400;
// The figures' volume (docs/volume.md): one chip's 64 x 128 x 128 slab.
constexpr std::array<uint32_t, 3> kFigureSize = {64, 128, 128};

constexpr uint64_t low_bits(const fx::Format& f) { return (uint64_t{1} << f.width()) - 1; }
uint64_t bits(int64_t raw, const fx::Format& f) { return static_cast<uint64_t>(raw) & low_bits(f); }
int32_t signed_field(uint64_t field, const fx::Format& f) {
  return static_cast<int32_t>(
      fx::fit(static_cast<int64_t>(field & low_bits(f)), f, fx::Overflow::kWrap));
}

// Uniform in lo..hi (inclusive) from the generator's raw output (no std distributions: the
// same stimulus on every standard library).
int64_t uniform(std::mt19937_64& rng, int64_t lo, int64_t hi) {
  return lo + static_cast<int64_t>(rng() % static_cast<uint64_t>(hi - lo + 1));
}

// The golden unit over a run: a configuration names the volume and the unit's mode and W (the
// page model runs on across volumes, as the memory's does); a ray gives its resamples, its
// accesses the requests.
class Golden : public Model {
 public:
  Golden(std::shared_ptr<const VolumeStore> store, const texram::OpenPages& open)
      : store_(std::move(store)), pages_(open) {}
  void configure(const Txn& cfg) override {
    setup_ = volume_setup_of(cfg);
    volume_ = store_->get(setup_);
  }
  void step(const Txn& item, Sink& sink) override {
    if (!volume_) throw std::logic_error("volume: a ray before the first configuration");
    const Ray ray = volume_ray_of(item);
    ++rays_;
    std::vector<volume::Access> accesses;
    for (volume::Marcher m(ray); !m.done(); m.advance()) {
      accesses.clear();
      const volume::Resample r =
          volume::resample(volume_->memory, setup_.config, m.position(), &pages_, &accesses);
      sink.output(volume_output_item(r, m.index() + 1 == ray.count));
      for (const volume::Access& a : accesses) sink.request(0, volume_request_item(a));
      ++resamples_;
    }
  }
  Counters counters() const override {
    constexpr uint64_t kWrap = 0xFFFF'FFFFu;  // StatCount
    Counters c = {{"rays", rays_ & kWrap}, {"resamples", resamples_ & kWrap}};
    for (auto& p : page_counters(pages_.stats())) c.push_back(std::move(p));
    return c;
  }

 private:
  std::shared_ptr<const VolumeStore> store_;
  VolumeSetup setup_;
  std::shared_ptr<const StoredVolume> volume_;
  texram::PageModel pages_;
  uint64_t rays_ = 0, resamples_ = 0;
};

// The voxels of a pattern other than random bytes.
volume::VoxelGrid pattern_grid(const VolumeSetup& s) {
  const auto [nx, ny, nz] = s.size;
  switch (s.pattern) {
    case VolumePattern::kMarschnerLobb:
      return volume::marschner_lobb_grid(nx, ny, nz);
    case VolumePattern::kSphere:
      return volume::sphere_grid(nx, ny, nz, std::min({nx, ny, nz}) / 3.0, 8.0);
    default: {  // a linear ramp, modulo 256
      volume::VoxelGrid g(nx, ny, nz);
      for (uint32_t z = 0; z < nz; ++z) {
        for (uint32_t y = 0; y < ny; ++y) {
          for (uint32_t x = 0; x < nx; ++x) g.at(x, y, z) = static_cast<uint8_t>(x + 3 * y + 7 * z);
        }
      }
      return g;
    }
  }
}

}  // namespace

// ---- The volumes ---------------------------------------------------------------------------

std::shared_ptr<const StoredVolume> VolumeStore::get(const VolumeSetup& setup) const {
  VolumeSetup key = setup;
  key.config = {};  // the volume is its size and content, whatever the unit's mode
  const std::lock_guard<std::mutex> lock(mutex_);
  for (const auto& [k, v] : cache_) {
    if (k == key) return v;
  }
  const auto [nx, ny, nz] = setup.size;
  auto v = std::make_shared<StoredVolume>(
      StoredVolume{volume::VolumeMemory{volume::VolumeGeometry(nx, ny, nz), {}}, nullptr});
  if (setup.pattern == VolumePattern::kRandom) {
    // Random bytes straight into the banks' cells (the padding's never read).
    std::mt19937_64 rng(0x7E1A'F00D'0000'0000ull ^ setup.content);
    for (auto& bank : v->memory.banks) {
      bank.resize(v->memory.geometry.bank_cells());
      for (size_t i = 0; i < bank.size(); i += 8) {
        const uint64_t r = rng();
        for (size_t k = 0; k < 8 && i + k < bank.size(); ++k) bank[i + k] = uint8_t(r >> (8 * k));
      }
    }
  } else {
    v->memory = volume::load(pattern_grid(setup));
  }
  auto image = std::make_shared<texram::TexramTexture>();
  for (size_t b = 0; b < volume::kVolumeBanks; ++b) image->banks[b] = v->memory.banks[b];
  v->image = image;
  cache_.emplace_back(key, v);
  return v;
}

void VolumeStore::hold(const VolumeSetup& setup, const volume::VoxelGrid& grid) {
  if (setup.size != std::array<uint32_t, 3>{grid.nx, grid.ny, grid.nz}) {
    throw std::invalid_argument(
        fmt::format("volume: a store's {} x {} x {} voxels held for a size "
                    "of {} x {} x {}",
                    grid.nx, grid.ny, grid.nz, setup.size[0], setup.size[1], setup.size[2]));
  }
  VolumeSetup key = setup;
  key.config = {};
  auto v = std::make_shared<StoredVolume>(StoredVolume{volume::load(grid), nullptr});
  auto image = std::make_shared<texram::TexramTexture>();
  for (size_t b = 0; b < volume::kVolumeBanks; ++b) image->banks[b] = v->memory.banks[b];
  v->image = image;
  const std::lock_guard<std::mutex> lock(mutex_);
  std::erase_if(cache_, [&key](const auto& kv) { return kv.first == key; });
  cache_.emplace_back(key, v);
}

// ---- Items -----------------------------------------------------------------------------------

Txn volume_cfg_item(const VolumeSetup& s) {
  return channel_item(D::table(), "cfg",
                      {uint64_t(s.config.mode), uint64_t(s.config.weight_bits), s.size[0],
                       s.size[1], s.size[2], uint64_t(s.pattern), s.content});
}

VolumeSetup volume_setup_of(const Txn& t) {
  VolumeSetup s;
  s.config.mode = t.f[D::cfg_mode] != 0 ? Mode::kRaw : Mode::kValue;
  const uint64_t w = t.f[D::cfg_weight_bits];
  if (w < 1 || w > 8) {
    throw std::invalid_argument(
        fmt::format("volume: cfg.weight_bits {}: the blend's weight bits are 1..8", w));
  }
  s.config.weight_bits = static_cast<int>(w);
  for (size_t a = 0; a < 3; ++a) {
    const uint64_t n = t.f[D::cfg_size + a];
    if (n < 2 || n > kMaxSide) {
      throw std::invalid_argument(
          fmt::format("volume: cfg.size[{}] ({}) {}: a side is 2..512 voxels", a, "xyz"[a], n));
    }
    s.size[a] = static_cast<uint32_t>(n);
  }
  try {
    volume::VolumeGeometry(s.size[0], s.size[1], s.size[2]);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("volume: cfg.size: ") + e.what());
  }
  s.pattern = static_cast<VolumePattern>(t.f[D::cfg_pattern] & 3);
  s.content = static_cast<uint32_t>(t.f[D::cfg_content]);
  return s;
}

Txn volume_ray_item(const Ray& r) {
  const fx::Format p = fmts::kVoxelPos, d = fmts::kVoxelStep;
  return channel_item(D::table(), "ray",
                      {bits(r.start[0], p), bits(r.start[1], p), bits(r.start[2], p),
                       bits(r.step[0], d), bits(r.step[1], d), bits(r.step[2], d), r.count});
}

Ray volume_ray_of(const Txn& t) {
  Ray r;
  for (size_t a = 0; a < 3; ++a) {
    r.start[a] = signed_field(t.f[D::ray_start + a], fmts::kVoxelPos);
    r.step[a] = signed_field(t.f[D::ray_step + a], fmts::kVoxelStep);
  }
  r.count = static_cast<uint32_t>(t.f[D::ray_count]);
  return r;
}

Txn volume_output_item(const volume::Resample& r, bool last) {
  Txn out;
  out.f[D::out_value] = r.value;
  for (size_t a = 0; a < 3; ++a) out.f[D::out_grad + a] = bits(r.gradient[a], fmts::kVolumeGrad);
  out.f[D::out_last] = last;
  return out;
}

Txn volume_request_item(const volume::Access& a) {
  Txn t;
  for (size_t b = 0; b < volume::kVolumeBanks; ++b) {
    t.f[D::mem_req_en + b] = a.address[b].has_value();
    t.f[D::mem_req_addr + b] = a.address[b].value_or(0);
  }
  return t;
}

volume::Resample volume_resample_of(const Txn& o) {
  volume::Resample r;
  r.value = static_cast<uint8_t>(o.f[D::out_value]);
  for (size_t a = 0; a < 3; ++a)
    r.gradient[a] = signed_field(o.f[D::out_grad + a], fmts::kVolumeGrad);
  return r;
}

// ---- The block -------------------------------------------------------------------------------

VolumeBlock::VolumeBlock(const BlockOptions& options)
    : VolumeBlock(options, std::make_shared<VolumeStore>()) {}

VolumeBlock::VolumeBlock(const BlockOptions& options, std::shared_ptr<const VolumeStore> store)
    : DescribedBlockOf(D::table()), options_(options), store_(std::move(store)) {
  if (options.vol_mode && (*options.vol_mode < 0 || *options.vol_mode > 1)) {
    throw std::invalid_argument("volume: mode " + std::to_string(*options.vol_mode) +
                                " (0 value, 1 raw)");
  }
  if (!options.vol_rays.empty()) {
    volume::figure_rays(options.vol_rays, 2, 2, 2);  // an unknown set is an error now
    first_.config = {options.vol_mode.value_or(0) != 0 ? Mode::kRaw : Mode::kValue, 8};
    first_.size = kFigureSize;
    first_.pattern = VolumePattern::kMarschnerLobb;
  } else {
    std::mt19937_64 rng(options.seed ^ 0x7E1A'0000'0000'0013ull);
    first_ = draw_setup(rng);
  }
  add_level("hls", hls_level<desc::volume_sc, hls::VolumeSc>());
  TMU_ADD_RTL_LEVELS(volume, variant());
}

std::string VolumeBlock::repro_options() const {
  std::string out;
  if (options_.vol_mode) out += *options_.vol_mode ? " --volume-mode raw" : " --volume-mode value";
  if (!options_.vol_rays.empty()) out += " --volume-rays " + options_.vol_rays;
  return out.empty() ? out : out.substr(1);
}

VolumeSetup VolumeBlock::draw_setup(std::mt19937_64& rng) const {
  VolumeSetup s;
  const bool raw = options_.vol_mode ? *options_.vol_mode != 0 : rng() % 2 == 0;
  s.config.mode = raw ? Mode::kRaw : Mode::kValue;
  s.config.weight_bits = rng() % 4 == 0 ? static_cast<int>(uniform(rng, 1, 7)) : 8;
  for (uint32_t& n : s.size) {
    const uint64_t r = rng() % 16;
    n = r == 0   ? 2
        : r == 1 ? static_cast<uint32_t>(uniform(rng, 41, 90))
                 : static_cast<uint32_t>(uniform(rng, 3, 40));
  }
  const uint64_t p = rng() % 8;
  s.pattern = p == 0   ? VolumePattern::kMarschnerLobb
              : p == 1 ? VolumePattern::kSphere
              : p == 2 ? VolumePattern::kRamp
                       : VolumePattern::kRandom;
  if (rng() % 24 == 0) {  // a side of 512 (random bytes: cheap to make)
    s.size[rng() % 3] = kMaxSide;
    s.pattern = VolumePattern::kRandom;
  }
  s.content = static_cast<uint32_t>(rng());
  return s;
}

std::vector<Txn> VolumeBlock::setup_items() const { return {volume_cfg_item(first_)}; }

namespace {

// A coordinate of a ray's start along an axis of n voxels: on a voxel (fraction 0), on the
// volume's faces, outside it, anywhere in VoxelPos now and then, mostly inside.
int32_t draw_start(std::mt19937_64& rng, uint32_t n) {
  const int64_t top = int64_t{n - 1} * kOne;
  const uint64_t r = rng() % 16;
  if (r == 0) return static_cast<int32_t>(uniform(rng, 0, n - 1) * kOne);
  if (r == 1) return rng() % 2 ? 0 : static_cast<int32_t>(top);
  if (r == 2) return static_cast<int32_t>(uniform(rng, -3 * kOne, 0));
  if (r == 3) return static_cast<int32_t>(uniform(rng, top, top + 3 * kOne));
  if (r == 4 && rng() % 4 == 0) return static_cast<int32_t>(uniform(rng, kPosMin, kPosMax));
  return static_cast<int32_t>(uniform(rng, -kOne / 2, top + kOne / 2));
}

// A step along an axis: zero, whole voxels, tiny, anything in VoxelStep (up to 8 voxels),
// mostly within a voxel and a half either way.
int32_t draw_step(std::mt19937_64& rng) {
  const uint64_t r = rng() % 16;
  if (r < 2) return 0;
  if (r == 2) return static_cast<int32_t>(uniform(rng, -3, 3) * kOne);
  if (r == 3) return static_cast<int32_t>(uniform(rng, kStepMin, kStepMax));
  if (r == 4) return static_cast<int32_t>(uniform(rng, -64, 64));
  return static_cast<int32_t>(uniform(rng, -3 * kOne / 2, 3 * kOne / 2));
}

Ray draw_ray(std::mt19937_64& rng, const VolumeSetup& s) {
  Ray r;
  for (size_t a = 0; a < 3; ++a) {
    r.start[a] = draw_start(rng, s.size[a]);
    r.step[a] = draw_step(rng);
  }
  if (rng() % 8 == 0) {  // axis-parallel
    const size_t axis = rng() % 3;
    for (size_t a = 0; a < 3; ++a) {
      if (a != axis) r.step[a] = 0;
    }
    if (r.step[axis] == 0) r.step[axis] = rng() % 2 ? kOne : -kOne;
  }
  // Short rays mostly (a location's cases are what varies; the drift's long rays are
  // directed), now and then one of a few hundred resamples.
  const uint64_t c = rng() % 256;
  r.count = c == 0    ? 0
            : c < 24  ? 1
            : c == 24 ? static_cast<uint32_t>(uniform(rng, 60, 300))
                      : static_cast<uint32_t>(uniform(rng, 2, 7));
  return r;
}

}  // namespace

std::vector<Txn> VolumeBlock::random_rays(std::mt19937_64& rng, const VolumeSetup& s,
                                          size_t count) const {
  std::vector<Txn> items;
  for (size_t i = 0; i < count; ++i) items.push_back(volume_ray_item(draw_ray(rng, s)));
  return items;
}

std::vector<Txn> VolumeBlock::random_items(std::mt19937_64& rng, size_t count) const {
  std::vector<Txn> items;
  items.reserve(count + count / kBatch + 1);
  if (!options_.vol_rays.empty()) {  // a figure's rays, in order, from the first
    const std::vector<Ray> rays =
        volume::figure_rays(options_.vol_rays, first_.size[0], first_.size[1], first_.size[2]);
    for (size_t i = 0; i < count; ++i) items.push_back(volume_ray_item(rays[i % rays.size()]));
    return items;
  }
  // The first volume, then a new one every kBatch rays, as a driver would between batches.
  VolumeSetup s = first_;
  while (items.size() < count) {
    const size_t n = std::min(kBatch, count - items.size());
    for (const Txn& t : random_rays(rng, s, n)) items.push_back(t);
    if (items.size() < count) {
      s = draw_setup(rng);
      items.push_back(volume_cfg_item(s));
    }
  }
  return items;
}

namespace {

// The most resamples of a directed ray other than the drift's.
constexpr uint32_t kReach = 40;

// The directed rays of one volume: the hard cases at its size.
std::vector<Ray> directed_rays(const VolumeSetup& s, bool long_rays) {
  const auto [nx, ny, nz] = s.size;
  const std::array<int32_t, 3> top = {int32_t(nx - 1) * kOne, int32_t(ny - 1) * kOne,
                                      int32_t(nz - 1) * kOne};
  std::vector<Ray> rays;
  const auto ray = [&rays](Position start, Position step, uint32_t count) {
    rays.push_back({start, step, count});
  };
  // Every corner of the volume (fraction 0 on every axis), one resample each, and a ray of
  // none between them.
  for (int k = 0; k < 8; ++k) {
    ray({k & 1 ? top[0] : 0, k & 2 ? top[1] : 0, k & 4 ? top[2] : 0}, {0, 0, 0}, 1);
    if (k == 3) ray({kOne / 3, kOne / 5, kOne / 7}, {kOne, kOne, kOne}, 0);
  }
  // Along every edge, voxel by voxel (fraction 0 throughout), both ways, from each end (at most
  // kReach voxels: a long side's middle is no harder).
  for (int a = 0; a < 3; ++a) {
    const auto n = std::min(kReach, static_cast<uint32_t>(top[a] / kOne + 1));
    for (int e = 0; e < 4; ++e) {
      const int b = (a + 1) % 3, c = (a + 2) % 3;
      Position p{}, d{}, q{};
      p[b] = e & 1 ? top[b] : 0;
      p[c] = e & 2 ? top[c] : 0;
      q = p;
      d[a] = kOne;
      ray(p, d, n);
      q[a] = top[a];
      d[a] = -kOne;
      ray(q, d, n);
    }
  }
  // On the faces, between the voxels: each face plane, fractions in the other two axes.
  for (int a = 0; a < 3; ++a) {
    for (int32_t face : {0, top[a]}) {
      Position p{kOne / 3, kOne / 2 + 5, kOne / 4 + 77}, d{kOne / 2 + 3, kOne / 3, kOne / 5};
      p[a] = face;
      d[a] = 0;
      ray(p, d,
          std::min(kReach,
                   2 * static_cast<uint32_t>(std::max({top[0], top[1], top[2]}) / kOne) + 2));
    }
  }
  // Axis-parallel rays through the inside, both directions, with fractions on the others.
  for (int a = 0; a < 3; ++a) {
    Position p{top[0] / 2 + kOne / 3, top[1] / 2 + kOne / 7, top[2] / 2 + 3 * kOne / 8}, d{};
    p[a] = -kOne / 2;
    d[a] = kOne / 4;
    ray(p, d, std::min(kReach, static_cast<uint32_t>(4 * top[a] / kOne + 6)));
    p[a] = top[a] + kOne / 2;
    d[a] = -3 * kOne / 4 - 1;
    ray(p, d, std::min(kReach, static_cast<uint32_t>(4 * top[a] / (3 * kOne) + 3)));
  }
  // Negative steps from the far corner, and oblique ones across the whole volume.
  ray({top[0], top[1], top[2]}, {-kOne / 3, -kOne / 5 - 1, -kOne / 2}, 40);
  ray({top[0] - 1, kOne / 8, top[2] / 2}, {-kOne / 2, kOne / 3, -kOne / 7}, 40);
  // One LSB either side of voxels and of the last voxel (weights 0 and 255, i1 clamped).
  ray({kOne - 1, kOne + 1, top[2] - 1}, {top[0] - kOne, top[1] - kOne, 1}, 3);
  ray({top[0] + 1, top[1] - 1, kOne - 1}, {-1, 2, -kOne}, 3);
  // Steps longer than a voxel, up to the largest, out of the volume and back (clamped).
  ray({kOne / 2, kOne / 3, kOne / 4}, {11 * kOne / 4, -3 * kOne / 2, kStepMax}, 8);
  ray({top[0], kOne / 2, top[2] / 2}, {kStepMin, kStepMax / 3, -5 * kOne}, 6);
  ray({-7 * kOne / 2, -kOne / 3, top[2] + 17 * kOne / 10}, {kOne + kOne / 2, kOne, -kOne}, 12);
  // Far outside in every direction (clamped to the faces and corners).
  ray({kPosMin, kPosMax, kPosMin / 2}, {kOne, -kOne, 0}, 3);
  ray({kPosMax, kPosMin, kPosMax}, {0, 0, -kOne}, 2);
  // The accumulator wraps: past +512 voxels to -512 (and back the other way).
  ray({kPosMax - 2 * kOne, kOne / 2, kOne / 2}, {kStepMax, kOne / 8, 0}, 4);
  ray({kOne / 2, kPosMin + kOne, kOne / 3}, {0, kStepMin, 0}, 4);
  // A zero step: one location three times.
  ray({kOne / 2 + 1, kOne / 3, kOne / 5}, {0, 0, 0}, 3);
  if (long_rays) {
    // Drift: 600 steps corner to corner (location n is start + n step exactly), and 1100 along
    // z in steps of a ninth of a voxel and less.
    ray({1, 2, 3}, {top[0] / 600, top[1] / 600 + 1, top[2] / 600 - 1}, 600);
    ray({top[0] / 2 + kOne / 9, top[1] / 3, 0}, {-1, 1, top[2] / 1100}, 1100);
  }
  return rays;
}

}  // namespace

std::vector<Txn> VolumeBlock::directed_items() const {
  std::vector<Txn> items;
  if (!options_.vol_rays.empty()) return items;  // a figure's run: its rays alone
  const auto setup = [](Mode mode, int w, std::array<uint32_t, 3> size, VolumePattern p,
                        uint32_t content) {
    VolumeSetup s;
    s.config = {mode, w};
    s.size = size;
    s.pattern = p;
    s.content = content;
    return s;
  };
  using P = VolumePattern;
  const std::vector<std::pair<VolumeSetup, bool>> tour = {
      {setup(Mode::kRaw, 8, {5, 6, 7}, P::kRandom, 1), true},
      {setup(Mode::kValue, 8, {5, 6, 7}, P::kRandom, 1), false},
      {setup(Mode::kRaw, 5, {9, 4, 11}, P::kRamp, 0), false},
      {setup(Mode::kRaw, 1, {3, 3, 3}, P::kRandom, 2), false},
      {setup(Mode::kRaw, 8, {2, 2, 2}, P::kRandom, 3), false},
      {setup(Mode::kValue, 3, {2, 3, 2}, P::kRandom, 4), false},
      {setup(Mode::kRaw, 8, {2, 3, 2}, P::kRandom, 4), false},
      {setup(Mode::kValue, 8, {33, 17, 35}, P::kMarschnerLobb, 0), false},
      {setup(Mode::kRaw, 7, {32, 32, 32}, P::kSphere, 0), false},
      {setup(Mode::kRaw, 8, {512, 9, 17}, P::kRandom, 5), false},
      {setup(Mode::kRaw, 8, {12, 512, 5}, P::kRandom, 6), false},
      {setup(Mode::kValue, 8, {4, 5, 512}, P::kRandom, 7), false},
      // 2^21 cells a bank: the bank address's top bit near the far corner.
      {setup(Mode::kRaw, 8, {256, 256, 128}, P::kRandom, 8), false},
  };
  for (const auto& [s, long_rays] : tour) {
    items.push_back(volume_cfg_item(s));
    for (const Ray& r : directed_rays(s, long_rays)) items.push_back(volume_ray_item(r));
  }
  items.push_back(volume_cfg_item(first_));  // where the random items begin
  return items;
}

std::unique_ptr<Model> VolumeBlock::golden() const {
  return std::make_unique<Golden>(store_, open_pages_);
}

std::unique_ptr<Environment> VolumeBlock::environment(uint64_t seed) const {
  std::shared_ptr<const VolumeStore> store = store_;
  return std::make_unique<TexramMemory>(
      [store](const Txn& cfg) { return store->get(volume_setup_of(cfg))->image; }, seed,
      /*empty_accesses=*/true, open_pages_);
}

// ---- Coverage --------------------------------------------------------------------------------

namespace {

constexpr const char* kValueMode = "value mode (2 accesses)";
constexpr const char* kRawMode = "raw mode (8 accesses, gradient)";
constexpr const char* kNarrowW = "W below 8";
constexpr const char* kCount0 = "a ray of 0 resamples";
constexpr const char* kCount1 = "a ray of 1 resample";
constexpr const char* kLong = "a ray of 512 or more resamples (drift)";
constexpr const char* kAxisParallel = "an axis-parallel ray";
constexpr const char* kNegative = "a negative step";
constexpr const char* kLongStep = "a step longer than a voxel";
constexpr const char* kFraction0 = "fraction 0 on every axis";
constexpr const char* kOutside = "a location outside the volume (clamped)";
constexpr const char* kClamped = "a location on a last voxel (i1 = i0)";
constexpr const char* kCorner = "a location on a corner of the volume";
constexpr const char* kEdge = "a location on an edge of the volume";
constexpr const char* kEmpty = "an access that reads no bank";
constexpr const char* kWrap = "the accumulator wraps";
constexpr const char* kSide2 = "a side of 2 voxels";
constexpr const char* kSide512 = "a side of 512 voxels";
constexpr const char* kHighAddress = "a bank address of 2^20 or more";
constexpr const char* kPatterns[] = {"random volume", "Marschner-Lobb volume", "sphere volume",
                                     "ramp volume"};

}  // namespace

std::vector<std::string> VolumeBlock::coverage_cases() const {
  std::vector<std::string> cases = {kValueMode, kRawMode,      kNarrowW,  kCount0,     kCount1,
                                    kLong,      kAxisParallel, kNegative, kLongStep,   kFraction0,
                                    kOutside,   kClamped,      kCorner,   kEdge,       kEmpty,
                                    kWrap,      kSide2,        kSide512,  kHighAddress};
  cases.insert(cases.end(), std::begin(kPatterns), std::end(kPatterns));
  return cases;
}

void VolumeBlock::cover(const std::vector<Txn>& items, size_t index, const Txn&,
                        Coverage& cov) const {
  // Called once per ray with resamples, in order: replay the items before it.
  if (index < cover_next_) cover_next_ = 0;
  for (; cover_next_ < index; ++cover_next_) {
    const Txn& t = items[cover_next_];
    if (port_table().is_cfg(t)) {
      cover_setup_ = volume_setup_of(t);
    } else if (volume_ray_of(t).count == 0) {
      ++cov[kCount0];
    }
  }
  cover_next_ = index + 1;
  const VolumeSetup& s = cover_setup_;
  const Ray ray = volume_ray_of(items[index]);
  ++cov[s.config.mode == Mode::kRaw ? kRawMode : kValueMode];
  if (s.config.weight_bits < 8) ++cov[kNarrowW];
  ++cov[kPatterns[static_cast<size_t>(s.pattern)]];
  if (std::count(s.size.begin(), s.size.end(), 2u) > 0) ++cov[kSide2];
  if (std::count(s.size.begin(), s.size.end(), kMaxSide) > 0) ++cov[kSide512];
  if (ray.count == 1) ++cov[kCount1];
  if (ray.count >= 512) ++cov[kLong];
  if (std::count(ray.step.begin(), ray.step.end(), 0) == 2) ++cov[kAxisParallel];
  for (int32_t d : ray.step) {
    if (d < 0) ++cov[kNegative];
    if (std::abs(d) > kOne) ++cov[kLongStep];
  }
  for (size_t a = 0; a < 3 && ray.count > 0; ++a) {
    const int64_t last = ray.start[a] + int64_t{ray.step[a]} * (ray.count - 1);
    if (last < kPosMin || last > kPosMax) ++cov[kWrap];
  }
  const volume::VolumeGeometry g(s.size[0], s.size[1], s.size[2]);
  for (volume::Marcher m(ray); !m.done(); m.advance()) {
    const Position& p = m.position();
    int fraction0 = 0, outside = 0, clamped = 0, extreme = 0;
    for (size_t a = 0; a < 3; ++a) {
      const int64_t top = int64_t{s.size[a] - 1} * kOne;
      fraction0 += (p[a] & (kOne - 1)) == 0;
      outside += p[a] < 0 || p[a] > top;
      clamped += p[a] >= top;
      extreme += p[a] == 0 || p[a] == top;
    }
    if (fraction0 == 3) ++cov[kFraction0];
    if (outside > 0) ++cov[kOutside];
    if (clamped > 0) ++cov[kClamped];
    if (extreme == 3) ++cov[kCorner];
    if (extreme == 2) ++cov[kEdge];
    for (const volume::Access& a : volume::plan_accesses(g, p, s.config.mode)) {
      if (std::none_of(a.address.begin(), a.address.end(), [](const auto& x) { return bool(x); }))
        ++cov[kEmpty];
      for (const auto& x : a.address) {
        if (x && *x >= (1u << 20)) ++cov[kHighAddress];
      }
    }
  }
}

}  // namespace tmu::tb

TMU_REGISTER_BLOCK(volume, VolumeBlock)
