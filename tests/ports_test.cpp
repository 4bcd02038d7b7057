// Every block's port description against its RTL: a module with exactly the description's
// ports (name, direction, width) around each top of the block's variants, linted by Verilator
// with -Wall (tb/icarus/testbench.hpp). A port the RTL lacks or has in another width, or one
// the description leaves out, is a warning, so the test fails.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include "blocks/registry.hpp"
#include "harness/described_block.hpp"
#include "icarus/icarus_engine.hpp"
#include "icarus/testbench.hpp"
#include "tests/cosim_test_support.hpp"

namespace tmu::tb {
namespace {

namespace fs = std::filesystem;

class PortsTest : public ::testing::TestWithParam<BlockVariant> {};

TEST_P(PortsTest, DescriptionMatchesTheRtl) {
  const BlockVariant& v = GetParam();
  const auto block = make_block(v.block, BlockOptions{});
  const auto* described = dynamic_cast<const DescribedBlock*>(block.get());
  ASSERT_NE(described, nullptr);
  const fs::path dir = testing::temp_dir("tmu_ports_test") / (v.block + "_" + v.top);
  fs::create_directories(dir);
  const fs::path check = dir / (v.block + "_port_check.sv");
  std::ofstream(check) << port_check(described->port_table(), v.top);
  std::string cmd =
      fmt::format("{} --lint-only -Wall --top-module {}_port_check", TMU_VERILATOR, v.block);
  // Verilator reads the handshake checker that the blocks' files bind right after the package
  // (rtl/manifest.txt's header: never listed, so not among manifest_sources()).
  std::vector<std::string> sources = manifest_sources(v.top);
  sources.insert(sources.begin() + 1, "common/tmu_stream_check.sv");
  for (const std::string& s : sources) {
    cmd += fmt::format(" {}", (fs::path(TMU_SOURCE_DIR) / "rtl" / s).string());
  }
  // and the binds of the top's description, which name its ports too.
  if (const fs::path binds = fs::path(TMU_BINDS_DIR) / (v.top + "_binds.sv"); fs::exists(binds)) {
    cmd += " " + binds.string();
  }
  cmd += fmt::format(" {} > {} 2>&1", check.string(), (dir / "lint.log").string());
  const int rc = std::system(cmd.c_str());
  std::ifstream log(dir / "lint.log");
  const std::string text((std::istreambuf_iterator<char>(log)), std::istreambuf_iterator<char>());
  EXPECT_EQ(rc, 0) << cmd << "\n" << text;
}

// One case per distinct top of each block.
std::vector<BlockVariant> tops() {
  std::vector<BlockVariant> out;
  std::set<std::pair<std::string, std::string>> seen;
  for (const BlockVariant& v : block_variants()) {
    if (seen.insert({v.block, v.top}).second) out.push_back(v);
  }
  return out;
}

INSTANTIATE_TEST_SUITE_P(Blocks, PortsTest, ::testing::ValuesIn(tops()),
                         [](const ::testing::TestParamInfo<BlockVariant>& p) {
                           return p.param.block + "_" + p.param.top;
                         });

}  // namespace
}  // namespace tmu::tb
