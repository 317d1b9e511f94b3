// Composition unit: of the texels fetched from the MEMORIES display memories
// at one address, the nearest (smallest depth code) wins; on equal depths
// the lower memory index wins (memory 0 is the most often updated); where
// every memory is empty (depth code 2^DEPTH_BITS - 1) the background colour
// shows. The datapath's compose() (rtl_model/datapath/CompositionUnit.hpp).
// A texel word is the display memory's: colour (R:G:B, red highest) in the
// low 32 bits, depth in the high 32; this unit reads the low RED_BITS +
// GREEN_BITS + BLUE_BITS and DEPTH_BITS of each (the write port stores no more).
//   one stage: a chain of MEMORIES - 1 strict compares, registered;
//   LATENCY - 1 further registers (LATENCY >= 1).
// Flow control: a stall-all pipeline, in_ready = out_ready | !out_valid.
// MUTANT (verification only): 1 lets the higher index win ties (<=),
// 2 ignores the empty code (an empty texel's colour shows, not the background).
module arp_composition_unit #(
  parameter int MEMORIES = 4,
  parameter int RED_BITS = 8,
  parameter int GREEN_BITS = 8,
  parameter int BLUE_BITS = 8,
  parameter int DEPTH_BITS = 16,
  parameter int BACKGROUND = 0,  // colour code shown where every memory is empty
  parameter int LATENCY = 1,
  parameter int MUTANT = 0,
  localparam int IW = MEMORIES > 1 ? $clog2(MEMORIES) : 1,
  localparam int COLOR_BITS = RED_BITS + GREEN_BITS + BLUE_BITS
) (
  input  logic clk,
  input  logic rst_n,
  input  logic in_valid,
  output logic in_ready,
  input  logic [64*MEMORIES-1:0] in_texels,  // memory 0 in the low 64 bits
  output logic out_valid,
  input  logic out_ready,
  output logic [COLOR_BITS-1:0] out_color,
  output logic [DEPTH_BITS-1:0] out_depth,
  output logic out_empty,                    // every memory empty: the background shows
  output logic [IW-1:0] out_memory           // the winning memory (0 when empty)
);
  if (LATENCY < 1) begin : g_latency_check
    $error("arp_composition_unit: LATENCY %0d is below its minimum 1", LATENCY);
  end
  if (MEMORIES < 1 || COLOR_BITS < 3 || COLOR_BITS > 32 || DEPTH_BITS < 1 || DEPTH_BITS > 32) begin : g_width_check
    $error("arp_composition_unit: MEMORIES >= 1, COLOR_BITS 3..32 and DEPTH_BITS 1..32 are built");
  end
  localparam int OW = COLOR_BITS + DEPTH_BITS + 1 + IW;
  localparam logic [DEPTH_BITS-1:0] EMPTY = '1;

  logic advance, last_valid, valid1;
  logic [OW-1:0] result_d, result_q;
  assign advance = out_ready || !last_valid;
  assign in_ready = advance;

  always_comb begin
    logic [DEPTH_BITS-1:0] best_depth, d;
    logic [COLOR_BITS-1:0] best_color;
    logic [IW-1:0] who;
    logic nearer, empty;
    best_depth = in_texels[32 +: DEPTH_BITS];
    best_color = in_texels[0 +: COLOR_BITS];
    who = '0;
    for (int i = 1; i < MEMORIES; i++) begin
      d = in_texels[64*i + 32 +: DEPTH_BITS];
      nearer = MUTANT == 1 ? d <= best_depth : d < best_depth;
      if (nearer) begin
        best_depth = d;
        best_color = in_texels[64*i +: COLOR_BITS];
        who = IW'(i);
      end
    end
    empty = MUTANT == 2 ? 1'b0 : best_depth == EMPTY;
    result_d = {empty ? COLOR_BITS'(BACKGROUND) : best_color, best_depth, empty, empty ? IW'(0) : who};
  end

  always_ff @(posedge clk) begin
    if (!rst_n) valid1 <= 1'b0;
    else if (advance) valid1 <= in_valid;
    if (advance) result_q <= result_d;
  end

  arp_pipe_delay #(.WIDTH(OW), .DEPTH(LATENCY > 1 ? LATENCY - 1 : 0)) u_pad (
    .clk, .rst_n, .advance, .in_valid(valid1), .in_data(result_q), .out_valid(last_valid),
    .out_data({out_color, out_depth, out_empty, out_memory}));
  assign out_valid = last_valid;
endmodule
