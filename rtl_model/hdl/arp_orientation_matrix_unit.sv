// Orientation matrix unit: the rotated lens vector r = M v, the datapath's
// rotate() (rtl_model/datapath/OrientationMatrixUnit.hpp) in hardware.
//   stage 1: nine signed MAT_W x VEC_W products, registered
//   stage 2: three 3-term sums, rounding shift to ROT_FRAC, saturation to
//            ROT_FRAC + 2 bits, registered
//   LATENCY - 2 further registers (LATENCY >= 2 is the minimum).
// The matrix is an input sampled with the vector: the orientation register
// that holds it between latch points sits outside this unit.
// Flow control: a stall-all pipeline; every register advances when the
// output is taken or empty (in_ready = out_ready | !out_valid).
// MUTANT (verification only, 0 in every real build): 1 drops the saturation
// (the sum wraps), 2 changes the rounding of exact ties (half up <-> half even).
module arp_orientation_matrix_unit #(
  parameter int VEC_FRAC = 14,
  parameter int MAT_FRAC = 14,
  parameter int ROT_FRAC = 14,
  parameter int ROT_ROUNDING = 1,  // 0 floor, 1 half up, 2 half even
  parameter int LATENCY = 2,
  parameter int MUTANT = 0
) (
  input  logic clk,
  input  logic rst_n,
  input  logic in_valid,
  output logic in_ready,
  input  logic [9*(MAT_FRAC+2)-1:0] in_matrix,  // row-major, entry 0 in the low bits
  input  logic [3*(VEC_FRAC+2)-1:0] in_vector,  // x in the low bits
  output logic out_valid,
  input  logic out_ready,
  output logic [3*(ROT_FRAC+2)-1:0] out_vector  // x in the low bits
);
  localparam int MW = MAT_FRAC + 2;
  localparam int VW = VEC_FRAC + 2;
  localparam int RW = ROT_FRAC + 2;
  localparam int PW = MW + VW;     // one product
  localparam int SW = PW + 2;      // a sum of three
  localparam int SHIFT = MAT_FRAC + VEC_FRAC - ROT_FRAC;
  localparam int ROUNDING = MUTANT == 2 ? (ROT_ROUNDING == 1 ? 2 : ROT_ROUNDING == 2 ? 1 : ROT_ROUNDING)
                                        : ROT_ROUNDING;

  // Widths and latencies this RTL does not build are refused at elaboration.
  if (LATENCY < 2) begin : g_latency_check
    $error("arp_orientation_matrix_unit: LATENCY %0d is below its minimum 2", LATENCY);
  end
  if (SHIFT < 0) begin : g_shift_check
    $error("arp_orientation_matrix_unit: ROT_FRAC %0d exceeds MAT_FRAC + VEC_FRAC (no left shift in this RTL)", ROT_FRAC);
  end
  if (ROT_ROUNDING < 0 || ROT_ROUNDING > 2) begin : g_rounding_check
    $error("arp_orientation_matrix_unit: ROT_ROUNDING %0d is not 0 (floor), 1 (half up) or 2 (half even)", ROT_ROUNDING);
  end

  logic advance;
  logic valid1, valid2;
  logic [9*PW-1:0] prod_d, prod_q;
  logic [3*RW-1:0] rot_d, rot_q;

  for (genvar i = 0; i < 9; i++) begin : g_mul
    logic signed [MW-1:0] m;
    logic signed [VW-1:0] v;
    logic signed [PW-1:0] p;
    assign m = in_matrix[i*MW +: MW];
    assign v = in_vector[(i % 3)*VW +: VW];
    assign p = m * v;
    assign prod_d[i*PW +: PW] = p;
  end

  for (genvar r = 0; r < 3; r++) begin : g_row
    logic signed [PW-1:0] p0, p1, p2;
    logic signed [SW-1:0] sum;
    logic signed [SW:0] rounded;
    logic signed [RW-1:0] sat;
    assign p0 = prod_q[(3*r+0)*PW +: PW];
    assign p1 = prod_q[(3*r+1)*PW +: PW];
    assign p2 = prod_q[(3*r+2)*PW +: PW];
    assign sum = SW'(p0) + SW'(p1) + SW'(p2);
    arp_round_shift #(.IN_W(SW), .SHIFT(SHIFT), .ROUNDING(ROUNDING)) u_round (.a(sum), .y(rounded));
    localparam logic signed [SW:0] HI = (SW+1)'((1 << (RW - 1)) - 1);
    localparam logic signed [SW:0] LO = -(SW+1)'(1 << (RW - 1));
    if (MUTANT == 1) begin : g_wrap
      /* verilator lint_off UNUSEDSIGNAL */
      logic [SW-RW:0] dropped;
      assign dropped = rounded[SW:RW];
      /* verilator lint_on UNUSEDSIGNAL */
      assign sat = rounded[RW-1:0];
    end else begin : g_saturate
      assign sat = rounded > HI ? HI[RW-1:0] : rounded < LO ? LO[RW-1:0] : rounded[RW-1:0];
    end
    assign rot_d[r*RW +: RW] = sat;
  end

  assign advance = out_ready || !out_valid_last;
  assign in_ready = advance;

  always_ff @(posedge clk) begin
    if (!rst_n) begin
      valid1 <= 1'b0;
      valid2 <= 1'b0;
    end else if (advance) begin
      valid1 <= in_valid;
      valid2 <= valid1;
    end
    if (advance) begin
      prod_q <= prod_d;
      rot_q <= rot_d;
    end
  end

  logic out_valid_last;
  arp_pipe_delay #(.WIDTH(3*RW), .DEPTH(LATENCY > 2 ? LATENCY - 2 : 0)) u_pad (
    .clk, .rst_n, .advance, .in_valid(valid2), .in_data(rot_q), .out_valid(out_valid_last), .out_data(out_vector));
  assign out_valid = out_valid_last;
endmodule
