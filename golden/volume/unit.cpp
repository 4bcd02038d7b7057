#include "volume/unit.hpp"

#include <algorithm>
#include <stdexcept>

#include "fixed/blend.hpp"

namespace tmu::volume {

VolumeMemory load(const VoxelGrid& grid) {
  VolumeMemory m{VolumeGeometry(grid.nx, grid.ny, grid.nz), {}};
  for (auto& bank : m.banks) bank.assign(m.geometry.bank_cells(), 0);
  for (uint32_t z = 0; z < grid.nz; ++z) {
    for (uint32_t y = 0; y < grid.ny; ++y) {
      for (uint32_t x = 0; x < grid.nx; ++x) {
        const texram::BankCell c = m.geometry.cell(x, y, z);
        m.banks[c.bank][c.address] = grid.at(x, y, z);
      }
    }
  }
  return m;
}

AxisCorners axis_corners(int32_t pos, uint32_t n, int weight_bits) {
  const int32_t top = static_cast<int32_t>((n - 1) << kPosFrac);
  const int32_t p = std::clamp(pos, 0, top);
  AxisCorners a;
  a.i0 = static_cast<uint32_t>(p) >> kPosFrac;
  a.i1 = std::min(a.i0 + 1, n - 1);
  a.w = (static_cast<uint32_t>(p) & ((1u << kPosFrac) - 1)) >> (kPosFrac - weight_bits);
  return a;
}

namespace {

// The voxels of one access before the layout: two x, two y, one z (signed: may be outside).
struct Slab {
  std::array<int64_t, 2> x, y;
  int64_t z;
};

std::vector<Slab> schedule(const std::array<AxisCorners, 3>& c, Mode mode) {
  const int64_t i0 = c[0].i0, i1 = c[0].i1, j0 = c[1].i0, j1 = c[1].i1, k0 = c[2].i0, k1 = c[2].i1;
  std::vector<Slab> s = {{{i0, i1}, {j0, j1}, k0}, {{i0, i1}, {j0, j1}, k1}};
  if (mode == Mode::kRaw) {
    s.push_back({{i0 - 1, i0 + 2}, {j0, j1}, k0});
    s.push_back({{i0 - 1, i0 + 2}, {j0, j1}, k1});
    s.push_back({{i0, i1}, {j0 - 1, j0 + 2}, k0});
    s.push_back({{i0, i1}, {j0 - 1, j0 + 2}, k1});
    s.push_back({{i0, i1}, {j0, j1}, k0 - 1});
    s.push_back({{i0, i1}, {j0, j1}, k0 + 2});
  }
  return s;
}

std::array<AxisCorners, 3> corners(const VolumeGeometry& g, const Position& pos, int w) {
  return {axis_corners(pos[0], g.nx(), w), axis_corners(pos[1], g.ny(), w),
          axis_corners(pos[2], g.nz(), w)};
}

Access layout_access(const VolumeGeometry& g, const Slab& s) {
  Access a;
  for (int64_t y : s.y) {
    for (int64_t x : s.x) {
      if (x < 0 || y < 0 || s.z < 0 || x >= g.nx() || y >= g.ny() || s.z >= g.nz()) continue;
      const Voxel v{static_cast<uint32_t>(x), static_cast<uint32_t>(y), static_cast<uint32_t>(s.z)};
      const texram::BankCell cell = g.cell(v.x, v.y, v.z);
      if (a.address[cell.bank] && *a.address[cell.bank] != cell.address) {
        throw std::logic_error("volume: two cells of one bank in one access");
      }
      a.voxel[cell.bank] = v;
      a.address[cell.bank] = cell.address;
    }
  }
  return a;
}

// The voxels the accesses delivered, in the 4 x 4 x 4 neighbourhood (i0 - 1 .. i0 + 2, ...).
class Delivered {
 public:
  explicit Delivered(const std::array<AxisCorners, 3>& c) : c_(c) {}
  void put(const Voxel& v, uint8_t value) { cells_[slot(v.x, v.y, v.z)] = value; }
  int64_t get(int64_t x, int64_t y, int64_t z) const {
    const std::optional<uint8_t>& s = cells_[slot(x, y, z)];
    if (!s) throw std::logic_error("volume: the schedule did not read a voxel the unit needs");
    return *s;
  }

