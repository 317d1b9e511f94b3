// Rounding right shift by a constant: y = a / 2^SHIFT rounded as the
// datapath's RoundShift (rtl_model/datapath/FixedPoint.hpp) rounds it.
// ROUNDING: 0 floor (truncation), 1 half up, 2 half even. The output is one
// bit wider than the input so the rounding add cannot overflow.
module arp_round_shift #(
  parameter int IN_W = 32,
  parameter int SHIFT = 1,
  parameter int ROUNDING = 1
) (
  input  logic signed [IN_W-1:0] a,
  output logic signed [IN_W:0]   y
);
  logic signed [IN_W:0] ax;
  assign ax = {a[IN_W-1], a};
  if (SHIFT == 0) begin : g_exact
    assign y = ax;
  end else begin : g_round
    localparam logic signed [IN_W:0] HALF = {{IN_W{1'b0}}, 1'b1} << (SHIFT - 1);
    logic signed [IN_W:0] bias;
    // Half even: half - 1, plus one when the kept part is odd (a tie then rounds up to even).
    assign bias = ROUNDING == 0 ? '0 : ROUNDING == 1 ? HALF : HALF - 1 + {{IN_W{1'b0}}, ax[SHIFT]};
    assign y = (ax + bias) >>> SHIFT;
  end
endmodule
