#include "texram/chip/drf.hpp"

#include <algorithm>
#include <optional>

#include "texram/layout.hpp"
#include "texram/page_model.hpp"

namespace tmu::texram::chip {
namespace {

uint32_t bits(uint32_t word, int lo, int width) { return (word >> lo) & ((1u << width) - 1u); }

constexpr int kBaseBits = formats::kBankAddr.width();

}  // namespace

std::string_view name(DrfOp op) {
  switch (op) {
    case DrfOp::kTexture:
      return "texture";
    case DrfOp::kShading:
      return "shading";
    case DrfOp::kReflectance:
      return "reflectance";
    case DrfOp::kEnvironment:
      return "environment";
    case DrfOp::kEmit:
      return "emit";
    case DrfOp::kOffsets:
      return "offsets";
    case DrfOp::kDetail:
      return "detail";
  }
  return "?";
}

uint32_t pack_shape(const Drf& d) {
  const SamplerConfig& s = d.sampler;
  return static_cast<uint32_t>(d.log2_w) | static_cast<uint32_t>(d.log2_h) << 4 |
         static_cast<uint32_t>(s.kind) << 8 | static_cast<uint32_t>(s.single_channel) << 11 |
         static_cast<uint32_t>(s.filter) << 13 | static_cast<uint32_t>(s.border_u) << 15 |
         static_cast<uint32_t>(s.border_v) << 17 | static_cast<uint32_t>(s.addressing) << 19 |
         static_cast<uint32_t>(d.cube) << 20;
}

uint32_t pack_control(const Drf& d) {
  return static_cast<uint32_t>(d.op) | static_cast<uint32_t>(d.link) << 3 |
         static_cast<uint32_t>(d.takes_coords) << 6 |
         static_cast<uint32_t>(d.sampler.combine) << 7 | static_cast<uint32_t>(d.footprint) << 9 |
         static_cast<uint32_t>(d.log2_max_probes) << 10 | static_cast<uint32_t>(d.q_rule) << 13 |
         static_cast<uint32_t>(d.detail) << 14 | static_cast<uint32_t>(d.detail_combine) << 15;
}

std::vector<DrfWrite> drf_writes(int number, const Drf& d) {
  const auto n = static_cast<uint8_t>(number);
  const auto w = [n](DrfFieldId f, uint32_t v) { return DrfWrite{n, static_cast<uint8_t>(f), v}; };
  std::vector<DrfWrite> out = {w(DrfFieldId::kBase, d.base), w(DrfFieldId::kShape, pack_shape(d)),
                               w(DrfFieldId::kBorderRgba, d.sampler.border_rgba),
                               w(DrfFieldId::kConstantRgba, d.sampler.constant_rgba),
                               w(DrfFieldId::kControl, pack_control(d))};
  if (d.cube) {
    for (int f = 0; f < kCubeFaces; ++f) {
      out.push_back({n, static_cast<uint8_t>(static_cast<int>(DrfFieldId::kFace0) + f),
                     d.face_base[static_cast<size_t>(f)]});
    }
  }
  return out;
}

void apply(DrfFile& file, const DrfWrite& w) {
  const int number = w.drf & 7;
  if (number < 1) return;  // DRF 0 does not exist: the write is dropped
  Drf& d = file[static_cast<size_t>(number - 1)];
  const uint32_t v = w.value;
  switch (static_cast<DrfFieldId>(w.field & 15)) {
    case DrfFieldId::kBase:
      d.base = bits(v, 0, kBaseBits);
      return;
    case DrfFieldId::kShape:
      d.log2_w = static_cast<int>(bits(v, 0, 4));
      d.log2_h = static_cast<int>(bits(v, 4, 4));
      d.sampler.kind = static_cast<TexelKind>(bits(v, 8, 3));
      d.sampler.single_channel = static_cast<int>(bits(v, 11, 2));
      d.sampler.filter = static_cast<Filter>(bits(v, 13, 2));
      d.sampler.border_u = static_cast<Border>(bits(v, 15, 2));
      d.sampler.border_v = static_cast<Border>(bits(v, 17, 2));
      d.sampler.addressing = static_cast<Addressing>(bits(v, 19, 1));
      d.cube = bits(v, 20, 1) != 0;
      return;
    case DrfFieldId::kBorderRgba:
      d.sampler.border_rgba = v;
      return;
    case DrfFieldId::kConstantRgba:
      d.sampler.constant_rgba = v;
      return;
    case DrfFieldId::kControl:
      d.op = static_cast<DrfOp>(bits(v, 0, 3));
      d.link = static_cast<int>(bits(v, 3, 3));
      d.takes_coords = bits(v, 6, 1) != 0;
      d.sampler.combine = static_cast<Combine>(bits(v, 7, 2));
      d.footprint = bits(v, 9, 1) != 0;
      d.log2_max_probes = static_cast<int>(bits(v, 10, 3));
      d.q_rule = static_cast<footprint::QRule>(bits(v, 13, 1));
      d.detail = bits(v, 14, 1) != 0;
      d.detail_combine = static_cast<DetailCombine>(bits(v, 15, 1));
      return;
    default:
      break;
  }
  const int face = (w.field & 15) - static_cast<int>(DrfFieldId::kFace0);
  if (number == kCubeDrf && face >= 0 && face < kCubeFaces)
    d.face_base[static_cast<size_t>(face)] = bits(v, 0, kBaseBits);
}

uint32_t offsets_v_base(const Drf& offsets) {
  const Geometry g(offsets.log2_w, offsets.log2_h);  // one byte plane: the offsets are bytes
  return offsets.base + page_up(g.bank_cells());
}

std::vector<int> chain(const DrfFile& file, int lead) {
  if (lead < 1 || lead > kDrfs) {
    throw ProgramError("leading DRF " + std::to_string(lead) + " is not 1.." +
                       std::to_string(kDrfs));
  }
  std::vector<int> out;
  for (int n = lead; n != 0; n = file[static_cast<size_t>(n - 1)].link) {
    if (std::find(out.begin(), out.end(), n) != out.end()) {
      std::string path;
      for (int m : out) path += std::to_string(m) + " -> ";
      throw ProgramError("link cycle: DRF " + path + std::to_string(n));
    }
    if (n > kDrfs)
      throw ProgramError("DRF " + std::to_string(out.back()) + " links to " + std::to_string(n) +
                         ", not 1.." + std::to_string(kDrfs));
    out.push_back(n);
  }
  return out;
}

void check_program(const DrfFile& file, const std::vector<int>& leads) {
  for (int lead : leads) {
    for (int n : chain(file, lead)) {
      const Drf& d = file[static_cast<size_t>(n - 1)];
      if (d.cube && n != kCubeDrf) {
        throw ProgramError("DRF " + std::to_string(n) + " holds a cube map: only DRF " +
                           std::to_string(kCubeDrf) + " can");
      }
      if (d.detail) {
        const auto op_of = [&](int m) {
          return m == 0 ? std::optional<DrfOp>() : file[static_cast<size_t>(m - 1)].op;
        };
        const int o = d.link, dm = o == 0 ? 0 : file[static_cast<size_t>(o - 1)].link;
        if ((d.op != DrfOp::kTexture && d.op != DrfOp::kReflectance) ||
            op_of(o) != DrfOp::kOffsets || op_of(dm) != DrfOp::kDetail) {
          throw ProgramError("DRF " + std::to_string(n) +
                             " has a detail map: it must be a texture or reflectance DRF linked to "
                             "an offsets DRF linked to a detail DRF");
        }
      }
      if (static_cast<int>(d.op) >= kDrfOps) {
        throw ProgramError("DRF " + std::to_string(n) + ": op " +
                           std::to_string(static_cast<int>(d.op)) + " is not an operation");
      }
    }
  }
}

}  // namespace tmu::texram::chip