 private:
  size_t slot(int64_t x, int64_t y, int64_t z) const {
    const int64_t dx = x - c_[0].i0 + 1, dy = y - c_[1].i0 + 1, dz = z - c_[2].i0 + 1;
    if (dx < 0 || dx > 3 || dy < 0 || dy > 3 || dz < 0 || dz > 3) {
      throw std::logic_error("volume: a voxel outside the neighbourhood");
    }
    return static_cast<size_t>(dx + 4 * dy + 16 * dz);
  }
  std::array<AxisCorners, 3> c_;
  std::array<std::optional<uint8_t>, 64> cells_{};
};

}  // namespace

std::vector<Access> plan_accesses(const VolumeGeometry& g, const Position& pos, Mode mode) {
  std::vector<Access> out;
  for (const Slab& s : schedule(corners(g, pos, 8), mode)) out.push_back(layout_access(g, s));
  return out;
}

std::array<std::optional<uint32_t>, 8> page_addresses(const Access& access) {
  std::array<std::optional<uint32_t>, 8> a{};
  for (size_t b = 0; b < kVolumeBanks; ++b) a[b] = access.address[b];
  return a;
}

Resample blend(const VolumeGeometry& g, const Config& config, const Position& pos,
               const std::vector<Access>& accesses, const std::vector<AccessData>& bytes) {
  const int w = config.weight_bits;
  if (w < 1 || w > 8) throw std::invalid_argument("volume: weight bits 1..8");
  if (accesses.size() != static_cast<size_t>(accesses_per_resample(config.mode)) ||
      bytes.size() != accesses.size()) {
    throw std::invalid_argument("volume: a location needs the mode's accesses and their data");
  }
  const std::array<AxisCorners, 3> c = corners(g, pos, w);
  Delivered data(c);
  for (size_t i = 0; i < accesses.size(); ++i) {
    for (size_t b = 0; b < kVolumeBanks; ++b) {
      if (accesses[i].voxel[b]) data.put(*accesses[i].voxel[b], bytes[i][b]);
    }
  }
  const std::array<uint32_t, 3> n = {g.nx(), g.ny(), g.nz()};
  // Corner k = x + 2 y + 4 z of the cell.
  auto corner = [&](size_t k) {
    return std::array<int64_t, 3>{(k & 1) ? c[0].i1 : c[0].i0, (k & 2) ? c[1].i1 : c[1].i0,
                                  (k & 4) ? c[2].i1 : c[2].i0};
  };
  std::array<int64_t, 8> values{};
  for (size_t k = 0; k < 8; ++k) {
    const auto p = corner(k);
    values[k] = data.get(p[0], p[1], p[2]);
  }
  Resample r;
  r.value = static_cast<uint8_t>(fx::trilerp(values, c[0].w, c[1].w, c[2].w, w));
  if (config.mode != Mode::kRaw) return r;
  for (size_t a = 0; a < 3; ++a) {
    std::array<int64_t, 8> d{};
    for (size_t k = 0; k < 8; ++k) {
      const auto p = corner(k);
      auto f = [&](int64_t offset) {
        auto q = p;
        q[a] += offset;
        return data.get(q[0], q[1], q[2]);
      };
      const int64_t i = p[a];
      const int64_t lo = i > 0 ? f(-1) : 2 * f(0) - f(1);
      const int64_t hi = i + 1 < n[a] ? f(1) : 2 * f(0) - f(-1);
      d[k] = hi - lo;
    }
    r.gradient[a] = static_cast<int32_t>(fx::trilerp(d, c[0].w, c[1].w, c[2].w, w, kGradFrac - 1));
  }
  return r;
}

Resample resample(const VolumeMemory& memory, const Config& config, const Position& pos,
                  texram::PageModel* pages, std::vector<Access>* accesses) {
  if (config.weight_bits < 1 || config.weight_bits > 8) {
    throw std::invalid_argument("volume: weight bits 1..8");
  }
  const VolumeGeometry& g = memory.geometry;
  const std::vector<Access> plan = plan_accesses(g, pos, config.mode);
  std::vector<AccessData> bytes(plan.size());
  for (size_t i = 0; i < plan.size(); ++i) {
    for (size_t b = 0; b < kVolumeBanks; ++b) {
      if (plan[i].address[b]) bytes[i][b] = memory.banks[b][*plan[i].address[b]];
    }
    if (pages) pages->access(page_addresses(plan[i]));
    if (accesses) accesses->push_back(plan[i]);
  }
  return blend(g, config, pos, plan, bytes);
}

std::vector<Resample> cast(const VolumeMemory& memory, const Config& config, const Ray& ray,
                           texram::PageModel* pages, std::vector<Access>* accesses) {
  std::vector<Resample> out;
  out.reserve(ray.count);
  for (Marcher m(ray); !m.done(); m.advance()) {
    out.push_back(resample(memory, config, m.position(), pages, accesses));
  }
  return out;
}

}  // namespace tmu::volume
