// Rounding right shift by a run-time amount s (0 <= s < IN_W): the
// datapath's rshift_round (rtl_model/datapath/ReciprocalUnit.hpp) for s >= 0.
// s = 0 drops no bits and rounds nothing. ROUNDING as arp_round_shift.
module arp_round_shift_var #(
  parameter int IN_W = 32,
  parameter int S_W = 6,
  parameter int ROUNDING = 1
) (
  input  logic signed [IN_W-1:0] a,
  input  logic        [S_W-1:0]  s,
  output logic signed [IN_W:0]   y
);
  logic signed [IN_W:0] ax, half, bias;
  logic on;
  assign ax = {a[IN_W-1], a};
  assign on = s != '0;
  assign half = on ? ({{IN_W{1'b0}}, 1'b1} << (s - 1'b1)) : '0;
  assign bias = ROUNDING == 0 ? '0
              : ROUNDING == 1 ? half
              : half - {{IN_W{1'b0}}, on} + {{IN_W{1'b0}}, on & ax[s]};
  assign y = (ax + bias) >>> s;
endmodule
