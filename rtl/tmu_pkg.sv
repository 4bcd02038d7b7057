// GENERATED from golden/formats/formats.def at configure time (also: texsim formats).
// Do not edit: change the table and regenerate (cmake --build build --target update-formats).
package tmu_pkg;

  // The package declares the formats of every block; each block uses a few.
  // verilator lint_off UNUSEDPARAM

  // TexCoord: SQ16.8, texture coordinate in texels of level 0, texel centres at i + 0.5
  localparam int unsigned TexCoordW = 24;
  localparam int unsigned TexCoordFrac = 8;
  typedef logic signed [TexCoordW-1:0] tex_coord_t;

  // FilterWeight: UQ0.8, bilinear / mip blend weight, 0..255/256
  localparam int unsigned FilterWeightW = 8;
  localparam int unsigned FilterWeightFrac = 8;
  typedef logic [FilterWeightW-1:0] filter_weight_t;

  // Channel: UQ8.0, one colour component
  localparam int unsigned ChannelW = 8;
  localparam int unsigned ChannelFrac = 0;
  typedef logic [ChannelW-1:0] channel_t;

  // Rgb888: UQ24.0, packed colour: R in 23:16, G in 15:8, B in 7:0
  localparam int unsigned Rgb888W = 24;
  localparam int unsigned Rgb888Frac = 0;
  typedef logic [Rgb888W-1:0] rgb888_t;

  // ClutIndex: UQ8.0, colour look-up table address
  localparam int unsigned ClutIndexW = 8;
  localparam int unsigned ClutIndexFrac = 0;
  typedef logic [ClutIndexW-1:0] clut_index_t;

  // TexSize: UQ13.0, texture width or height in texels, 1..4096
  localparam int unsigned TexSizeW = 13;
  localparam int unsigned TexSizeFrac = 0;
  typedef logic [TexSizeW-1:0] tex_size_t;

  // CccBlock: UQ32.0, CCC block word: 31:24 index a, 23:16 index b, 15:0 decision bits
  localparam int unsigned CccBlockW = 32;
  localparam int unsigned CccBlockFrac = 0;
  typedef logic [CccBlockW-1:0] ccc_block_t;

  // CccTexel: UQ4.0, texel address in a 4x4 block: 4*y + x
  localparam int unsigned CccTexelW = 4;
  localparam int unsigned CccTexelFrac = 0;
  typedef logic [CccTexelW-1:0] ccc_texel_t;

  // CccBlockAddr: UQ20.0, CCC block index in texture memory: by * ceil(width/4) + bx
  localparam int unsigned CccBlockAddrW = 20;
  localparam int unsigned CccBlockAddrFrac = 0;
  typedef logic [CccBlockAddrW-1:0] ccc_block_addr_t;

  // Lod: SQ6.8, level of detail lambda = log2 of the footprint size in level-0 texels
  localparam int unsigned LodW = 14;
  localparam int unsigned LodFrac = 8;
  typedef logic signed [LodW-1:0] lod_t;

  // MipLevel: UQ4.0, mipmap level 0..10
  localparam int unsigned MipLevelW = 4;
  localparam int unsigned MipLevelFrac = 0;
  typedef logic [MipLevelW-1:0] mip_level_t;

  // MipLog2: UQ4.0, log2 of a TEXRAM texture side, 0..10
  localparam int unsigned MipLog2W = 4;
  localparam int unsigned MipLog2Frac = 0;
  typedef logic [MipLog2W-1:0] mip_log2_t;

  // MipCoord: UQ10.0, texel (or CCC block) coordinate within a level, 0..1023
  localparam int unsigned MipCoordW = 10;
  localparam int unsigned MipCoordFrac = 0;
  typedef logic [MipCoordW-1:0] mip_coord_t;

  // Bank: UQ3.0, TEXRAM memory bank 0..7: 4 (level & 1) + (x & 1) + 2 (y & 1)
  localparam int unsigned BankW = 3;
  localparam int unsigned BankFrac = 0;
  typedef logic [BankW-1:0] bank_t;

  // BankAddr: UQ21.0, cell address within a bank (8-bit cells)
  localparam int unsigned BankAddrW = 21;
  localparam int unsigned BankAddrFrac = 0;
  typedef logic [BankAddrW-1:0] bank_addr_t;

  // BytePlane: UQ2.0, TEXRAM byte plane 0..3 of a texel: R G B A, or a CCC block word's bytes 31:24 first
  localparam int unsigned BytePlaneW = 2;
  localparam int unsigned BytePlaneFrac = 0;
  typedef logic [BytePlaneW-1:0] byte_plane_t;

  // Rgba8888: UQ32.0, packed colour: R 31:24, G 23:16, B 15:8, A 7:0
  localparam int unsigned Rgba8888W = 32;
  localparam int unsigned Rgba8888Frac = 0;
  typedef logic [Rgba8888W-1:0] rgba8888_t;

  // TexKind: UQ3.0, TEXRAM texel configuration: 0 luminance, 1 index, 2 true colour, 3 single, 4 CCC
  localparam int unsigned TexKindW = 3;
  localparam int unsigned TexKindFrac = 0;
  typedef logic [TexKindW-1:0] tex_kind_t;

  // TexFilter: UQ2.0, TEXRAM filter: 0 nearest, 1 bilinear, 2 trilinear
  localparam int unsigned TexFilterW = 2;
  localparam int unsigned TexFilterFrac = 0;
  typedef logic [TexFilterW-1:0] tex_filter_t;

  // TexBorder: UQ2.0, TEXRAM border operator of an axis: 0 wrap, 1 clamp, 2 border colour, 3 mirror
  localparam int unsigned TexBorderW = 2;
  localparam int unsigned TexBorderFrac = 0;
  typedef logic [TexBorderW-1:0] tex_border_t;

  // TexCombine: UQ2.0, eq. 5 selection: 0 one (T unmodified), 1 constant k_T, 2 shade I_d
  localparam int unsigned TexCombineW = 2;
  localparam int unsigned TexCombineFrac = 0;
  typedef logic [TexCombineW-1:0] tex_combine_t;

  // DetailOffset: UQ8.0, detail map (000 §9): a detail offset map's entry, the first column (row) of a texel's 16 x 16 region in the detail map's level-0 texels (lambda = -4), 0..255
  localparam int unsigned DetailOffsetW = 8;
  localparam int unsigned DetailOffsetFrac = 0;
  typedef logic [DetailOffsetW-1:0] detail_offset_t;

  // TexDetailCombine: UQ1.0, detail map: 0 replace (the detail levels continue the pyramid), 1 modulate (RGB = min(255, T D / 128), A = T's)
  localparam int unsigned TexDetailCombineW = 1;
  localparam int unsigned TexDetailCombineFrac = 0;
  typedef logic [TexDetailCombineW-1:0] tex_detail_combine_t;

  // TexAddressing: UQ1.0, TEXRAM request coordinates: 0 texels (TexCoord), 1 a sphere map's uN, vN (UnitComp)
  localparam int unsigned TexAddressingW = 1;
  localparam int unsigned TexAddressingFrac = 0;
  typedef logic [TexAddressingW-1:0] tex_addressing_t;

  // ClipLog2: UQ4.0, clip-map: log2 of the virtual texture's side, 2..15 (32k)
  localparam int unsigned ClipLog2W = 4;
  localparam int unsigned ClipLog2Frac = 0;
  typedef logic [ClipLog2W-1:0] clip_log2_t;

  // ClipCoord: UQ15.0, clip-map: a texel coordinate in a virtual level, 0..32767
  localparam int unsigned ClipCoordW = 15;
  localparam int unsigned ClipCoordFrac = 0;
  typedef logic [ClipCoordW-1:0] clip_coord_t;

  // ClipBound: UQ16.0, clip-map: a region's bound in a virtual level's texels, 0..32768 (the end exclusive)
  localparam int unsigned ClipBoundW = 16;
  localparam int unsigned ClipBoundFrac = 0;
  typedef logic [ClipBoundW-1:0] clip_bound_t;

  // ClipSubstitution: UQ1.0, clip-map: a wayward sample's substitute: 0 per sample (lambda raised), 1 per tap
  localparam int unsigned ClipSubstitutionW = 1;
  localparam int unsigned ClipSubstitutionFrac = 0;
  typedef logic [ClipSubstitutionW-1:0] clip_substitution_t;

  // PixelCoord: UQ12.0, pixel x or y of a fragment, 0..4095
  localparam int unsigned PixelCoordW = 12;
  localparam int unsigned PixelCoordFrac = 0;
  typedef logic [PixelCoordW-1:0] pixel_coord_t;

  // MaterialId: UQ8.0, index of a fragment's material in its scene
  localparam int unsigned MaterialIdW = 8;
  localparam int unsigned MaterialIdFrac = 0;
  typedef logic [MaterialIdW-1:0] material_id_t;

  // TexDeriv: SQ16.8, a derivative d(u or v)/d(x or y), texels of level 0 per pixel
  localparam int unsigned TexDerivW = 24;
  localparam int unsigned TexDerivFrac = 8;
  typedef logic signed [TexDerivW-1:0] tex_deriv_t;

  // SolidCoord: SQ12.12, solid texture coordinate (object space), for procedural textures
  localparam int unsigned SolidCoordW = 24;
  localparam int unsigned SolidCoordFrac = 12;
  typedef logic signed [SolidCoordW-1:0] solid_coord_t;

  // UnitComp: SQ2.14, a component of a unit vector (normal, view vector)
  localparam int unsigned UnitCompW = 16;
  localparam int unsigned UnitCompFrac = 14;
  typedef logic signed [UnitCompW-1:0] unit_comp_t;

  // ProbeLog2: UQ3.0, footprint assembly: log2 of a probe count N, 0..4 (1..16 probes)
  localparam int unsigned ProbeLog2W = 3;
  localparam int unsigned ProbeLog2Frac = 0;
  typedef logic [ProbeLog2W-1:0] probe_log2_t;

  // QRule: UQ1.0, footprint assembly: the edge length q, 0 the parallelogram's heights, 1 its shorter side
  localparam int unsigned QRuleW = 1;
  localparam int unsigned QRuleFrac = 0;
  typedef logic [QRuleW-1:0] q_rule_t;

  // SpherePhi: UQ9.0, deflection: horizontal angle phi = p * 2pi/512, modulo 512 (001 eq. 12, nodes)
  localparam int unsigned SpherePhiW = 9;
  localparam int unsigned SpherePhiFrac = 0;
  typedef logic [SpherePhiW-1:0] sphere_phi_t;

  // SphereTheta: UQ8.0, deflection: vertical angle theta, bit 7 sign, 6:0 magnitude m: +-m * 2pi/512
  localparam int unsigned SphereThetaW = 8;
  localparam int unsigned SphereThetaFrac = 0;
  typedef logic [SphereThetaW-1:0] sphere_theta_t;

  // S2sEntry: UQ15.0, spherical-to-spherical map entry: 14:7 first-octant phi 0..128, 6:0 theta 0..127
  localparam int unsigned S2sEntryW = 15;
  localparam int unsigned S2sEntryFrac = 0;
  typedef logic [S2sEntryW-1:0] s2s_entry_t;

  // S2sBlockAddr: UQ10.0, spherical-to-spherical map: 4x4 block (k_theta >> 2) * 32 + (k >> 2)
  localparam int unsigned S2sBlockAddrW = 10;
  localparam int unsigned S2sBlockAddrFrac = 0;
  typedef logic [S2sBlockAddrW-1:0] s2s_block_addr_t;

  // MapAccess: UQ2.0, deflection: the map look-up was 0 a hit in the MBR, 1 a miss, 2 bypassed (z = 0)
  localparam int unsigned MapAccessW = 2;
  localparam int unsigned MapAccessFrac = 0;
  typedef logic [MapAccessW-1:0] map_access_t;

  // CoordValue: SQ1.9, coordinate table entry F1..H3 (001 §5), SQ1.9
  localparam int unsigned CoordValueW = 10;
  localparam int unsigned CoordValueFrac = 9;
  typedef logic signed [CoordValueW-1:0] coord_value_t;

  // CoordTableId: UQ3.0, coordinate table: 0 F1 (cos), 1 F2, 2 F3, 3 G2, 4 G3, 5 H2, 6 H3
  localparam int unsigned CoordTableIdW = 3;
  localparam int unsigned CoordTableIdFrac = 0;
  typedef logic [CoordTableIdW-1:0] coord_table_id_t;

  // CoordTableAddr: UQ8.0, coordinate table address: |theta| 0..127, or phi 0..255 (0..180 degrees)
  localparam int unsigned CoordTableAddrW = 8;
  localparam int unsigned CoordTableAddrFrac = 0;
  typedef logic [CoordTableAddrW-1:0] coord_table_addr_t;

  // CubeFace: UQ3.0, cube environment map face 0..5: +X, -X, +Y, -Y, +Z, -Z (OpenGL's order)
  localparam int unsigned CubeFaceW = 3;
  localparam int unsigned CubeFaceFrac = 0;
  typedef logic [CubeFaceW-1:0] cube_face_t;

  // NoiseValue: SQ1.11, Perlin noise P in [-1, 1): lattice values SQ0.7 plus 4 lerp fraction bits
  localparam int unsigned NoiseValueW = 12;
  localparam int unsigned NoiseValueFrac = 11;
  typedef logic signed [NoiseValueW-1:0] noise_value_t;

  // FractalValue: SQ2.14, fractal sum or turbulence of four octaves, |value| <= 1.875
  localparam int unsigned FractalValueW = 16;
  localparam int unsigned FractalValueFrac = 14;
  typedef logic signed [FractalValueW-1:0] fractal_value_t;

  // StatCount: UQ32.0, statistics counter (wraps)
  localparam int unsigned StatCountW = 32;
  localparam int unsigned StatCountFrac = 0;
  typedef logic [StatCountW-1:0] stat_count_t;

  // Flag: UQ1.0, a one-bit enable or flag
  localparam int unsigned FlagW = 1;
  localparam int unsigned FlagFrac = 0;
  typedef logic [FlagW-1:0] flag_t;

  // EnvSeed: UQ32.0, harness only, not a port: the seed of what a block's environment holds (a texture)
  localparam int unsigned EnvSeedW = 32;
  localparam int unsigned EnvSeedFrac = 0;
  typedef logic [EnvSeedW-1:0] env_seed_t;

  // BankByte: UQ8.0, a TEXRAM bank cell's byte: one lane of a memory response
  localparam int unsigned BankByteW = 8;
  localparam int unsigned BankByteFrac = 0;
  typedef logic [BankByteW-1:0] bank_byte_t;

  // EnvPattern: UQ3.0, harness only, not a port: a TEXRAM texture's content: 0 gradient, 1 checker, 2 noise, 3 smooth, 4 random bytes, 5 given (an image file, a scene's texture)
  localparam int unsigned EnvPatternW = 3;
  localparam int unsigned EnvPatternFrac = 0;
  typedef logic [EnvPatternW-1:0] env_pattern_t;

  // MaterialWriteOp: UQ1.0, material unit write: 0 a register, 1 a colour table entry
  localparam int unsigned MaterialWriteOpW = 1;
  localparam int unsigned MaterialWriteOpFrac = 0;
  typedef logic [MaterialWriteOpW-1:0] material_write_op_t;

  // MaterialRegId: UQ4.0, material unit register: 0 kind, 1 g_t, 2 g_v, 3 g_r, 4 g_w, 5 offset, 6 g_l, 7 cutoff, 8 pw, 9 ph, 10 mortar_w, 11 mortar_h; 12..15 ignored
  localparam int unsigned MaterialRegIdW = 4;
  localparam int unsigned MaterialRegIdFrac = 0;
  typedef logic [MaterialRegIdW-1:0] material_reg_id_t;

  // MaterialRegValue: UQ16.0, material unit register value, raw (g_w, offset, cutoff two's complement)
  localparam int unsigned MaterialRegValueW = 16;
  localparam int unsigned MaterialRegValueFrac = 0;
  typedef logic [MaterialRegValueW-1:0] material_reg_value_t;

  // MaterialTable: UQ1.0, material unit colour table: 0 main, 1 mortar
  localparam int unsigned MaterialTableW = 1;
  localparam int unsigned MaterialTableFrac = 0;
  typedef logic [MaterialTableW-1:0] material_table_t;

  // MaterialEntry: UQ8.0, material unit colour table entry 0..127 (a write to 128..255 is ignored)
  localparam int unsigned MaterialEntryW = 8;
  localparam int unsigned MaterialEntryFrac = 0;
  typedef logic [MaterialEntryW-1:0] material_entry_t;

  // FireIndex: UQ9.0, fire's e^-v table index k = clamp(floor(32 v), 0, 511)
  localparam int unsigned FireIndexW = 9;
  localparam int unsigned FireIndexFrac = 0;
  typedef logic [FireIndexW-1:0] fire_index_t;

  // FireEntry: UQ1.12, fire's e^-v table entry round(e^(-k/32) 2^12)
  localparam int unsigned FireEntryW = 13;
  localparam int unsigned FireEntryFrac = 12;
  typedef logic [FireEntryW-1:0] fire_entry_t;

  // PcCoord: SQ8.16, tau unit: a parameter coordinate s or t in tau-grid cells (0 .. cells), carried in a fragment's TexCoord port (same width)
  localparam int unsigned PcCoordW = 24;
  localparam int unsigned PcCoordFrac = 16;
  typedef logic signed [PcCoordW-1:0] pc_coord_t;

  // PcDeriv: SQ8.16, tau unit: ds or dt per pixel in grid cells, carried in a fragment's TexDeriv port
  localparam int unsigned PcDerivW = 24;
  localparam int unsigned PcDerivFrac = 16;
  typedef logic signed [PcDerivW-1:0] pc_deriv_t;

  // TauCells: UQ5.0, tau unit: the grid's cells along s or t, 1..16 (0 acts as 1, above 16 as 16)
  localparam int unsigned TauCellsW = 5;
  localparam int unsigned TauCellsFrac = 0;
  typedef logic [TauCellsW-1:0] tau_cells_t;

  // TauNodeAddr: UQ9.0, tau unit: a node's address i + 17 j (i along s, 0..cells_s; j along t), 0..288
  localparam int unsigned TauNodeAddrW = 9;
  localparam int unsigned TauNodeAddrFrac = 0;
  typedef logic [TauNodeAddrW-1:0] tau_node_addr_t;

  // TauInterp: UQ1.0, tau unit: 0 linear (claim 5), 1 Catmull-Rom spline (claim 6)
  localparam int unsigned TauInterpW = 1;
  localparam int unsigned TauInterpFrac = 0;
  typedef logic [TauInterpW-1:0] tau_interp_t;

  // DrfIndex: UQ3.0, TEXRAM chip: a description register file 1..7 (0: none, as a link the chain's end)
  localparam int unsigned DrfIndexW = 3;
  localparam int unsigned DrfIndexFrac = 0;
  typedef logic [DrfIndexW-1:0] drf_index_t;

  // DrfField: UQ4.0, TEXRAM chip DRF write: 0 base, 1 shape, 2 border colour, 3 constant, 4 control, 5..10 cube faces +X..-Z (DRF 7)
  localparam int unsigned DrfFieldW = 4;
  localparam int unsigned DrfFieldFrac = 0;
  typedef logic [DrfFieldW-1:0] drf_field_t;

  // DrfValue: UQ32.0, TEXRAM chip DRF write: a field's value (golden/texram/chip/drf.hpp packs them)
  localparam int unsigned DrfValueW = 32;
  localparam int unsigned DrfValueFrac = 0;
  typedef logic [DrfValueW-1:0] drf_value_t;

  // DrfOp: UQ3.0, TEXRAM chip: what a DRF's sample does: 0 texture (eq. 5), 1 shading map (I_d), 2 reflectance (R), 3 environment (E, eq. 6-7, ends the pixel), 4 emit (leaves the chip)
  localparam int unsigned DrfOpW = 3;
  localparam int unsigned DrfOpFrac = 0;
  typedef logic [DrfOpW-1:0] drf_op_t;

  // VoxelPos: SQ10.16, volume: a resample coordinate in voxels, voxel centres at integers (the marcher's 26-bit accumulator)
  localparam int unsigned VoxelPosW = 26;
  localparam int unsigned VoxelPosFrac = 16;
  typedef logic signed [VoxelPosW-1:0] voxel_pos_t;

  // VoxelStep: SQ4.16, volume: a ray's step per resample, voxels, |step| < 8
  localparam int unsigned VoxelStepW = 20;
  localparam int unsigned VoxelStepFrac = 16;
  typedef logic signed [VoxelStepW-1:0] voxel_step_t;

  // VoxelCount: UQ16.0, volume: resample locations of a ray, 0..65535
  localparam int unsigned VoxelCountW = 16;
  localparam int unsigned VoxelCountFrac = 0;
  typedef logic [VoxelCountW-1:0] voxel_count_t;

  // VolumeSize: UQ10.0, volume: voxels along an axis, 2..512
  localparam int unsigned VolumeSizeW = 10;
  localparam int unsigned VolumeSizeFrac = 0;
  typedef logic [VolumeSizeW-1:0] volume_size_t;

  // VolumeMode: UQ1.0, volume: 0 value (an RGBA component, two accesses), 1 raw (value and gradient, eight)
  localparam int unsigned VolumeModeW = 1;
  localparam int unsigned VolumeModeFrac = 0;
  typedef logic [VolumeModeW-1:0] volume_mode_t;

  // VolumeGrad: SQ9.4, volume: a gradient component in voxel values per voxel (central differences / 2, interpolated)
  localparam int unsigned VolumeGradW = 13;
  localparam int unsigned VolumeGradFrac = 4;
  typedef logic signed [VolumeGradW-1:0] volume_grad_t;

  // VolumeWeightBits: UQ4.0, volume: W, the weight bits per axis of the trilinear blend, 1..8
  localparam int unsigned VolumeWeightBitsW = 4;
  localparam int unsigned VolumeWeightBitsFrac = 0;
  typedef logic [VolumeWeightBitsW-1:0] volume_weight_bits_t;

  // VolumePattern: UQ2.0, harness only, not a port: what a volume holds: 0 random bytes, 1 Marschner-Lobb, 2 sphere distance field, 3 linear ramp
  localparam int unsigned VolumePatternW = 2;
  localparam int unsigned VolumePatternFrac = 0;
  typedef logic [VolumePatternW-1:0] volume_pattern_t;

  // VideoFlags: UQ4.0, video port item: bit 0 first of frame, 1 first of field, 2 first of line, 3 field 2 (an odd line of an interlaced frame)
  localparam int unsigned VideoFlagsW = 4;
  localparam int unsigned VideoFlagsFrac = 0;
  typedef logic [VideoFlagsW-1:0] video_flags_t;

  // VideoTexel: UQ32.0, video port item: the texel's bytes, plane 0 in 31:24 (R G B A; one-plane video: 31:24)
  localparam int unsigned VideoTexelW = 32;
  localparam int unsigned VideoTexelFrac = 0;
  typedef logic [VideoTexelW-1:0] video_texel_t;

  // VideoError: UQ2.0, video receiver: an item's error: 0 none, 1 flags not those of its place (the frame under way dropped), 2 field order (a first-of-frame item flagged field 2)
  localparam int unsigned VideoErrorW = 2;
  localparam int unsigned VideoErrorFrac = 0;
  typedef logic [VideoErrorW-1:0] video_error_t;

  // VideoTag: UQ16.0, video row buffers: a frame's tag (its number, wrapping), and the arbiter's cycle stamps and waits
  localparam int unsigned VideoTagW = 16;
  localparam int unsigned VideoTagFrac = 0;
  typedef logic [VideoTagW-1:0] video_tag_t;

  // largest texture side in texels
  localparam int unsigned MaxTexSize = 4096;

  // colour look-up table entries
  localparam int unsigned ClutEntries = 256;

  // CCC block side in texels
  localparam int unsigned CccBlockSide = 4;

  // entries of the low-cost unit's decoded-block cache
  localparam int unsigned CccCacheEntries = 4;

  // TEXRAM: largest texture side is 2^10 = 1024 texels
  localparam int unsigned MaxMipLog2 = 10;

  // clip-map: largest virtual texture side is 2^15 = 32768 texels
  localparam int unsigned MaxClipLog2 = 15;

  // TEXRAM memory banks
  localparam int unsigned Banks = 8;

  // TEXRAM chip: description register files, numbered 1..7; 7 holds a cube map
  localparam int unsigned Drfs = 7;

  // TEXRAM memory: a DRAM page holds 2^9 = 512 cells of a bank (the page model; maps, and a v-offset map after its u map, start on a page)
  localparam int unsigned PageLog2 = 9;

  // footprint assembly: at most 2^4 = 16 probes per fragment
  localparam int unsigned MaxProbeLog2 = 4;

  // entries of a spherical-to-spherical map block (4 x 4)
  localparam int unsigned S2sBlockEntries = 16;

  // noise hash: row 0 of the 12 x 12 xor table T (bit 0 of T(x) = parity of x & row)
  localparam int unsigned NoiseXorRow0 = 3787;

  // noise hash: row 1 of the 12 x 12 xor table T (bit 1 of T(x) = parity of x & row)
  localparam int unsigned NoiseXorRow1 = 1655;

  // noise hash: row 2 of the 12 x 12 xor table T (bit 2 of T(x) = parity of x & row)
  localparam int unsigned NoiseXorRow2 = 1294;

  // noise hash: row 3 of the 12 x 12 xor table T (bit 3 of T(x) = parity of x & row)
  localparam int unsigned NoiseXorRow3 = 2489;

  // noise hash: row 4 of the 12 x 12 xor table T (bit 4 of T(x) = parity of x & row)
  localparam int unsigned NoiseXorRow4 = 883;

  // noise hash: row 5 of the 12 x 12 xor table T (bit 5 of T(x) = parity of x & row)
  localparam int unsigned NoiseXorRow5 = 2433;

  // noise hash: row 6 of the 12 x 12 xor table T (bit 6 of T(x) = parity of x & row)
  localparam int unsigned NoiseXorRow6 = 1895;

  // noise hash: row 7 of the 12 x 12 xor table T (bit 7 of T(x) = parity of x & row)
  localparam int unsigned NoiseXorRow7 = 1745;

  // noise hash: row 8 of the 12 x 12 xor table T (bit 8 of T(x) = parity of x & row)
  localparam int unsigned NoiseXorRow8 = 4010;

  // noise hash: row 9 of the 12 x 12 xor table T (bit 9 of T(x) = parity of x & row)
  localparam int unsigned NoiseXorRow9 = 2768;

  // noise hash: row 10 of the 12 x 12 xor table T (bit 10 of T(x) = parity of x & row)
  localparam int unsigned NoiseXorRow10 = 3597;

  // noise hash: row 11 of the 12 x 12 xor table T (bit 11 of T(x) = parity of x & row)
  localparam int unsigned NoiseXorRow11 = 489;

  // byte planes of a texel (true colour R G B A) or of a CCC block word
  localparam int unsigned Planes = 4;

  // detail map: a level-0 texel's region is 16 x 16 texels of level -4
  localparam int unsigned DetailRegionSide = 16;

  // detail map: the levels below level 0, lambda = -1 .. -4
  localparam int unsigned DetailLevels = 4;

  // volume: the cells of a brick in a bank (8 x 4 x 16: 16 x 8 x 16 voxels), one DRAM page
  localparam int unsigned VolumeBrickCells = 512;

  // detail map: the largest side is 2^8 = 256 texels (8-bit offsets)
  localparam int unsigned MaxDetailLog2 = 8;

  // tau unit: the most grid cells along s or t (17 x 17 nodes)
  localparam int unsigned TauMaxCells = 16;

  // verilator lint_on UNUSEDPARAM

endpackage
