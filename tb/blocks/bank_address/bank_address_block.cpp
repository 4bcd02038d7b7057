#include "blocks/bank_address/bank_address_block.hpp"

#include <fmt/format.h>

#include <array>
#include <optional>
#include <stdexcept>

#include "formats/formats.hpp"
#include "harness/described_engines.hpp"
#include "rtl_models_bank_address.hpp"

namespace tmu::tb {
namespace fmts = tmu::formats;
using D = desc::bank_address;

namespace {

// A random run draws a new layout after this many items.
constexpr size_t kBatch = 1500;

uint32_t uniform(std::mt19937_64& rng, uint32_t n) { return static_cast<uint32_t>(rng() % n); }

texram::Geometry draw_layout(std::mt19937_64& rng) {
  const int lw = static_cast<int>(uniform(rng, fmts::kMaxMipLog2 + 1));
  const int lh = static_cast<int>(uniform(rng, fmts::kMaxMipLog2 + 1));
  const int planes = rng() % 2 ? fmts::kPlanes : 1;
  return {lw, lh, planes, rng() % 2 == 0};
}

// Geometry::cell on the layout of the configuration items before.
class Golden : public Model {
 public:
  void configure(const Txn& cfg) override { layout_ = BankAddressBlock::layout_of(cfg); }
  void step(const Txn& item, Sink& sink) override {
    if (!layout_) throw std::runtime_error("bank_address: a position before the configuration");
    const texram::BankCell c = layout_->cell(
        static_cast<int>(item.f[D::in_level]), static_cast<uint32_t>(item.f[D::in_x]),
        static_cast<uint32_t>(item.f[D::in_y]), static_cast<int>(item.f[D::in_plane]));
    Txn out;
    out.f[D::out_bank] = c.bank;
    out.f[D::out_addr] = c.address;
    sink.output(out);
  }

