#include "blocks/footprint_setup/footprint_setup_block.hpp"

#include <fmt/format.h>

#include <optional>
#include <stdexcept>

#include "blocks/footprint/fragments.hpp"
#include "formats/formats.hpp"
#include "harness/described_engines.hpp"
#include "rtl_models_footprint_setup.hpp"

namespace tmu::tb {
namespace fmts = tmu::formats;
using D = desc::footprint_setup;

namespace {

constexpr int64_t kSide = int64_t{256} << fmts::kTexCoord.frac_bits;  // the nominal texture
// A random run draws a new configuration after this many items.
constexpr size_t kBatch = 2500;

constexpr uint64_t low_bits(const fx::Format& f) { return (uint64_t{1} << f.width()) - 1; }

int32_t signed_field(uint64_t field, const fx::Format& f) {
  return static_cast<int32_t>(
      fx::fit(static_cast<int64_t>(field & low_bits(f)), f, fx::Overflow::kWrap));
}

footprint::Request request_of(const Txn& t) {
  footprint::Request r;
  r.u = signed_field(t.f[D::req_u], fmts::kTexCoord);
  r.v = signed_field(t.f[D::req_v], fmts::kTexCoord);
  r.r1u = signed_field(t.f[D::req_r1u], fmts::kTexDeriv);
  r.r1v = signed_field(t.f[D::req_r1v], fmts::kTexDeriv);
  r.r2u = signed_field(t.f[D::req_r2u], fmts::kTexDeriv);
  r.r2v = signed_field(t.f[D::req_r2v], fmts::kTexDeriv);
  r.shade = static_cast<uint32_t>(t.f[D::req_shade]);
  return r;
}

// footprint::plan on the configuration of the items before; the centre, the shade and the
// longer vector pass through as they came.
class Golden : public Model {
 public:
  explicit Golden(std::shared_ptr<const FootprintSetupBlock> block) : block_(std::move(block)) {}
  void configure(const Txn& cfg) override { config_ = block_->config_of(cfg); }
  void step(const Txn& item, Sink& sink) override {
    if (!config_) throw std::runtime_error("footprint_setup: a fragment before the configuration");
    const footprint::Request r = request_of(item);
    const footprint::Plan p = footprint::plan(r, *config_);
    Txn out;
    out.f[D::plan_u] = item.f[D::req_u];
    out.f[D::plan_v] = item.f[D::req_v];
    out.f[D::plan_du] = item.f[p.r2_longer ? D::req_r2u : D::req_r1u];
    out.f[D::plan_dv] = item.f[p.r2_longer ? D::req_r2v : D::req_r1v];
    out.f[D::plan_shade] = item.f[D::req_shade];
    out.f[D::plan_log2_n] = static_cast<uint64_t>(p.log2_n);
    out.f[D::plan_lambda] = static_cast<uint64_t>(p.lambda) & low_bits(fmts::kLod);
    sink.output(out);
  }
  // Nothing is left in a stage at the end.
  Counters counters() const override { return {{"busy", 0}}; }

