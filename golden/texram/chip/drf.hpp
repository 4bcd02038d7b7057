// The TEXRAM chip's description register files (000 §14; docs/texram_chip.md): seven DRFs,
// numbered 1..7, each describing one map in the chip's shared memory and what its sample does
// for the pixel, linked into chains. The rasterizer sends each pixel with the number of its
// leading DRF; the chip walks the links. DRF 7 may hold a cube environment map (six faces).
//
// The write port loads a DRF field by field: DrfWrite {drf 1..7, field, 32-bit value}; the
// packing of each field's value is declared here once (pack_* / apply), and the hardware
// decodes exactly what apply() decodes.
#pragma once

#include <array>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "footprint/q_rule.hpp"
#include "formats/formats.hpp"
#include "texram/detail_definition.hpp"
#include "texram/sampler_config.hpp"

namespace tmu::texram::chip {

inline constexpr int kDrfs = formats::kDrfs;  // DRFs 1..kDrfs
inline constexpr int kCubeDrf = kDrfs;        // the one that may hold six faces
inline constexpr int kCubeFaces = 6;          // +X, -X, +Y, -Y, +Z, -Z (CubeFace)
inline constexpr int kMaxSteps = kDrfs;       // accesses of one pixel: a longer chain is a cycle

// What a DRF's sample does for the pixel (DrfOp).
enum class DrfOp : uint8_t {
  kTexture = 0,      // C_d = eq. 5 (T, I_d) with the DRF's combine and constant k_T
  kShading = 1,      // I_d for the texture after it (a diffuse shading map)
  kReflectance = 2,  // R of eq. 7 for the environment after it
  kEnvironment = 3,  // E (or I_s): C = min(255, C_d + R E / 255) per channel (eq. 6-7)
  kEmit = 4,         // the sample leaves the chip (a bump texel for the deflection unit)
  // A detail map's two DRFs (000 §9), after the texture or reflectance DRF they serve (which
  // has `detail` set and links to them): visited through that DRF only.
  kOffsets = 5,  // the u-offset map; the v-offset map follows it in the memory (offsets_v_base)
  kDetail = 6,   // the detail mipmap
};
inline constexpr int kDrfOps = 7;
std::string_view name(DrfOp op);

// The write port's field numbers (DrfField).
enum class DrfFieldId : uint8_t {
  kBase = 0,          // BankAddr: the map's first cell in every bank
  kShape = 1,         // pack_shape
  kBorderRgba = 2,    // Rgba8888
  kConstantRgba = 3,  // Rgba8888: k_T (texture), the constant R (environment without one)
  kControl = 4,       // pack_control
  kFace0 = 5,         // DRF 7: the bases of faces 0..5 at fields 5..10
};
inline constexpr int kDrfFields = static_cast<int>(DrfFieldId::kFace0) + kCubeFaces;

struct Drf {
  uint32_t base = 0;  // BankAddr
  int log2_w = 0, log2_h = 0;
  // kind, single_channel, filter, border_u, border_v, border_rgba, combine, constant_rgba,
  // addressing; widths are the chip's (the defaults).
  SamplerConfig sampler;
  DrfOp op = DrfOp::kTexture;
  int link = 0;               // next DRF 1..7; 0 ends the chain
  bool takes_coords = false;  // wait for the pixel's next parameter before the access
  // Footprint assembly (000 §10) of the DRF's samples: N trilinear probes along the longer
  // derivative, averaged (footprint/footprint.hpp at the chip's widths), from the parameter's
  // r1, r2. Off: one trilinear sample at the parameter's lambda.
  bool footprint = false;
  int log2_max_probes = 3;  // ProbeLog2 (the field's 5..7 act as 4)
  footprint::QRule q_rule = footprint::QRule::kHeights;
  // Detail maps (000 §9, texram/detail.hpp): below level 0 this DRF's samples come from the
  // offsets DRF it links to and the detail DRF that one links to, combined by detail_combine;
  // the chain goes on at the detail DRF's link.
  bool detail = false;
  DetailCombine detail_combine = DetailCombine::kReplace;
  bool cube = false;  // DRF 7: the six faces below, each log2_w x log2_h
  std::array<uint32_t, kCubeFaces> face_base{};
  friend bool operator==(const Drf&, const Drf&) = default;
};

// DRF n is file[n - 1].
using DrfFile = std::array<Drf, kDrfs>;

struct DrfWrite {
  uint8_t drf = 1;     // DrfIndex 1..7
  uint8_t field = 0;   // DrfField
  uint32_t value = 0;  // DrfValue
  friend bool operator==(const DrfWrite&, const DrfWrite&) = default;
};

// Shape word: log2_w 3:0, log2_h 7:4, kind 10:8, single_channel 12:11, filter 14:13,
// border_u 16:15, border_v 18:17, addressing 19, cube 20.
uint32_t pack_shape(const Drf& d);
// Control word: op 2:0, link 5:3, takes_coords 6, combine 8:7, footprint 9,
// log2_max_probes 12:10, q_rule 13, detail 14, detail_combine 15.
uint32_t pack_control(const Drf& d);

// The writes that load DRF `number` (1..7) with `d`: every field (faces only when d.cube).
std::vector<DrfWrite> drf_writes(int number, const Drf& d);

// What the chip does with a write: the field's bits decoded into the DRF (bits above a field's
// width are ignored; a face write to a DRF other than 7, or a field number above 10, changes
// nothing). Never throws: the hardware takes any word.
void apply(DrfFile& file, const DrfWrite& w);

// A DRF program the host refuses (ProgramError): a link cycle, a chain of more than seven maps,
// a link or leading DRF out of range, a cube map outside DRF 7.
struct ProgramError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Where a v-offset map sits: right after the u-offset map of an offsets DRF (page aligned).
uint32_t offsets_v_base(const Drf& offsets);

// The DRF numbers a pixel led by `lead` visits, in order: lead, its link, ... up to the DRF
// whose link is 0. Throws ProgramError naming the DRFs of a cycle, or when lead is not 1..7.
// (Seven DRFs and no cycle: at most kMaxSteps.)
std::vector<int> chain(const DrfFile& file, int lead);

// Every DRF of `file` that some lead in `leads` reaches is valid: its chain is finite, a cube
// map sits only in DRF 7, a detail DRF is a texture or reflectance DRF linked to an offsets DRF
// linked to a detail DRF. Throws ProgramError.
void check_program(const DrfFile& file, const std::vector<int>& leads);

}  // namespace tmu::texram::chip
