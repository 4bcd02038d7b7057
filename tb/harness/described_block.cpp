#include "harness/described_block.hpp"

#include <block_list.hpp>
#include <stdexcept>

namespace tmu::tb {

bool DescribedBlock::produces_output(const Txn& item) const {
  if (ports_.is_cfg(item)) return false;
  const ChannelKind k = ports_.channels()[size_t(ports_.channel_of(item))].kind;
  return k == ChannelKind::kSample || k == ChannelKind::kCombIn || k == ChannelKind::kStream;
}

std::vector<Port> DescribedBlock::ports() const {
  std::vector<Port> out;
  for (const BlockPorts::Port& p : ports_.ports()) out.push_back({p.name, p.width, p.is_signed});
  return out;
}

std::string DescribedBlock::repro_options() const {
#define TMU_VARIANT_OPTIONS(block, key, top, options) \
  if (name() == #block && variant() == key) return options;
  TMU_BLOCK_VARIANTS(TMU_VARIANT_OPTIONS)
#undef TMU_VARIANT_OPTIONS
  return "";
}

std::vector<const Schema*> DescribedBlock::request_schemas() const {
  std::vector<const Schema*> out;
  for (size_t r = 0; r < ports_.request_channels().size(); ++r) {
    out.push_back(&ports_.requests(static_cast<int>(r)));
  }
  return out;
}

ItemPlan DescribedBlock::plan(const std::vector<Txn>& items) const {
  ItemPlan p;
  p.outputs.resize(items.size());
  p.config.resize(items.size());
  bool stream = false;
  for (const PortChannel& c : ports_.channels()) stream |= c.kind == ChannelKind::kStream;
  if (stream) {  // a stream item's outputs depend on the items before it: golden counts them
    const RunResult r = model_engine(*this, "golden")->run(items, RunOptions{});
    if (!r.error.empty()) throw std::runtime_error(name() + ": golden model failed: " + r.error);
    for (const size_t i : r.output_items) ++p.outputs[i];
  }
  for (size_t i = 0; i < items.size(); ++i) {
    p.config[i] = ports_.is_cfg(items[i]);
    if (!stream) p.outputs[i] = produces_output(items[i]) ? 1 : 0;
    p.total += p.outputs[i];
  }
  return p;
}

void DescribedBlock::add_level(const std::string& level, EngineFactory make) {
  levels_.emplace_back(level, std::move(make));
}

std::vector<std::string> DescribedBlock::levels() const {
  std::vector<std::string> out = {"golden"};
  if (ideal()) out.push_back("ideal");
  for (const auto& [level, make] : levels_) out.push_back(level);
  return out;
}

std::unique_ptr<Engine> DescribedBlock::engine(const std::string& level) const {
  if (level == "golden" || (level == "ideal" && ideal())) return model_engine(*this, level);
  for (const auto& [name, make] : levels_) {
    if (name == level) return make(*this);
  }
  std::string known;
  for (const std::string& l : levels()) known += (known.empty() ? "" : ", ") + l;
  throw std::invalid_argument(name() + ": no engine '" + level + "' (levels: " + known + ")");
}

std::unique_ptr<Engine> model_engine(const DescribedBlock& block, const std::string& level) {
  const std::shared_ptr<const DescribedBlock> b = block.share();
  const bool ideal = level == "ideal";
  return std::make_unique<ModelEngine>(
      level, [b, ideal] { return ideal ? b->ideal() : b->golden(); },
      [b](const Txn& t) { return b->port_table().is_cfg(t); },
      b->port_table().request_channels().size());
}

}  // namespace tmu::tb
