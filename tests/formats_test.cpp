// The interface format table: the checked-in SystemVerilog package is exactly what the
// table generates, so the RTL cannot drift from the C++ widths.
#include "formats/formats.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace tmu::formats {
namespace {

TEST(FormatsTest, SvPackageMatchesTable) {
  const std::filesystem::path path = std::filesystem::path(TMU_SOURCE_DIR) / "rtl" / "tmu_pkg.sv";
  std::ifstream in(path);
  ASSERT_TRUE(in) << "cannot open " << path;
  std::stringstream checked_in;
  checked_in << in.rdbuf();
  EXPECT_EQ(checked_in.str(), sv_package())
      << path << " is out of date; run: cmake --build build --target update-formats";
}

TEST(FormatsTest, TableDeclaresTheWidthsTheModelsRelyOn) {
  EXPECT_EQ(kTexCoord.width(), 24);
  EXPECT_GE(kTexCoord.frac_bits, 8);  // D3D11: at least 8 sub-texel bits
  EXPECT_EQ(kFilterWeight.width(), 8);
  EXPECT_EQ(kCccBlock.width(), 32);
  EXPECT_EQ(kCccTexel.width(), 4);
  EXPECT_EQ(1 << kCccTexel.width(), kCccBlockSide * kCccBlockSide);
  EXPECT_EQ(1 << kClutIndex.width(), kClutEntries);
  EXPECT_GE(int64_t{1} << kTexSize.width(), kMaxTexSize + 1);
  EXPECT_GE(int64_t{1} << kCccBlockAddr.width(),
            int64_t{kMaxTexSize / kCccBlockSide} * (kMaxTexSize / kCccBlockSide));
}

}  // namespace
}  // namespace tmu::formats
