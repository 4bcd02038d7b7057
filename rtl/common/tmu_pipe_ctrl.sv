/// The control of a pipeline that moves as one (tmu_noise, tmu_specular_combine,
/// tmu_normal_encoder, tmu_cube_address): stages 1 .. NumStages, each a register with a valid
/// bit; the whole pipeline advances when the last stage is empty or being taken, and stalls
/// otherwise. One item per clock while the output is taken.
///
///   advance      = !valid[NumStages] || out_ready_i; it is in_ready_o (the next edge takes
///                  the input exactly when the pipeline moves)
///   valid        shifts by one stage at each advancing edge, in_valid_i entering stage 1
///   load_o[j]    stage j takes stage j - 1's item (stage 1: the input) at this edge: advance
///                and a valid item before it. The user's data registers load on it and keep
///                no reset (they are read only while their stage is valid).
///
/// The last stage is the output register: out_valid_o = valid_o[NumStages]. An item accepted
/// at an edge is on the output NumStages - 1 edges later when nothing stalls.
///
/// Example (NumStages = 2): in_valid_i high at edges 0 and 1, out_ready_i low from edge 1 on:
/// valid_o = 01 after edge 0, 11 after edge 1; then advance is low and both stages hold, and
/// in_ready_o is low until out_ready_i rises.
module tmu_pipe_ctrl #(
  /// Stages, 1 or more.
  parameter int unsigned NumStages = 2
) (
  input  logic                 clk_i,
  input  logic                 rst_ni,

  /// The pipeline's input handshake (its payload goes to the user's stage 1 on load_o[1]).
  input  logic                 in_valid_i,
  output logic                 in_ready_o,

  /// The pipeline's output handshake (the payload is the user's last stage).
  output logic                 out_valid_o,
  input  logic                 out_ready_i,

  /// valid_o[j]: stage j holds an item; load_o[j]: stage j loads at this edge.
  output logic [NumStages:1]   valid_o,
  output logic [NumStages:1]   load_o
);

  if (NumStages < 1) begin : gen_check
    $error("tmu_pipe_ctrl: NumStages must be at least 1");
  end

  logic [NumStages:1] valid_q, shifted;
  logic               advance;

  // {valid_q[NumStages-1:1], in_valid_i}, written as a shift so that one stage works too.
  assign shifted     = (valid_q << 1) | NumStages'(in_valid_i);
  assign advance     = !valid_q[NumStages] || out_ready_i;
  assign in_ready_o  = advance;
  assign load_o      = advance ? shifted : '0;
  assign valid_o     = valid_q;
  assign out_valid_o = valid_q[NumStages];

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      valid_q <= '0;
    end else if (advance) begin
      valid_q <= shifted;
    end
  end

endmodule
