// The icarus level of a described block (tb/harness/described_engines.hpp).
#include <sstream>

#include "harness/described_engines.hpp"
#include "icarus/icarus_engine.hpp"
#include "icarus/testbench.hpp"

namespace tmu::tb {

bool icarus_drives(const BlockPorts& p) {
  return p.cfg_op() < 0 && p.request_channels().empty() && p.response_channels().empty();
}

DescribedBlock::EngineFactory icarus_level(const std::string& top, const std::string& params) {
  std::vector<std::pair<std::string, std::string>> list;  // NAME, VALUE
  std::istringstream words(params);
  for (std::string w; words >> w;) {
    const size_t eq = w.find('=');
    list.emplace_back(w.substr(0, eq), eq == std::string::npos ? "" : w.substr(eq + 1));
  }
  return [top, list](const DescribedBlock& b) {
    IcarusModel model(b.name() + "_tb", top);
    model.text = icarus_testbench(b.port_table(), top, model.testbench, list);
    const std::shared_ptr<const DescribedBlock> shared = b.share();
    return make_icarus_engine("icarus", std::move(model), b.inputs(), b.outputs(),
                              [shared](const Txn& t) { return shared->produces_output(t); });
  };
}

}  // namespace tmu::tb
