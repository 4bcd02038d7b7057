#include "texsim/sweep_mipgen.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <sstream>
#include <vector>

#include "common/error.hpp"
#include "common/image.hpp"
#include "common/test_patterns.hpp"
#include "formats/formats.hpp"
#include "texram/mipmap.hpp"
#include "texram/mipmap_ideal.hpp"
#include "texram/texture.hpp"
#include "texsim/sweep_support.hpp"

namespace tmu::texsim {
namespace {

std::vector<int> parse_carries(const std::string& text) {
  std::vector<int> out;
  std::stringstream ss(text);
  for (std::string item; std::getline(ss, item, ';');) {
    size_t end = 0;
    int carry = -1;
    try {
      carry = std::stoi(item, &end);
    } catch (const std::exception&) {
    }
    if (end != item.size() || carry < 0 || carry > texram::kExactCarry) {
      throw InputError("--settings", "",
                       fmt::format("'{}' is not a carry 0..{}", item, texram::kExactCarry));
    }
    out.push_back(carry);
  }
  if (out.empty()) throw InputError("--settings", "", "no settings");
  return out;
}

// The bits tmu_mipgen keeps per carry at MaxLog2 = 10: per stage l, the hold register and the
// line FIFO's 2^(9-l) entries of ChW + 1 + min(2l, carry) bits each.
struct CarryBits {
  long fifo = 0, hold = 0;
};
CarryBits carry_bits(int carry) {
  CarryBits b;
  for (int l = 0; l < formats::kMaxMipLog2; ++l) {
    const long width = formats::kChannel.width() + 1 + texram::carried_bits(l, carry);
    b.fifo += (1L << (formats::kMaxMipLog2 - 1 - l)) * width;
    b.hold += width;
  }
  return b;
}

// Random items of the generator's check: texels of small random frames.
constexpr size_t kMipgenItems = 20000;

}  // namespace

void sweep_mipgen(const MipgenSweepArgs& args) {
  const std::vector<int> carries = parse_carries(args.settings);
  const ImageRgb8 image =
      args.image.empty() ? patterns::smooth_field(512, 512, 7) : read_image(args.image);
  if (!std::has_single_bit(static_cast<unsigned>(image.width)) ||
      !std::has_single_bit(static_cast<unsigned>(image.height)) ||
      image.width > (1 << formats::kMaxMipLog2) || image.height > (1 << formats::kMaxMipLog2)) {
    throw InputError(args.image, "", "the sides must be powers of two up to 1024");
  }
  std::vector<texram::Level8> planes;
  std::vector<std::vector<texram::LevelD>> ideal;
  for (uint8_t (*pick)(Rgb8) :
       {+[](Rgb8 p) { return p.r; }, +[](Rgb8 p) { return p.g; }, +[](Rgb8 p) { return p.b; }}) {
    planes.push_back(texram::plane_of(image, pick));
    ideal.push_back(texram::ideal_pyramid(planes.back()));
  }
  const size_t levels = ideal[0].size() - 1;
  fmt::print(
      "mipgen: {} ({} x {}), R, G and B; each level against the exact box mean of level 0, in "
      "8-bit levels; bits at 1024 x 1024 (MaxLog2 10)\n",
      args.image.empty() ? "the photo-like field" : args.image, image.width, image.height);
  // The errors are golden's pyramid's, the bits a formula; the generator is verilated at the
  // default (exact) carry only, and its block has no carry option (no Icarus run elsewhere).
  std::vector<Column> header = {
      "carry", {"max abs err", Mark::kModel}, {"top mean err", Mark::kModel}};
  for (size_t l = 1; l <= levels; ++l)
    header.emplace_back(fmt::format("L{} mean/max", l), Mark::kModel);
  header.emplace_back("FIFO bits", Mark::kFormula);
  header.emplace_back("hold bits", Mark::kFormula);
  header.emplace_back("rtl = golden", Mark::kSim);
  for (const char* h : {"cells", "logic", "depth"}) header.emplace_back(h, Mark::kSynth);
  SweepTable table(header);
  for (const int carry : carries) {
    std::vector<texram::LevelError> e(levels);
    for (size_t c = 0; c < planes.size(); ++c) {
      const std::vector<texram::LevelError> pe =
          texram::pyramid_error(texram::build_pyramid(planes[c], carry), ideal[c]);
      for (size_t l = 0; l < levels; ++l) {
        e[l].mean += pe[l].mean / static_cast<double>(planes.size());
        e[l].max_abs = std::max(e[l].max_abs, pe[l].max_abs);
      }
    }
    double worst = 0;
    for (const texram::LevelError& le : e) worst = std::max(worst, le.max_abs);
    std::vector<Cell> row = {std::to_string(carry), fmt::format("{:.3f}", worst),
                             fmt::format("{:+.3f}", e.back().mean)};
    for (const texram::LevelError& le : e) {
      row.push_back(fmt::format("{:+.2f}/{:.2f}", le.mean, le.max_abs));
    }
    const CarryBits bits = carry_bits(carry);
    const SynthFigures synth =
        args.synth ? synthesize("tmu_mipgen", {{"CarryBits", carry}}) : SynthFigures{};
    const RtlCheck rtl =
        carry == texram::kExactCarry ? check_rtl("mipgen", {}, kMipgenItems) : RtlCheck{};
    row.push_back(std::to_string(bits.fifo));
    row.push_back(std::to_string(bits.hold));
    row.push_back(rtl.verdict());
    for (const std::string& s : {synth.cells, synth.logic, synth.depth})
      row.push_back(synth_cell(s, rtl.simulated()));
    table.add(row);
    fmt::print("{}\n", table.last_row_text());
  }
  table.print(args.markdown);
}

}  // namespace tmu::texsim
