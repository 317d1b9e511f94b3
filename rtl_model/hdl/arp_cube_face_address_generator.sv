// Cube-face address generator: rotated direction -> face and texel-space
// position (u, v as Q.TEXEL_FRAC), the datapath's generate_address()
// (rtl_model/datapath/CubeFaceAddressGenerator.hpp) in hardware.
//   select   (no register of its own: it shares the divider's first stage)
//            |x| |y| |z|, the major axis with the tie rule X over Y over Z
//            (a major component of exactly zero is positive), sc, tc, |ma|
//   divider  DIVIDER 0: leading-one normaliser and reciprocal table (2^IB
//            entries of Q1.RECIP_FRAC_BITS, midpoints of 1/M, rounded half
//            even, computed at elaboration), NEWTON_STEPS Newton-Raphson
//            stages, then one stage of the denormalising shift and the two
//            multiplies sc * y', tc * y'.
//            DIVIDER 1: restoring division, DIV_BITS_PER_STAGE quotient bits
//            per stage, and a stage for the sign and the rounding.
//   position quotient clamped to +-1, (q + 1)/2 x S rounded to TEXEL_FRAC
//            bits, clamped to the face.
// Minimum latency: 3 + NEWTON_STEPS (table), ceil(QUOT_FRAC / DIV_BITS_PER_STAGE)
// + 2 (exact: 6 at the default widths); LATENCY pads beyond it.
// Input contract (as the datapath's): no component is the most negative code
// -2^(ROT_FRAC+1), which a rotation of a unit vector never produces.
// Flow control: a stall-all pipeline, in_ready = out_ready | !out_valid.
// MUTANT (verification only): 1 flips the tie rule (Y over X on equal
// magnitudes), 2 clamps positions to S*2^TEXEL_FRAC instead of one below.
module arp_cube_face_address_generator #(
  parameter int ROT_FRAC = 14,
  parameter int DIVIDER = 0,           // 0 reciprocal table, 1 exact
  parameter int DIV_BITS_PER_STAGE = 4,  // exact divider: quotient bits per pipeline stage
  parameter int RECIP_INDEX_BITS = 8,
  parameter int RECIP_FRAC_BITS = 16,
  parameter int NEWTON_STEPS = 1,
  parameter int QUOT_FRAC = 16,
  parameter int DIV_ROUNDING = 1,      // 0 floor, 1 half up, 2 half even
  parameter int TEXEL_FRAC = 8,
  parameter int TEXEL_ROUNDING = 0,
  parameter int FACE_SIZE = 512,
  parameter int LATENCY = 4,
  parameter int MUTANT = 0,
  localparam int RW = ROT_FRAC + 2,                       // rotated components
  localparam int UW = $clog2(FACE_SIZE + 1) + TEXEL_FRAC  // texel-space positions
) (
  input  logic clk,
  input  logic rst_n,
  input  logic in_valid,
  output logic in_ready,
  input  logic [3*RW-1:0] in_vector,  // x in the low bits
  output logic out_valid,
  input  logic out_ready,
  output logic [2:0] out_face,        // +X -X +Y -Y +Z -Z = 0..5
  output logic [UW-1:0] out_u,        // texel x = u >> TEXEL_FRAC, sub-texel = low bits
  output logic [UW-1:0] out_v
);
  localparam int F = RECIP_FRAC_BITS;
  localparam int NMAX = ROT_FRAC + 1;  // bit length of the widest |ma|
  localparam int SCW = RW + 1;         // sc, tc: negated components
  localparam int MAW = RW;             // |ma|
  localparam int NW = 6;               // bit length of |ma|, 0..NMAX
  localparam int YW = F + 3;           // reciprocal mantissa, signed
  localparam int QW = QUOT_FRAC + 3;   // quotient, signed
  localparam int BW = 3 + 1 + 2 * SCW + MAW;  // face, zero, sc, tc, |ma|
  localparam int MIN_LATENCY = DIVIDER == 0 ? 3 + NEWTON_STEPS : (QUOT_FRAC + DIV_BITS_PER_STAGE - 1) / DIV_BITS_PER_STAGE + 2;

  // Widths and latencies this RTL does not build are refused at elaboration.
  if (LATENCY < MIN_LATENCY) begin : g_latency_check
    $error("arp_cube_face_address_generator: LATENCY %0d is below its minimum %0d", LATENCY, MIN_LATENCY);
  end
  if (DIVIDER == 0 && RECIP_FRAC_BITS + ROT_FRAC < QUOT_FRAC) begin : g_shift_check
    $error("arp_cube_face_address_generator: QUOT_FRAC %0d exceeds RECIP_FRAC_BITS + ROT_FRAC", QUOT_FRAC);
  end
  if (DIV_ROUNDING < 0 || DIV_ROUNDING > 2 || TEXEL_ROUNDING < 0 || TEXEL_ROUNDING > 2) begin : g_rounding_check
    $error("arp_cube_face_address_generator: DIV_ROUNDING and TEXEL_ROUNDING are 0 (floor), 1 (half up) or 2 (half even)");
  end

  logic advance;
  logic last_valid;
  assign advance = out_ready || !last_valid;
  assign in_ready = advance;

  // ---- select ----------------------------------------------------------
  localparam bit Y_OVER_X = MUTANT == 1;  // the mutant tie rule
  logic [BW-1:0] sel_d, sel_q;
  logic sel_valid;
  always_comb begin
    logic signed [SCW-1:0] x, y, z, sc, tc;
    logic [MAW-1:0] ax, ay, az, ma;
    logic is_x, is_y, pos;
    logic [2:0] face;
    x = SCW'($signed(in_vector[0 +: RW]));
    y = SCW'($signed(in_vector[RW +: RW]));
    z = SCW'($signed(in_vector[2*RW +: RW]));
    ax = MAW'(x < 0 ? -x : x);
    ay = MAW'(y < 0 ? -y : y);
    az = MAW'(z < 0 ? -z : z);
    is_x = (Y_OVER_X ? ax > ay : ax >= ay) && ax >= az;
    is_y = !is_x && ay >= az;
    pos = is_x ? x >= 0 : is_y ? y >= 0 : z >= 0;
    sc = is_x ? (pos ? -z : z) : is_y ? x : (pos ? x : -x);
    tc = is_x ? -y : is_y ? (pos ? z : -z) : -y;
    ma = is_x ? ax : is_y ? ay : az;
    face = {is_x ? 2'd0 : is_y ? 2'd1 : 2'd2, 1'b0} | {2'b0, !pos};
    sel_d = {face, ma == '0, sc, tc, ma};
  end
  // Selection is shallow (compares and negations): it shares the next stage's clock.
  assign sel_q = sel_d;
  assign sel_valid = in_valid;

  // ---- divider: quotients qs = sc/|ma|, qt = tc/|ma| as signed Q1.QUOT_FRAC ----
  logic quot_valid;
  logic [2:0] quot_face;
  logic signed [QW-1:0] qs, qt;

  if (DIVIDER == 0) begin : g_table
    localparam int IB = RECIP_INDEX_BITS;
    localparam int N = 1 << IB;
    // The table entry for M in [1 + i/N, 1 + (i+1)/N): the midpoint of 1/M
    // over it, 2^(F-1) N (2N + 2i + 1) / ((N + i)(N + i + 1)), rounded half even.
    function automatic logic [YW-1:0] recip_entry(input int i);
      logic [127:0] num, den, q, r;
      num = (128'(1) << (F - 1)) * 128'(N) * (128'(2 * N) + 128'(2 * i) + 128'(1));
      den = (128'(N) + 128'(i)) * (128'(N) + 128'(i) + 128'(1));
      q = num / den;
      r = num % den;
      if (2 * r > den || (2 * r == den && q[0])) q = q + 1;
      recip_entry = q[YW-1:0];
    endfunction
    logic [YW-1:0] lut [N];
    for (genvar i = 0; i < N; i++) begin : g_lut
      assign lut[i] = recip_entry(i);
    end

    // normalise and look up: carried bundle + n + y
    localparam int CW = BW + NW;
    logic [CW-1:0] nr_carry [NEWTON_STEPS + 1];
    logic signed [YW-1:0] nr_y [NEWTON_STEPS + 1];
    logic nr_valid [NEWTON_STEPS + 1];
    logic [CW-1:0] norm_carry_d;
    logic signed [YW-1:0] norm_y_d;
    always_comb begin
      logic [MAW-1:0] m, frac_part;
      logic [NW-1:0] n;
      logic [IB-1:0] idx;
      m = sel_q[MAW-1:0] == '0 ? MAW'(1) : sel_q[MAW-1:0];  // |ma| = 0 has no reciprocal: 1/1, unused
      n = '0;
      for (int b = 0; b < MAW; b++) if (m[b]) n = NW'(b + 1);
      frac_part = m & ~(MAW'(1) << (n - 1'b1));
      // the IB bits below the leading one (zeros appended when n - 1 < IB)
      idx = IB'(({{IB{1'b0}}, frac_part} << IB) >> (n - 1'b1));
      norm_y_d = $signed(lut[idx]);
      norm_carry_d = {sel_q[BW-1:MAW], m, n};
    end
    always_ff @(posedge clk) begin
      if (!rst_n) nr_valid[0] <= 1'b0;
      else if (advance) nr_valid[0] <= sel_valid;
      if (advance) begin
        nr_carry[0] <= norm_carry_d;
        nr_y[0] <= norm_y_d;
      end
    end

    // Newton-Raphson: y <- y (2 - M y), M y first reduced to Q.F at a shift of n - 1.
    for (genvar k = 0; k < NEWTON_STEPS; k++) begin : g_newton
      localparam int PW = MAW + YW + 1;   // m * y
      localparam int TW = PW + 2;         // 2 - M y
      localparam int YTW = YW + TW;       // y * t
      logic [MAW-1:0] m;
      logic [NW-1:0] n;
      logic signed [PW-1:0] my_full;
      logic signed [PW:0] my;
      logic signed [TW-1:0] t;
      logic signed [YTW-1:0] yt;
      /* verilator lint_off UNUSEDSIGNAL */
      logic signed [YTW:0] y_next;  // the mantissa is its low YW bits
      /* verilator lint_on UNUSEDSIGNAL */
      assign m = nr_carry[k][NW +: MAW];
      assign n = nr_carry[k][NW-1:0];
      assign my_full = $signed({1'b0, m}) * nr_y[k];
      arp_round_shift_var #(.IN_W(PW), .S_W(NW), .ROUNDING(DIV_ROUNDING)) u_my (.a(my_full), .s(n - 1'b1), .y(my));
      assign t = (TW'(1) <<< (F + 1)) - TW'(my);
      assign yt = YTW'(nr_y[k]) * YTW'(t);
      arp_round_shift #(.IN_W(YTW), .SHIFT(F), .ROUNDING(DIV_ROUNDING)) u_y (.a(yt), .y(y_next));
      always_ff @(posedge clk) begin
        if (!rst_n) nr_valid[k+1] <= 1'b0;
        else if (advance) nr_valid[k+1] <= nr_valid[k];
        if (advance) begin
          nr_carry[k+1] <= nr_carry[k];
          nr_y[k+1] <= y_next[YW-1:0];
        end
      end
    end

    // denormalise (y' = y << (NMAX - n)) and multiply: sc * y', tc * y' at a fixed shift
    localparam int AW = YW + NMAX;
    localparam int MPW = SCW + AW;
    localparam int MSHIFT = F + NMAX - 1 - QUOT_FRAC;
    logic [CW-1:0] c;
    logic signed [AW-1:0] aligned;
    logic signed [SCW-1:0] sc, tc;
    logic signed [MPW-1:0] ps, pt;
    /* verilator lint_off UNUSEDSIGNAL */
    logic signed [MPW:0] rs, rt;  // quotients are their low QW bits
    /* verilator lint_on UNUSEDSIGNAL */
    assign c = nr_carry[NEWTON_STEPS];
    assign aligned = AW'(nr_y[NEWTON_STEPS]) <<< (NW'(NMAX) - c[NW-1:0]);
    assign sc = c[NW + MAW + SCW +: SCW];
    assign tc = c[NW + MAW +: SCW];
    assign ps = MPW'(sc) * MPW'(aligned);
    assign pt = MPW'(tc) * MPW'(aligned);
    arp_round_shift #(.IN_W(MPW), .SHIFT(MSHIFT), .ROUNDING(DIV_ROUNDING)) u_s (.a(ps), .y(rs));
    arp_round_shift #(.IN_W(MPW), .SHIFT(MSHIFT), .ROUNDING(DIV_ROUNDING)) u_t (.a(pt), .y(rt));
    logic zero;
    assign zero = c[NW + MAW + 2 * SCW];
    always_ff @(posedge clk) begin
      if (!rst_n) quot_valid <= 1'b0;
      else if (advance) quot_valid <= nr_valid[NEWTON_STEPS];
      if (advance) begin
        quot_face <= c[CW-1 -: 3];
        qs <= zero ? '0 : rs[QW-1:0];
        qt <= zero ? '0 : rt[QW-1:0];
      end
    end
  end else begin : g_exact
    // Restoring division of |sc| and |tc| by |ma| (|sc|, |tc| <= |ma|), two
    // dividers side by side: the integer bit first, then DIV_BITS_PER_STAGE
    // fraction bits per pipeline stage (NS stages for QUOT_FRAC bits), then a
    // stage that restores the sign (floor division) and rounds by the remainder.
    localparam int K = DIV_BITS_PER_STAGE;
    localparam int NS = (QUOT_FRAC + K - 1) / K;
    localparam int QB = QUOT_FRAC + 1;  // quotient magnitude, <= 2^QUOT_FRAC
    // the state between division stages: face, zero, |ma|, signs, remainders, quotients so far
    localparam int DW = 3 + 1 + MAW + 2 + 2 * MAW + 2 * QB;
    logic [DW-1:0] div_state [NS + 1];
    logic div_valid [NS + 1];
    always_comb begin
      logic signed [SCW-1:0] sc, tc;
      logic [MAW-1:0] m, as, at;
      logic is, it;
      sc = sel_q[MAW + SCW +: SCW];
      tc = sel_q[MAW +: SCW];
      m = sel_q[MAW-1:0] == '0 ? MAW'(1) : sel_q[MAW-1:0];  // |ma| = 0: the zero vector, whose quotients are 0
      as = MAW'(sc < 0 ? -sc : sc);
      at = MAW'(tc < 0 ? -tc : tc);
      is = as == m;  // the integer bit: |sc| / |ma| is 1 only on the face edge
      it = at == m;
      div_state[0] = {sel_q[BW-1 -: 3], sel_q[BW-4], m, sc < 0, tc < 0, is ? '0 : as, it ? '0 : at,
                      QB'(is), QB'(it)};
      div_valid[0] = sel_valid;
    end
    for (genvar k = 0; k < NS; k++) begin : g_divide
      localparam int BITS = QUOT_FRAC - k * K < K ? QUOT_FRAC - k * K : K;  // fraction bits in this stage
      logic [MAW-1:0] m;
      logic [MAW-1:0] r_s [BITS + 1] /*verilator split_var*/;  // a chain: element j + 1 from j
      logic [MAW-1:0] r_t [BITS + 1] /*verilator split_var*/;  // a chain: element j + 1 from j
      logic [QB-1:0] q_s [BITS + 1] /*verilator split_var*/;  // a chain: element j + 1 from j
      logic [QB-1:0] q_t [BITS + 1] /*verilator split_var*/;  // a chain: element j + 1 from j
      assign m = div_state[k][2 * QB + 2 * MAW + 2 +: MAW];
      assign r_s[0] = div_state[k][2 * QB + MAW +: MAW];
      assign r_t[0] = div_state[k][2 * QB +: MAW];
      assign q_s[0] = div_state[k][QB +: QB];
      assign q_t[0] = div_state[k][0 +: QB];
      for (genvar j = 0; j < BITS; j++) begin : g_bit
        logic [MAW:0] ds, dt;  // the remainder doubled: below 2 |ma|
        logic gs, gt;
        assign ds = {r_s[j], 1'b0};
        assign dt = {r_t[j], 1'b0};
        assign gs = ds >= {1'b0, m};
        assign gt = dt >= {1'b0, m};
        assign r_s[j+1] = MAW'(gs ? ds - {1'b0, m} : ds);
        assign r_t[j+1] = MAW'(gt ? dt - {1'b0, m} : dt);
        assign q_s[j+1] = {q_s[j][QB-2:0], gs};
        assign q_t[j+1] = {q_t[j][QB-2:0], gt};
      end
      always_ff @(posedge clk) begin
        if (!rst_n) div_valid[k+1] <= 1'b0;
        else if (advance) div_valid[k+1] <= div_valid[k];
        if (advance)
          div_state[k+1] <= {div_state[k][DW-1 -: 3 + 1 + MAW + 2], r_s[BITS], r_t[BITS], q_s[BITS], q_t[BITS]};
      end
    end
    // sign and rounding: floor division of the signed value, then the remainder decides
    function automatic logic signed [QW-1:0] signed_rounded(input logic neg, input logic [QB-1:0] qa,
                                                            input logic [MAW-1:0] r, input logic [MAW-1:0] m);
      logic signed [QW+1:0] q;
      logic [MAW-1:0] rem;
      logic [MAW:0] twice;
      logic up;
      if (neg && r != '0) begin
        q = -$signed((QW+2)'(qa)) - 1;
        rem = m - r;
      end else begin
        q = neg ? -$signed((QW+2)'(qa)) : $signed((QW+2)'(qa));
        rem = r;
      end
      twice = {rem, 1'b0};
      up = DIV_ROUNDING != 0 && (twice > {1'b0, m} || (twice == {1'b0, m} && (DIV_ROUNDING == 1 || q[0])));
      signed_rounded = QW'(q + (QW+2)'(up));
    endfunction
    logic [DW-1:0] d;
    assign d = div_state[NS];
    always_ff @(posedge clk) begin
      if (!rst_n) quot_valid <= 1'b0;
      else if (advance) quot_valid <= div_valid[NS];
      if (advance) begin
        quot_face <= d[DW-1 -: 3];
        qs <= d[DW-4] ? '0 : signed_rounded(d[2 * QB + 2 * MAW + 1], d[QB +: QB], d[2 * QB + MAW +: MAW], d[2 * QB + 2 * MAW + 2 +: MAW]);
        qt <= d[DW-4] ? '0 : signed_rounded(d[2 * QB + 2 * MAW], d[0 +: QB], d[2 * QB +: MAW], d[2 * QB + 2 * MAW + 2 +: MAW]);
      end
    end
  end

  // ---- position: (clamp(q) + 1) * S / 2 to TEXEL_FRAC bits, clamped to the face ----
  localparam int SB = $clog2(FACE_SIZE + 1);
  localparam int OW = QUOT_FRAC + 2 + SB;  // (q + one) * S
  localparam int PSHIFT = QUOT_FRAC + 1 - TEXEL_FRAC;
  localparam logic [UW-1:0] MAX_POS = MUTANT == 2 ? UW'(FACE_SIZE) << TEXEL_FRAC
                                                  : (UW'(FACE_SIZE) << TEXEL_FRAC) - 1'b1;
  // p >= 0: the quotient was clamped to -1 or more first
  function automatic logic [UW-1:0] clamp_position(input logic signed [OW+1:0] p);
    clamp_position = p > $signed((OW+2)'(MAX_POS)) ? MAX_POS : UW'(p);
  endfunction
  logic [OW-1:0] scaled_s, scaled_t;
  logic signed [OW+1:0] pos_s, pos_t;
  always_comb begin
    logic signed [QW-1:0] one, cs, ct;
    one = QW'(1) <<< QUOT_FRAC;
    cs = qs < -one ? -one : qs > one ? one : qs;
    ct = qt < -one ? -one : qt > one ? one : qt;
    scaled_s = (OW'(cs) + OW'(one)) * OW'(FACE_SIZE);
    scaled_t = (OW'(ct) + OW'(one)) * OW'(FACE_SIZE);
  end
  if (PSHIFT >= 0) begin : g_round_position
    logic signed [OW+1:0] rs, rt;
    arp_round_shift #(.IN_W(OW+1), .SHIFT(PSHIFT), .ROUNDING(TEXEL_ROUNDING)) u_s (.a({1'b0, scaled_s}), .y(rs));
    arp_round_shift #(.IN_W(OW+1), .SHIFT(PSHIFT), .ROUNDING(TEXEL_ROUNDING)) u_t (.a({1'b0, scaled_t}), .y(rt));
    assign pos_s = rs;
    assign pos_t = rt;
  end else begin : g_widen_position
    assign pos_s = $signed({2'b0, scaled_s}) <<< (-PSHIFT);
    assign pos_t = $signed({2'b0, scaled_t}) <<< (-PSHIFT);
  end
  logic pos_valid;
  logic [2:0] pos_face;
  logic [UW-1:0] pos_u, pos_v;
  always_ff @(posedge clk) begin
    if (!rst_n) pos_valid <= 1'b0;
    else if (advance) pos_valid <= quot_valid;
    if (advance) begin
      pos_face <= quot_face;
      pos_u <= clamp_position(pos_s);
      pos_v <= clamp_position(pos_t);
    end
  end

  arp_pipe_delay #(.WIDTH(3 + 2 * UW), .DEPTH(LATENCY > MIN_LATENCY ? LATENCY - MIN_LATENCY : 0)) u_pad (
    .clk, .rst_n, .advance, .in_valid(pos_valid), .in_data({pos_face, pos_u, pos_v}),
    .out_valid(last_valid), .out_data({out_face, out_u, out_v}));
  assign out_valid = last_valid;
endmodule
