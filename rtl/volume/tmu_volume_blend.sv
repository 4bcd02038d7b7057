/// One pass of the volume unit's blend (golden volume::blend, golden/volume/unit.cpp): from the
/// bytes a location's accesses delivered, the eight samples of the pass through the trilinear
/// interpolator (tmu_volume_trilerp) and the pass's one rounding, half up:
///   pass 0     the corner voxels -> the value, 0..255 (Channel), the sum rounded by 24 bits
///   pass 1..3  the central differences D along x, y, z at the corners -> the gradient
///              component, VolumeGrad SQ9.4, the sum rounded by 21 bits (D has one fraction
///              bit of the gradient, the result keeps three more)
/// Combinational. The 8-bit weights stand for golden's W-bit ones (tmu_volume_axis says why the
/// results are the same bit for bit).
///
/// Where the samples are (docs/volume.md, the access order): access a's bank b byte at
/// data_i[32 a + 8 b +: 8]; accesses 0, 1 read the corners of slices k0, k1; 2, 3 the
/// x-neighbours i0 - 1, i0 + 2 in k0, k1; 4, 5 the y-neighbours; 6, 7 the slices k0 - 1 and
/// k0 + 2. Corner c = cx + 2 cy + 4 cz lies in bank (x parity) + 2 (y parity), its x being i0,
/// or i1 = i0 + 1 (of the other parity) unless the axis is clamped (same: i1 = i0).
///
/// D at a corner x along an axis: f(x + 1) - f(x - 1); on the first voxel 2 (f(1) - f(0)), on
/// the last 2 (f(n-1) - f(n-2)) (the field continued linearly: golden's rule). Corner x = i0
/// (or the clamped i1) takes f(x - 1) from the neighbour access and f(x + 1) from the other
/// corner; corner x = i0 + 1 takes f(x - 1) from the corner i0 and f(x + 1) from the
/// neighbour access. D (-510 .. 510) enters the interpolator as D + 512 (0 .. 1022, unsigned):
/// the weights sum to 2^24, so the sum is 512 2^24 too large, 4096 after the rounding shift.
///
/// Per axis, info_i[12 a +: 12] = {inner2, first, same, i0 parity, w[7:0]} (tmu_volume_axis).
module tmu_volume_blend (
  input  logic [8*32-1:0]           data_i,
  input  logic [3*12-1:0]           info_i,
  /// 0 the value, 1 + a the gradient along axis a.
  input  logic [1:0]                pass_i,
  output tmu_pkg::channel_t         value_o,
  output tmu_pkg::volume_grad_t     grad_o
);

  localparam int unsigned GW = tmu_pkg::VolumeGradW;  // 13

  if (GW != 13 || tmu_pkg::VolumeGradFrac != 4) begin : gen_check
    $error("tmu_volume_blend: built for VolumeGrad SQ9.4");
  end

  logic [2:0] p0, same, first, inner2;
  logic [7:0] w [3];
  for (genvar a = 0; a < 3; a++) begin : gen_info
    assign w[a]      = info_i[12*a +: 8];
    assign p0[a]     = info_i[12*a + 8];
    assign same[a]   = info_i[12*a + 9];
    assign first[a]  = info_i[12*a + 10];
    assign inner2[a] = info_i[12*a + 11];
  end

  // The parity of a corner's coordinate along axis a (c: 0 the corner i0, 1 the corner i1).
  function automatic logic parity(input logic [2:0] p0_v, input logic [2:0] same_v,
                                  input logic [1:0] a, input logic c);
    parity = c && !same_v[a] ? !p0_v[a] : p0_v[a];
  endfunction

  function automatic logic [7:0] byte_at(input logic [8*32-1:0] data, input int access,
                                         input logic [1:0] bank);
    byte_at = data[32*access + 8*32'(bank) +: 8];
  endfunction

  // The corner voxels.
  logic [8*8-1:0] v;
  for (genvar k = 0; k < 8; k++) begin : gen_corner
    assign v[k*8 +: 8] = byte_at(data_i, (k >> 2) & 1,
                                 {parity(p0, same, 2'd1, ((k >> 1) & 1) != 0),
                                  parity(p0, same, 2'd0, (k & 1) != 0)});
  end

  // Per axis a and corner k, the central difference D (10 bits signed) in d[a][k*10 +: 10].
  logic [8*10-1:0] d [3];
  for (genvar a = 0; a < 3; a++) begin : gen_axis
    for (genvar k = 0; k < 8; k++) begin : gen_corner
      localparam bit Cx = (k & 1) != 0;
      localparam bit Cy = ((k >> 1) & 1) != 0;
      localparam bit Cz = ((k >> 2) & 1) != 0;
      localparam bit C  = a == 0 ? Cx : a == 1 ? Cy : Cz;
      localparam int K0 = k & ~(1 << a);  // the same corner at i0 and at i1 along axis a
      localparam int K1 = k | (1 << a);
      logic [1:0] bank_lo, bank_hi;
      logic [7:0] nb_lo, nb_hi, here, m, p;
      logic       at0, is_first, is_last;
      // The neighbours' banks and bytes: along x in access 2 + cz, along y in 4 + cz (i0 - 1
      // has the other parity than i0, i0 + 2 the same), along z in 6 and 7 (the corner's own
      // bank).
      if (a == 0) begin : gen_x
        assign bank_lo = {parity(p0, same, 2'd1, Cy), !p0[0]};
        assign bank_hi = {parity(p0, same, 2'd1, Cy), p0[0]};
        assign nb_lo   = byte_at(data_i, Cz ? 3 : 2, bank_lo);
        assign nb_hi   = byte_at(data_i, Cz ? 3 : 2, bank_hi);
      end else if (a == 1) begin : gen_y
        assign bank_lo = {!p0[1], parity(p0, same, 2'd0, Cx)};
        assign bank_hi = {p0[1], parity(p0, same, 2'd0, Cx)};
        assign nb_lo   = byte_at(data_i, Cz ? 5 : 4, bank_lo);
        assign nb_hi   = byte_at(data_i, Cz ? 5 : 4, bank_hi);
      end else begin : gen_z
        assign bank_lo = {parity(p0, same, 2'd1, Cy), parity(p0, same, 2'd0, Cx)};
        assign bank_hi = bank_lo;
        assign nb_lo   = byte_at(data_i, 6, bank_lo);
        assign nb_hi   = byte_at(data_i, 7, bank_hi);
      end
      assign here     = v[k*8 +: 8];
      assign at0      = !C || same[a];
      assign m        = at0 ? nb_lo : v[K0*8 +: 8];
      assign p        = at0 ? v[K1*8 +: 8] : nb_hi;
      assign is_first = at0 && first[a];
      assign is_last  = at0 ? same[a] : !inner2[a];
      assign d[a][k*10 +: 10] = is_first ? {1'b0, p, 1'b0} - {1'b0, here, 1'b0}
                              : is_last  ? {1'b0, here, 1'b0} - {1'b0, m, 1'b0}
                                         : {2'b0, p} - {2'b0, m};
    end
  end

  // The pass's samples, unsigned: the voxels, or D + 512 (D's sign bit flipped).
  logic [8*10-1:0] samples, voxels, bias;
  for (genvar k = 0; k < 8; k++) begin : gen_sample
    assign voxels[k*10 +: 10] = {2'b0, v[k*8 +: 8]};
    assign bias[k*10 +: 10]   = 10'h200;
  end
  always_comb begin
    unique case (pass_i)
      2'd0:    samples = voxels;
      2'd1:    samples = d[0] ^ bias;
      2'd2:    samples = d[1] ^ bias;
      default: samples = d[2] ^ bias;
    endcase
  end

  logic [33:0] sum;
  tmu_volume_trilerp u_trilerp (
    .c_i   (samples),
    .wx_i  (w[0]),
    .wy_i  (w[1]),
    .wz_i  (w[2]),
    .sum_o (sum)
  );

  // Half up: add half of the dropped unit, shift. The value fits 8 bits (the samples do);
  // the gradient is (D + 512) blended, 4096 too large after the shift of 21.
  logic [33:0] value_sum, grad_sum;
  assign value_sum = sum + 34'(1 << 23);
  assign grad_sum  = sum + 34'(1 << 20);
  assign value_o   = value_sum[24 +: 8];
  assign grad_o    = GW'(grad_sum[33:21] - 13'd4096);

  logic unused_bits;
  assign unused_bits = ^{value_sum[33:32], value_sum[23:0], grad_sum[20:0]};

endmodule
