// DEPTH registers of a stall-all pipeline (valid bit + WIDTH data bits),
// advancing when `advance` is high; DEPTH 0 is a wire. Pads a module to the
// latency the configuration asks for beyond its minimum.
module arp_pipe_delay #(
  parameter int WIDTH = 8,
  parameter int DEPTH = 0
) (
  input  logic             clk,
  input  logic             rst_n,
  input  logic             advance,
  input  logic             in_valid,
  input  logic [WIDTH-1:0] in_data,
  output logic             out_valid,
  output logic [WIDTH-1:0] out_data
);
  if (DEPTH == 0) begin : g_wire
    // The clock, reset and advance inputs are unused here by design.
    /* verilator lint_off UNUSEDSIGNAL */
    logic unused;
    assign unused = clk ^ rst_n ^ advance;
    /* verilator lint_on UNUSEDSIGNAL */
    assign out_valid = in_valid;
    assign out_data = in_data;
  end else begin : g_regs
    logic [DEPTH-1:0] valid_q;
    logic [DEPTH*WIDTH-1:0] data_q;
    logic [DEPTH-1:0] valid_d;
    logic [DEPTH*WIDTH-1:0] data_d;
    if (DEPTH == 1) begin : g_one
      assign valid_d = in_valid;
      assign data_d = in_data;
    end else begin : g_shift
      assign valid_d = {valid_q[DEPTH-2:0], in_valid};
      assign data_d = {data_q[(DEPTH-1)*WIDTH-1:0], in_data};
    end
    always_ff @(posedge clk) begin
      if (!rst_n) valid_q <= '0;
      else if (advance) valid_q <= valid_d;
      if (advance) data_q <= data_d;
    end
    assign out_valid = valid_q[DEPTH-1];
    assign out_data = data_q[DEPTH*WIDTH-1 -: WIDTH];
  end
endmodule
