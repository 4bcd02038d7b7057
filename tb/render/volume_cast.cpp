#include "render/volume_cast.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <limits>

#include "texram/page_model.hpp"
#include "volume/compositing.hpp"
#include "volume/sample_shading.hpp"

namespace tmu::render {
namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

// A run of one pixel's locations on one chip within a round, and where its samples are in that
// chip's output.
struct IssuedRun {
  size_t pixel = 0, chip = 0, offset = 0;
  uint32_t first = 0, count = 0;
};

}  // namespace

double VolumeFrame::unit_seconds() const {
  double s = 0;
  for (const VolumeCounters& c : chips) s = std::max(s, c.seconds());
  return s;
}

double VolumeFrame::clocked_seconds() const {
  uint64_t c = 0;
  for (uint64_t k : chip_cycles) c = std::max(c, k);
  return static_cast<double>(c) * texram::kAccessNs * 1e-9;
}

std::vector<host::RaySetup> set_up_rays(const host::VolumeScene& scene) {
  const host::VolumeView view = host::make_view(scene.camera, scene.data.size);
  std::vector<host::RaySetup> rays;
  rays.reserve(static_cast<size_t>(view.width) * view.height);
  for (int y = 0; y < view.height; ++y) {
    for (int x = 0; x < view.width; ++x) {
      rays.push_back(host::set_up_ray(scene.data.size, view.eye, host::pixel_direction(view, x, y),
                                      scene.step));
    }
  }
  return rays;
}

VolumeFrame cast_volume(const host::VolumeScene& scene, const std::vector<volume::VoxelGrid>& grids,
                        const std::vector<host::RaySetup>& rays, const VolumeCastOptions& o) {
  const auto t_setup = Clock::now();
  VolumeFrame f;
  f.width = scene.camera.width;
  f.height = scene.camera.height;
  const volume::Mode mode = host::volume_mode(scene);
  const int chips = o.level == Level::kIdeal ? 1 : o.chips;  // the ideal: no banks, no slabs
  f.plan = o.level == Level::kIdeal
               ? host::whole_volume(scene.data.size, scene.slab_axis)
               : host::plan_slabs(scene.data.size, chips, scene.slab_axis, mode);
  const volume::Config config{mode, scene.weight_bits};
  std::vector<std::vector<std::unique_ptr<VolumeUnitEngine>>> engines(f.plan.slabs.size());
  for (size_t c = 0; c < engines.size(); ++c) {
    for (size_t k = 0; k < grids.size(); ++k) {
      VolumeEngineOptions eo;
      eo.check = o.check_units;
      eo.inject_fault = c == 0 && k == 0 ? o.inject_fault : -1;
      eo.name = fmt::format("chip {}, component {}", c, k);
      const volume::VoxelGrid& g = grids[k];
      engines[c].push_back(make_volume_engine(
          o.level, o.level == Level::kIdeal ? g : host::slab_grid(g, f.plan, c), config, eo));
    }
  }
  const host::SampleShading shading(scene.transfer, scene.lights, scene.step, scene.data.size);
  std::vector<host::RayCompositor> compositors(
      rays.size(), host::RayCompositor(scene.termination ? std::optional(scene.termination->alpha)
                                                         : std::nullopt));
  std::vector<uint32_t> next(rays.size(), 0);
  std::vector<size_t> open;
  for (size_t p = 0; p < rays.size(); ++p) {
    f.locations += rays[p].count;
    if (rays[p].count > 0) open.push_back(p);
  }
  f.rays = rays.size();
  f.rays_hit = open.size();
  const uint64_t segment =
      scene.termination ? scene.termination->segment : std::numeric_limits<uint32_t>::max();
  f.setup_s = seconds_since(t_setup);

  while (!open.empty()) {
    ++f.rounds;
    auto t = Clock::now();
    std::vector<std::vector<VolumeCommand>> commands(engines.size());
    std::vector<size_t> issued_per_chip(engines.size(), 0);
    std::vector<IssuedRun> runs;
    for (size_t p : open) {
      const host::RaySetup& r = rays[p];
      const uint32_t first = next[p];
      const auto n = static_cast<uint32_t>(std::min<uint64_t>(segment, r.count - first));
      if (o.level == Level::kIdeal) {
        // The real ray's locations first .. first + n - 1; the quantised ray is not read (nor
        // split by the unit's corner rule: the ideal shares no arithmetic with golden).
        commands[0].push_back({volume::Ray{{}, {}, n}, r.start, r.step, first});
        runs.push_back({p, 0, issued_per_chip[0], first, n});
        issued_per_chip[0] += n;
      } else {
        for (const host::ChipRun& run : host::split_by_chip(f.plan, r.ray, first, n)) {
          commands[run.chip].push_back(
              {host::chip_ray(f.plan, run.chip, r.ray, run.first, run.count), r.start, r.step,
               run.first});
          runs.push_back({p, run.chip, issued_per_chip[run.chip], run.first, run.count});
          issued_per_chip[run.chip] += run.count;
        }
      }
      next[p] = first + n;
      f.issued += n;
    }
    f.setup_s += seconds_since(t);

    t = Clock::now();
    // out[chip][component]: the samples of that chip's batch.
    std::vector<std::vector<std::vector<VolumeSample>>> out(engines.size());
    for (size_t c = 0; c < engines.size(); ++c) {
      if (commands[c].empty()) continue;
      for (auto& engine : engines[c]) {
        out[c].push_back(engine->cast(commands[c]));
        if (o.record) o.record->insert(o.record->end(), out[c].back().begin(), out[c].back().end());
      }
    }
    f.unit_s += seconds_since(t);

    t = Clock::now();
    for (const IssuedRun& run : runs) {
      host::RayCompositor& comp = compositors[run.pixel];
      const host::RaySetup& r = rays[run.pixel];
      const auto& samples = out[run.chip];
      for (uint32_t k = 0; k < run.count && !comp.terminated(); ++k) {
        const size_t i = run.offset + k;
        if (mode == volume::Mode::kRaw) {
          const glm::dvec3 position = r.start + r.step * static_cast<double>(run.first + k);
          comp.add(shading.raw(samples[0][i].value, samples[0][i].gradient, position));
        } else {
          comp.add(shading.rgba({samples[0][i].value, samples[1][i].value, samples[2][i].value,
                                 samples[3][i].value}));
        }
      }
    }
    std::vector<size_t> still_open;
    for (size_t p : open) {
      if (compositors[p].terminated()) {
        ++f.rays_terminated;
      } else if (next[p] < rays[p].count) {
        still_open.push_back(p);
      }
    }
    open = std::move(still_open);
    f.composite_s += seconds_since(t);
  }

  const auto t = Clock::now();
  f.pixels.resize(rays.size());
  for (size_t p = 0; p < rays.size(); ++p) {
    f.pixels[p] = compositors[p].over(scene.background);
    f.composited += compositors[p].added();
  }
  f.chips.resize(engines.size());
  f.chip_cycles.assign(engines.size(), 0);
  for (size_t c = 0; c < engines.size(); ++c) {
    for (const auto& e : engines[c]) {
      f.chips[c] += e->counters();
      f.chip_cycles[c] += e->cycles();
      f.pieces += e->pieces();
      if (const auto check = e->piece_check()) {
        if (!f.unit_check) f.unit_check.emplace();
        *f.unit_check += *check;
      }
    }
    f.total += f.chips[c];
    f.has_memory = engines[c].front()->has_memory();
  }
  f.composite_s += seconds_since(t);
  return f;
}

}  // namespace tmu::render