 private:
  std::optional<texram::Geometry> layout_;
};

// Every level's four stored corners in every plane, and every position of a level of at most
// 4 x 4 stored cells.
void corners(const texram::Geometry& g, std::vector<Txn>& items) {
  for (int l = 0; l < g.levels(); ++l) {
    const uint32_t sw = g.stored_width(l), sh = g.stored_height(l);
    for (int p = 0; p < g.planes(); ++p) {
      if (sw * sh <= 16) {
        for (uint32_t y = 0; y < sh; ++y) {
          for (uint32_t x = 0; x < sw; ++x)
            items.push_back(BankAddressBlock::position_item(l, x, y, p));
        }
        continue;
      }
      for (const auto& [x, y] :
           {std::pair{0u, 0u}, {sw - 1, 0u}, {0u, sh - 1}, {sw - 1, sh - 1}, {sw / 2, sh / 2}}) {
        items.push_back(BankAddressBlock::position_item(l, x, y, p));
      }
    }
  }
}

constexpr const char* kOnePlane = "one plane";
constexpr const char* kFourPlanes = "four planes";
constexpr const char* kTexels = "texel grid";
constexpr const char* kBlocks = "block grid";
constexpr const char* kLevel0 = "level 0";
constexpr const char* kOddLevel = "an odd level";
constexpr const char* kTopLevel = "the top level";
constexpr const char* kReplica = "a replica cell (a coordinate beyond the grid)";
constexpr const char* kLastCell = "the layout's last cell";
constexpr const char* kHighAddress = "cell address >= 2^20";
constexpr const char* kLargest = "texture 1024 x 1024";
constexpr const char* kOneTexel = "texture with a one-texel side";
constexpr const char* kNonSquare = "non-square texture";

}  // namespace

Txn BankAddressBlock::config_item(const texram::Geometry& g) {
  return channel_item(D::table(), "cfg",
                      {uint64_t(g.log2_width()), uint64_t(g.log2_height()),
                       g.planes() == fmts::kPlanes ? 1u : 0u, g.block_grid() ? 1u : 0u});
}

Txn BankAddressBlock::position_item(int level, uint32_t x, uint32_t y, int plane) {
  return channel_item(D::table(), "in", {uint64_t(level), x, y, uint64_t(plane)});
}

texram::Geometry BankAddressBlock::layout_of(const Txn& cfg) {
  return {static_cast<int>(cfg.f[D::cfg_log2_w]), static_cast<int>(cfg.f[D::cfg_log2_h]),
          cfg.f[D::cfg_four_planes] != 0 ? fmts::kPlanes : 1, cfg.f[D::cfg_block_grid] != 0};
}

BankAddressBlock::BankAddressBlock(const BlockOptions& options) : DescribedBlockOf(D::table()) {
  std::mt19937_64 rng(options.seed ^ 0xBA4C'ADD4'0000'0001ull);
  first_ = draw_layout(rng);
  TMU_ADD_RTL_LEVELS(bank_address, variant());
}

std::vector<Txn> BankAddressBlock::setup_items() const { return {config_item(first_)}; }

std::vector<Txn> BankAddressBlock::directed_items() const {
  std::vector<Txn> items;
  corners(first_, items);
  // The extremes of the layout: one texel, the largest texture, one row, one column, flat and
  // tall, each with one plane and four, texels and blocks.
  for (const auto& [lw, lh] : std::initializer_list<std::pair<int, int>>{
           {0, 0}, {10, 10}, {10, 0}, {0, 10}, {3, 7}, {1, 1}, {6, 2}}) {
    for (const int planes : {1, fmts::kPlanes}) {
      for (const bool blocks : {false, true}) {
        const texram::Geometry g(lw, lh, planes, blocks);
        items.push_back(config_item(g));
        corners(g, items);
      }
    }
  }
  items.push_back(config_item(first_));  // back to the first layout, where the random items begin
  return items;
}

std::vector<Txn> BankAddressBlock::random_items(std::mt19937_64& rng, size_t count) const {
  std::vector<Txn> items;
  items.reserve(count);
  texram::Geometry g = first_;
  size_t next_batch = kBatch;
  while (items.size() < count) {
    if (items.size() >= next_batch) {  // a new layout, as a driver between batches
      next_batch += kBatch;
      g = draw_layout(rng);
      items.push_back(config_item(g));
      continue;
    }
    const int l = static_cast<int>(uniform(rng, static_cast<uint32_t>(g.levels())));
    const uint32_t sw = g.stored_width(l), sh = g.stored_height(l);
    // Mostly anywhere in the level, now and then on its last row or column.
    const uint64_t where = rng() % 8;
    const uint32_t x = where == 0 ? sw - 1 : uniform(rng, sw);
    const uint32_t y = where == 1 ? sh - 1 : uniform(rng, sh);
    items.push_back(position_item(l, x, y, static_cast<int>(uniform(rng, uint32_t(g.planes())))));
  }
  return items;
}

std::unique_ptr<Model> BankAddressBlock::golden() const { return std::make_unique<Golden>(); }

std::vector<std::string> BankAddressBlock::coverage_cases() const {
  std::vector<std::string> cases;
  for (int b = 0; b < 8; ++b) cases.push_back(fmt::format("bank {}", b));
  for (int p = 0; p < fmts::kPlanes; ++p) cases.push_back(fmt::format("plane {}", p));
  cases.insert(cases.end(),
               {kOnePlane, kFourPlanes, kTexels, kBlocks, kLevel0, kOddLevel, kTopLevel, kReplica,
                kLastCell, kHighAddress, kLargest, kOneTexel, kNonSquare});
  return cases;
}

void BankAddressBlock::cover(const std::vector<Txn>& items, size_t index, const Txn& output,
                             Coverage& cov) const {
  if (index < cover_next_) {
    cover_next_ = 0;
    cover_layout_ = first_;
  }
  for (; cover_next_ < index; ++cover_next_) {
    if (D::table().is_cfg(items[cover_next_])) cover_layout_ = layout_of(items[cover_next_]);
  }
  const texram::Geometry& g = cover_layout_;
  const Txn& t = items[index];
  const auto level = static_cast<int>(t.f[D::in_level]);
  const auto x = static_cast<uint32_t>(t.f[D::in_x]), y = static_cast<uint32_t>(t.f[D::in_y]);
  ++cov[fmt::format("bank {}", output.f[D::out_bank] & 7)];
  ++cov[fmt::format("plane {}", t.f[D::in_plane] & 3)];
  ++cov[g.planes() == 1 ? kOnePlane : kFourPlanes];
  ++cov[g.block_grid() ? kBlocks : kTexels];
  if (level == 0) ++cov[kLevel0];
  if (level % 2 == 1) ++cov[kOddLevel];
  if (level == g.levels() - 1) ++cov[kTopLevel];
  if (level < g.levels() && (x >= g.grid_width(level) || y >= g.grid_height(level))) {
    ++cov[kReplica];
  }
  if (output.f[D::out_addr] == g.bank_cells() - 1) ++cov[kLastCell];
  if (output.f[D::out_addr] >= (uint64_t{1} << 20)) ++cov[kHighAddress];
  if (g.log2_width() == fmts::kMaxMipLog2 && g.log2_height() == fmts::kMaxMipLog2) ++cov[kLargest];
  if (g.log2_width() == 0 || g.log2_height() == 0) ++cov[kOneTexel];
  if (g.log2_width() != g.log2_height()) ++cov[kNonSquare];
  cover_next_ = index + 1;
}

}  // namespace tmu::tb

TMU_REGISTER_BLOCK(bank_address, BankAddressBlock)
