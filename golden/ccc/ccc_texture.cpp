#include "ccc/ccc_texture.hpp"

#include <fstream>
#include <sstream>
#include <stdexcept>

#include "common/atomic_file.hpp"
#include "common/error.hpp"

namespace tmu::ccc {
namespace {

void put_u32(std::string& out, uint32_t v) {
  for (int i = 0; i < 4; ++i) out.push_back(static_cast<char>((v >> (8 * i)) & 0xFF));
}

uint32_t get_u32(std::string_view bytes, size_t at) {
  uint32_t v = 0;
  for (int i = 0; i < 4; ++i) v |= uint32_t{static_cast<uint8_t>(bytes[at + i])} << (8 * i);
  return v;
}

uint64_t block_count(uint64_t w, uint64_t h) { return ((w + 3) / 4) * ((h + 3) / 4); }

}  // namespace

std::string serialize(const Texture& tex) {
  if (tex.width == 0 || tex.height == 0 ||
      tex.blocks.size() != block_count(tex.width, tex.height)) {
    throw std::invalid_argument("ccc::serialize: block count does not match the size");
  }
  std::string out(kMagic);
  put_u32(out, tex.width);
  put_u32(out, tex.height);
  for (const Rgb8& c : tex.clut) {
    out.push_back(static_cast<char>(c.r));
    out.push_back(static_cast<char>(c.g));
    out.push_back(static_cast<char>(c.b));
  }
  for (uint32_t w : tex.blocks) put_u32(out, w);
  return out;
}

Texture parse(std::string_view bytes, const std::string& name) {
  if (bytes.size() < kHeaderBytes) {
    throw InputError(name, "header",
                     "file is " + std::to_string(bytes.size()) + " bytes, shorter than the " +
                         std::to_string(kHeaderBytes) + "-byte header");
  }
  if (bytes.substr(0, 4) != kMagic) throw InputError(name, "magic", "not a CCC1 file");
  Texture tex;
  tex.width = get_u32(bytes, 4);
  tex.height = get_u32(bytes, 8);
  if (tex.width == 0) throw InputError(name, "width", "must be at least 1");
  if (tex.height == 0) throw InputError(name, "height", "must be at least 1");
  const uint64_t n = block_count(tex.width, tex.height);
  const uint64_t expected = kHeaderBytes + 4 * n;
  if (bytes.size() != expected) {
    throw InputError(name, "blocks",
                     std::to_string(tex.width) + "x" + std::to_string(tex.height) + " needs " +
                         std::to_string(n) + " blocks (" + std::to_string(expected) +
                         " bytes in all) but the file has " + std::to_string(bytes.size()) +
                         " bytes");
  }
  for (size_t i = 0; i < 256; ++i) {
    const size_t at = 12 + 3 * i;
    tex.clut[i] = {static_cast<uint8_t>(bytes[at]), static_cast<uint8_t>(bytes[at + 1]),
                   static_cast<uint8_t>(bytes[at + 2])};
  }
  tex.blocks.resize(n);
  for (size_t i = 0; i < n; ++i) tex.blocks[i] = get_u32(bytes, kHeaderBytes + 4 * i);
  return tex;
}

Texture read_ccc(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "", "cannot open");
  std::ostringstream ss;
  ss << in.rdbuf();
  return parse(ss.str(), path);
}

void write_ccc(const std::string& path, const Texture& tex) {
  write_file_atomically(path, serialize(tex));
}

}  // namespace tmu::ccc
