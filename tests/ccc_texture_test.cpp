// The `.ccc` container (golden/ccc/ccc_texture.hpp): round trips, odd sizes, and every
// corrupt input rejected with an InputError that names the offending field.
#include "ccc/ccc_texture.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "common/error.hpp"

namespace tmu::ccc {
namespace {

namespace fs = std::filesystem;

// A texture whose every byte is distinct enough that a misplaced field would show.
Texture sample_texture(uint32_t width, uint32_t height) {
  Texture tex;
  tex.width = width;
  tex.height = height;
  for (size_t i = 0; i < tex.clut.size(); ++i) {
    tex.clut[i] = {static_cast<uint8_t>(i), static_cast<uint8_t>(255 - i),
                   static_cast<uint8_t>(i * 7)};
  }
  tex.blocks.resize(size_t{tex.blocks_wide()} * tex.blocks_high());
  for (size_t i = 0; i < tex.blocks.size(); ++i)
    tex.blocks[i] = static_cast<uint32_t>(0x9E3779B9u * (i + 1));
  return tex;
}

// A fresh directory under the system temp dir, removed when the test ends.
class TempDir {
 public:
  TempDir() {
    path_ = fs::temp_directory_path() /
            ("tmu_ccc_texture_test_" + std::to_string(::getpid()) + "_" +
             ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

// Runs `f`, expecting an InputError for field `field`; returns its message for inspection.
template <typename F>
std::string expect_input_error(F&& f, const std::string& field) {
  try {
    f();
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), field) << e.what();
    return e.what();
  }
  ADD_FAILURE() << "no InputError thrown; expected field '" << field << "'";
  return {};
}

// --- Round trips ----------------------------------------------------------------------

TEST(CccTextureTest, SerializeParseRoundTrip) {
  const Texture tex = sample_texture(16, 12);
  const std::string bytes = serialize(tex);
  EXPECT_EQ(bytes.size(), kHeaderBytes + 4 * 4 * 3);
  EXPECT_EQ(bytes.substr(0, 4), "CCC1");
  EXPECT_EQ(parse(bytes, "mem"), tex);
}

TEST(CccTextureTest, LayoutIsLittleEndianWithClutThenBlocks) {
  Texture tex = sample_texture(4, 4);
  tex.blocks[0] = Block{0x12, 0x34, 0x5678}.word();
  const std::string bytes = serialize(tex);
  const auto byte = [&](size_t i) { return static_cast<uint8_t>(bytes[i]); };
  EXPECT_EQ(byte(4), 4);  // width, low byte first
  EXPECT_EQ(byte(8), 4);
  EXPECT_EQ(byte(12 + 3 * 5 + 1), tex.clut[5].g);
  EXPECT_EQ(byte(kHeaderBytes + 0), 0x78);  // decision bits low byte
  EXPECT_EQ(byte(kHeaderBytes + 2), 0x34);  // index b
  EXPECT_EQ(byte(kHeaderBytes + 3), 0x12);  // index a
}

TEST(CccTextureTest, FileRoundTrip) {
  TempDir dir;
  const std::string path = (dir.path() / "t.ccc").string();
  const Texture tex = sample_texture(33, 17);
  write_ccc(path, tex);
  EXPECT_EQ(read_ccc(path), tex);
  // Only the target remains: the atomic write's temporary is gone.
  EXPECT_EQ(std::distance(fs::directory_iterator(dir.path()), fs::directory_iterator{}), 1);
}

TEST(CccTextureTest, OddSizesCoverPartialBlocks) {
  struct Case {
    uint32_t w, h, blocks_wide, blocks_high;
  };
  for (const Case& c :
       {Case{1, 1, 1, 1}, Case{5, 3, 2, 1}, Case{4097, 1, 1025, 1}, Case{4, 5, 1, 2}}) {
    SCOPED_TRACE(std::to_string(c.w) + "x" + std::to_string(c.h));
    const Texture tex = sample_texture(c.w, c.h);
    EXPECT_EQ(tex.blocks_wide(), c.blocks_wide);
    EXPECT_EQ(tex.blocks_high(), c.blocks_high);
    const std::string bytes = serialize(tex);
    EXPECT_EQ(bytes.size(), kHeaderBytes + 4 * size_t{c.blocks_wide} * c.blocks_high);
    EXPECT_EQ(parse(bytes, "mem"), tex);
  }
}

TEST(CccTextureTest, SerializeRejectsInconsistentBlockCount) {
  Texture tex = sample_texture(8, 8);
  tex.blocks.pop_back();
  EXPECT_THROW(serialize(tex), std::invalid_argument);
  tex = sample_texture(8, 8);
  tex.width = 0;
  EXPECT_THROW(serialize(tex), std::invalid_argument);
}

// --- Corrupt inputs ---------------------------------------------------------------------

TEST(CccTextureTest, ShortHeader) {
  const std::string bytes = serialize(sample_texture(4, 4)).substr(0, kHeaderBytes - 1);
  expect_input_error([&] { parse(bytes, "f"); }, "header");
  expect_input_error([&] { parse("", "f"); }, "header");
}

TEST(CccTextureTest, WrongMagic) {
  std::string bytes = serialize(sample_texture(4, 4));
  bytes[3] = '2';
  expect_input_error([&] { parse(bytes, "f"); }, "magic");
}

TEST(CccTextureTest, ZeroWidthOrHeight) {
  std::string bytes = serialize(sample_texture(4, 4));
  std::string zero_width = bytes;
  zero_width[4] = 0;
  expect_input_error([&] { parse(zero_width, "f"); }, "width");
  std::string zero_height = bytes;
  zero_height[8] = 0;
  expect_input_error([&] { parse(zero_height, "f"); }, "height");
}

TEST(CccTextureTest, TruncatedBlocks) {
  const std::string bytes = serialize(sample_texture(8, 8));
  const std::string msg =
      expect_input_error([&] { parse(bytes.substr(0, bytes.size() - 1), "f"); }, "blocks");
  EXPECT_NE(msg.find("8x8"), std::string::npos) << msg;  // the message explains the size
  expect_input_error([&] { parse(bytes.substr(0, kHeaderBytes), "f"); }, "blocks");
}

TEST(CccTextureTest, TrailingBytes) {
  expect_input_error([&] { parse(serialize(sample_texture(8, 8)) + '\0', "f"); }, "blocks");
}

TEST(CccTextureTest, CorruptFileNamesThePath) {
  TempDir dir;
  const std::string path = (dir.path() / "bad.ccc").string();
  std::ofstream(path, std::ios::binary) << "CCC0 not a texture, but long enough? no.";
  try {
    read_ccc(path);
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), path);
    EXPECT_EQ(e.field(), "header");
  }
}

TEST(CccTextureTest, MissingFile) {
  TempDir dir;
  const std::string path = (dir.path() / "absent.ccc").string();
  expect_input_error([&] { read_ccc(path); }, "");  // no field: the file itself is missing
}

TEST(CccTextureTest, WriteToMissingDirectoryThrowsAndLeavesNothing) {
  TempDir dir;
  const fs::path missing = dir.path() / "no_such_dir";
  const std::string path = (missing / "t.ccc").string();
  EXPECT_THROW(write_ccc(path, sample_texture(4, 4)), InputError);
  EXPECT_FALSE(fs::exists(missing));
  EXPECT_TRUE(fs::is_empty(dir.path()));
}

TEST(CccTextureTest, FailedWriteKeepsThePreviousFile) {
  TempDir dir;
  const std::string path = (dir.path() / "t.ccc").string();
  const Texture good = sample_texture(4, 4);
  write_ccc(path, good);
  Texture bad = sample_texture(4, 4);
  bad.blocks.clear();  // serialize() refuses it before anything is written
  EXPECT_THROW(write_ccc(path, bad), std::invalid_argument);
  EXPECT_EQ(read_ccc(path), good);
}

}  // namespace
}  // namespace tmu::ccc
