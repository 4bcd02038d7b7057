#include "blocks/material_fire/material_fire_block.hpp"

#include <algorithm>
#include <cmath>

#include "harness/described_engines.hpp"
#include "perlin/materials.hpp"
#include "rtl_models_material_fire.hpp"

namespace tmu::tb {
using D = desc::material_fire;

namespace {

constexpr uint32_t kEntries = perlin::kFireTableEntries;  // 512
// The last k whose entry is not 0 (e^(-289/32) 2^12 = 0.49).
constexpr uint32_t kLastNonzero = 288;

Txn item_of(uint32_t k) { return channel_item(D::table(), "in", {k}); }

// Whether entry k was rounded up from the exact value e^(-k/32) 2^12.
bool rounded_up(uint32_t k) {
  const double exact = std::exp(-static_cast<double>(k) / 32.0) * 4096.0;
  return perlin::fire_entry(k) > exact;
}

class GoldenFire : public Model {
 public:
  void step(const Txn& item, Sink& sink) override {
    Txn out;
    out.f[D::out_entry] = perlin::fire_entry(static_cast<uint32_t>(item.f[D::in_k]));
    sink.output(out);
  }
};

constexpr const char* kOne = "k = 0: entry 4096 (1.0)";
constexpr const char* kLast = "k = 288: the last entry above 0";
constexpr const char* kZero = "k >= 289: entry 0";
constexpr const char* kTop = "k = 511";
constexpr const char* kUp = "entry rounded up";
constexpr const char* kDown = "entry rounded down";
constexpr const char* kEvery = "every k";
constexpr const char* kFall = "k then k + 1 (a step down the table)";

}  // namespace

MaterialFireBlock::MaterialFireBlock(const BlockOptions&) : DescribedBlockOf(D::table()) {
  TMU_ADD_RTL_LEVELS(material_fire, variant());
}

// Every entry in order, then back down (each step a neighbour's change of bits).
std::vector<Txn> MaterialFireBlock::directed_items() const {
  std::vector<Txn> items;
  for (uint32_t k = 0; k < kEntries; ++k) items.push_back(item_of(k));
  for (uint32_t k = kEntries; k-- > 0;) items.push_back(item_of(k));
  return items;
}

// Uniform over the table, and a third of them where it falls fastest and where it ends.
std::vector<Txn> MaterialFireBlock::random_items(std::mt19937_64& rng, size_t count) const {
  std::vector<Txn> items;
  items.reserve(count);
  for (size_t i = 0; i < count; ++i) {
    const uint64_t r = rng();
    uint32_t k = static_cast<uint32_t>(r >> 8) % kEntries;
    if (r % 6 == 0) k = static_cast<uint32_t>(r >> 8) % 32;
    if (r % 6 == 1) k = kLastNonzero - 8 + static_cast<uint32_t>(r >> 8) % 16;
    items.push_back(item_of(k));
  }
  return items;
}

std::unique_ptr<Model> MaterialFireBlock::golden() const { return std::make_unique<GoldenFire>(); }

std::vector<std::string> MaterialFireBlock::coverage_cases() const {
  return {kOne, kLast, kZero, kTop, kUp, kDown, kEvery, kFall};
}

void MaterialFireBlock::cover(const std::vector<Txn>& items, size_t index, const Txn&,
                              Coverage& cov) const {
  if (index == 0 || index != cover_next_) seen_.assign(kEntries, false);
  cover_next_ = index + 1;
  const auto k = static_cast<uint32_t>(items[index].f[D::in_k]);
  if (k == 0) ++cov[kOne];
  if (k == kLastNonzero) ++cov[kLast];
  if (k > kLastNonzero) ++cov[kZero];
  if (k == kEntries - 1) ++cov[kTop];
  if (k > 0 && k <= kLastNonzero) ++cov[rounded_up(k) ? kUp : kDown];
  if (index > 0 && items[index - 1].f[D::in_k] + 1 == k) ++cov[kFall];
  if (!seen_[k]) {
    seen_[k] = true;
    if (std::all_of(seen_.begin(), seen_.end(), [](bool b) { return b; })) ++cov[kEvery];
  }
}

}  // namespace tmu::tb

TMU_REGISTER_BLOCK(material_fire, MaterialFireBlock)
