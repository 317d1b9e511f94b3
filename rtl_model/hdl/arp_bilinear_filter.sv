// Bilinear anti-aliasing blend: four composited colours c00 c10 c01 c11 (the
// taps around the sample point; 1 = the next texel in x or y) and the weights
// wx, wy of the x1 / y1 taps (Q0.TEXEL_FRAC), per channel
//   ((c00 (W - wx) + c10 wx)(W - wy) + (c01 (W - wx) + c11 wx) wy) / W^2,
// rounded half up, W = 2^TEXEL_FRAC: the datapath's bilinear_blend()
// (rtl_model/datapath/AntiAliasingFilter.hpp). Colours are R:G:B, red highest.
//   stage 1: the horizontal blends (top, bottom) of each channel, registered
//   stage 2: the vertical blend and rounding, registered
//   LATENCY - 2 further registers (LATENCY >= 2).
// Flow control: a stall-all pipeline, in_ready = out_ready | !out_valid.
// MUTANT (verification only): 1 drops the rounding (truncates), 2 reverses
// the blue channel's x weight (wx for the x0 taps, W - wx for the x1 taps).
module arp_bilinear_filter #(
  parameter int RED_BITS = 8,
  parameter int GREEN_BITS = 8,
  parameter int BLUE_BITS = 8,
  parameter int TEXEL_FRAC = 8,
  parameter int LATENCY = 2,
  parameter int MUTANT = 0,
  localparam int CB = RED_BITS + GREEN_BITS + BLUE_BITS
) (
  input  logic clk,
  input  logic rst_n,
  input  logic in_valid,
  output logic in_ready,
  input  logic [4*CB-1:0] in_taps,          // c00, c10, c01, c11 from the low bits up
  input  logic [TEXEL_FRAC-1:0] in_wx,
  input  logic [TEXEL_FRAC-1:0] in_wy,
  output logic out_valid,
  input  logic out_ready,
  output logic [CB-1:0] out_color
);
  if (LATENCY < 2) begin : g_latency_check
    $error("arp_bilinear_filter: LATENCY %0d is below its minimum 2", LATENCY);
  end
  if (TEXEL_FRAC < 1 || TEXEL_FRAC > 16 || RED_BITS > 16 || GREEN_BITS > 16 || BLUE_BITS > 16) begin : g_width_check
    $error("arp_bilinear_filter: TEXEL_FRAC 1..16 and channels of at most 16 bits are built");
  end
  localparam int WB = TEXEL_FRAC + 1;        // a weight, 0..W
  localparam int HB = 16 + WB;               // a horizontal blend
  localparam int VB = HB + WB + 1;           // a vertical blend before the shift

  logic advance, last_valid, valid1, valid2;
  assign advance = out_ready || !last_valid;
  assign in_ready = advance;

  logic [6*HB-1:0] horiz_d, horiz_q;  // top and bottom of each channel
  logic [WB-1:0] wy_q;
  logic [CB-1:0] color_d, color_q;
  localparam logic [WB-1:0] W = WB'(1) << TEXEL_FRAC;

  for (genvar c = 0; c < 3; c++) begin : g_channel
    localparam int CHB = c == 0 ? RED_BITS : c == 1 ? GREEN_BITS : BLUE_BITS;  // this channel's bits
    localparam int SHIFT = c == 0 ? GREEN_BITS + BLUE_BITS : c == 1 ? BLUE_BITS : 0;  // and its place
    logic [15:0] a, b, d, e;
    logic [WB-1:0] wx, wxn;
    assign a = 16'(in_taps[0*CB + SHIFT +: CHB]);
    assign b = 16'(in_taps[1*CB + SHIFT +: CHB]);
    assign d = 16'(in_taps[2*CB + SHIFT +: CHB]);
    assign e = 16'(in_taps[3*CB + SHIFT +: CHB]);
    if (MUTANT == 2 && c == 2) begin : g_swapped
      assign wx = W - WB'(in_wx);
    end else begin : g_weight
      assign wx = WB'(in_wx);
    end
    assign wxn = W - wx;
    assign horiz_d[(2*c)*HB +: HB] = HB'(a) * HB'(wxn) + HB'(b) * HB'(wx);
    assign horiz_d[(2*c+1)*HB +: HB] = HB'(d) * HB'(wxn) + HB'(e) * HB'(wx);

    logic [VB-1:0] v;
    assign v = VB'(horiz_q[(2*c)*HB +: HB]) * (VB'(W) - VB'(wy_q)) + VB'(horiz_q[(2*c+1)*HB +: HB]) * VB'(wy_q)
             + (MUTANT == 1 ? VB'(0) : VB'(1) << (2 * TEXEL_FRAC - 1));
    /* verilator lint_off UNUSEDSIGNAL */
    logic [VB-1:0] shifted;  // the channel is its low CHB bits
    /* verilator lint_on UNUSEDSIGNAL */
    assign shifted = v >> (2 * TEXEL_FRAC);
    assign color_d[SHIFT +: CHB] = shifted[CHB-1:0];
  end

  always_ff @(posedge clk) begin
    if (!rst_n) begin
      valid1 <= 1'b0;
      valid2 <= 1'b0;
    end else if (advance) begin
      valid1 <= in_valid;
      valid2 <= valid1;
    end
    if (advance) begin
      horiz_q <= horiz_d;
      wy_q <= WB'(in_wy);
      color_q <= color_d;
    end
  end

  arp_pipe_delay #(.WIDTH(CB), .DEPTH(LATENCY > 2 ? LATENCY - 2 : 0)) u_pad (
    .clk, .rst_n, .advance, .in_valid(valid2), .in_data(color_q), .out_valid(last_valid), .out_data(out_color));
  assign out_valid = last_valid;
endmodule