 private:
  std::shared_ptr<const FootprintSetupBlock> block_;
  std::optional<footprint::Config> config_;
};

constexpr const char* kAfterCfg = "fragment right after a configuration";

}  // namespace

Txn FootprintSetupBlock::config_item(const footprint::Config& c) {
  return channel_item(D::table(), "cfg",
                      {static_cast<uint64_t>(c.log2_max_probes), static_cast<uint64_t>(c.q_rule)});
}

footprint::Config FootprintSetupBlock::config_of(const Txn& cfg) const {
  footprint::Config c;
  c.log2_max_probes = static_cast<int>(cfg.f[D::cfg_log2_max_probes]);
  c.q_rule = static_cast<footprint::QRule>(cfg.f[D::cfg_q_rule]);
  c.widths = first_.widths;
  return c;
}

Txn FootprintSetupBlock::fragment_item(const footprint::Request& r) {
  return channel_item(D::table(), "req",
                      {static_cast<uint32_t>(r.u), static_cast<uint32_t>(r.v),
                       static_cast<uint32_t>(r.r1u), static_cast<uint32_t>(r.r1v),
                       static_cast<uint32_t>(r.r2u), static_cast<uint32_t>(r.r2v), r.shade});
}

FootprintSetupBlock::FootprintSetupBlock(const BlockOptions& options)
    : DescribedBlockOf(D::table()), options_(options), first_(fragments::first_setup(options)) {
  TMU_ADD_RTL_LEVELS(footprint_setup, variant());
}

std::string FootprintSetupBlock::variant() const { return fragments::setup_variant(first_.widths); }

std::string FootprintSetupBlock::repro_options() const {
  return fragments::setup_repro_options(options_);
}

std::vector<Txn> FootprintSetupBlock::setup_items() const { return {config_item(first_)}; }

std::vector<Txn> FootprintSetupBlock::directed_items() const {
  const std::vector<footprint::Request> fragments = fragments::directed(kSide, kSide);
  std::vector<Txn> items;
  for (const footprint::Request& r : fragments) items.push_back(fragment_item(r));
  // Every maximum probe count with both q rules (what the options leave free), then back to
  // the first configuration, where the random items begin.
  for (int m = 0; m <= fmts::kMaxProbeLog2; ++m) {
    for (const footprint::QRule q : {footprint::QRule::kHeights, footprint::QRule::kSides}) {
      footprint::Config c = first_;
      c.log2_max_probes = options_.fp_log2_max_probes.value_or(m);
      c.q_rule = options_.fp_q_rule.value_or(q);
      items.push_back(config_item(c));
      for (const footprint::Request& r : fragments) items.push_back(fragment_item(r));
    }
  }
  items.push_back(config_item(first_));
  return items;
}

std::vector<Txn> FootprintSetupBlock::random_items(std::mt19937_64& rng, size_t count) const {
  std::vector<Txn> items;
  items.reserve(count);
  size_t next_batch = kBatch;
  while (items.size() < count) {
    if (items.size() >= next_batch) {  // a new configuration, as a driver between batches
      next_batch += kBatch;
      items.push_back(config_item(fragments::draw_setup(rng, options_)));
      continue;
    }
    items.push_back(fragment_item(fragments::random(rng, kSide, kSide)));
  }
  return items;
}

std::unique_ptr<Model> FootprintSetupBlock::golden() const {
  return std::make_unique<Golden>(std::static_pointer_cast<const FootprintSetupBlock>(share()));
}

std::vector<std::string> FootprintSetupBlock::coverage_cases() const {
  std::vector<footprint::QRule> q_rules = {footprint::QRule::kHeights, footprint::QRule::kSides};
  if (options_.fp_q_rule) q_rules = {*options_.fp_q_rule};
  std::vector<int> maxes = {0, 1, 2, 3, 4};
  if (options_.fp_log2_max_probes) maxes = {*options_.fp_log2_max_probes};
  std::vector<std::string> cases = fragments::shape_cases(q_rules, maxes);
  cases.push_back(kAfterCfg);
  return cases;
}

void FootprintSetupBlock::cover(const std::vector<Txn>& items, size_t index, const Txn&,
                                Coverage& cov) const {
  if (index < cover_next_) {
    cover_next_ = 0;
    cover_config_ = first_;
  }
  for (; cover_next_ < index; ++cover_next_) {
    if (D::table().is_cfg(items[cover_next_])) cover_config_ = config_of(items[cover_next_]);
  }
  if (index > 0 && D::table().is_cfg(items[index - 1])) ++cov[kAfterCfg];
  const footprint::Request r = request_of(items[index]);
  footprint::Plan p;
  try {
    p = footprint::plan(r, cover_config_);
  } catch (const std::exception&) {
    return;  // golden reports it
  }
  fragments::cover_shape(r, cover_config_, p, cov);
}

}  // namespace tmu::tb

TMU_REGISTER_BLOCK(footprint_setup, FootprintSetupBlock)
