// Accuracy harness: the datapath (bit-accurate, any widths) against the golden
// reference over (a) every display pixel for several orientations, (b) seeded
// random orientations and pixels, (c) directed extremes -- cube edges and
// corners (exact ties), zero and tiny components, the widest lens angles,
// matrix entries at +-1, the reciprocal at both ends of its range (major
// component 1 and 1/sqrt 3), 90/120/180 degree rotations -- and the colour of
// whole bilinear frames against the golden frame. Whole-frame views come in
// two sets: generic (a spread of yaw, pitch and roll) and aligned with the
// cube axes (straight ahead, the 90-degree turns, and a field of view that
// puts the display's side edges on a cube edge), each reported view by view.
// Samples whose exact position -- exact integer arithmetic on the quantised
// lens vector and matrix -- lies on a texel or face boundary are ties, where
// either adjacent texel is right; they are counted apart from errors.
#pragma once
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "rtl_model/datapath/ArpConfig.hpp"
#include "rtl_model/datapath/LensVectorTable.hpp"
#include "rtl_model/datapath/OrientationMatrixUnit.hpp"

namespace arp::accuracy {

struct Options {
  int frame_orientations = 4;       // (a) full frames, generic views
  bool aligned = true;              // (a) full frames, the views aligned with the cube axes (aligned_views)
  int aligned_row_step = 1;         // every n-th display line of the aligned views (tests thin them out)
  int random_orientations = 32;     // (b)
  int random_pixels = 8192;         // (b) per orientation (plus as many random sphere directions)
  bool directed = true;             // (c)
  int color_orientations = 2;       // bilinear colour check, full frames
  uint64_t seed = 1;
  int worst_kept = 8;
  // Called as work completes: a stage name and the fraction of all work done.
  std::function<void(const char*, double)> progress;
};

// Texel-position error statistics of one sample set, in texels.
struct Stats {
  uint64_t samples = 0;
  uint64_t exact = 0;           // same face and nearest texel as golden
  uint64_t face_mismatch = 0;   // a different face (only possible at cube edges)
  double max_error = 0.0;
  double sum_error = 0.0;
  // Exact ties (see exact_address): either texel adjacent to the boundary is right.
  uint64_t ties = 0;            // on a texel boundary (integer u or v) or a face boundary
  uint64_t face_ties = 0;       // of those: two or three components of equal largest magnitude
  uint64_t tie_low = 0;         // tied coordinates the datapath put in the texel below the boundary (k - 1)
  uint64_t tie_high = 0;        // ... in the texel above it (k)
  uint64_t tie_rule_face = 0;   // face ties on the tie rule's face (X over Y over Z)
  uint64_t tie_other_face = 0;  // face ties on another of the tied faces
  uint64_t tie_off = 0;         // ties whose tied coordinate or face went to no texel beside the boundary: a defect
  uint64_t nontie_exact = 0;    // non-ties whose face and nearest texel equal golden's
  // Samples (ties too) whose face or an untied coordinate is off the exact
  // texel of the quantised inputs: the datapath's own rounding, without the
  // lens vector's and matrix's quantisation that the comparison with golden includes.
  uint64_t arith_errors = 0;
  double mean_error() const { return samples ? sum_error / static_cast<double>(samples) : 0.0; }
  double exact_share() const { return samples ? static_cast<double>(exact) / static_cast<double>(samples) : 0.0; }
  uint64_t nontie_errors() const { return samples - ties - nontie_exact; }  // nearest texel differs from golden's
  double exact_share_nontie() const {
    return samples > ties ? static_cast<double>(nontie_exact) / static_cast<double>(samples - ties) : 0.0;
  }
  void merge(const Stats& o);
};

// A whole-frame view: an orientation and the lens it is seen through.
struct View {
  std::string name;
  dp::Quat q;           // head orientation, unit
  dp::LensConfig lens;  // the configuration's, or one chosen to put pixels on cube edges
};

// Straight ahead, yaw 90/180/270, pitch +-90, roll 90 (matrix entries exactly
// 0 and +-1), and straight ahead through edge_fov_deg: the views whose exact
// positions fall on texel and face boundaries.
std::vector<View> aligned_views(const dp::ArpConfig& cfg);

// The horizontal field of view that puts the centres of the first and last
// pixel columns on the cube edges of the straight-ahead face: tan(fov/2) =
// W / (W - 1), an undistorted lens centred on the panel.
double edge_fov_deg(int h_active);

struct ViewStats {
  View view;
  bool aligned = false;  // false: a generic view
  Stats stats;
};

// The exact address of a rotated vector p = M v (the exact integer product of
// the quantised matrix and lens vector, before any datapath rounding), with
// the golden reference's face table and tie rule.
struct ExactAddress {
  int face = 0;              // the tie rule's face: X over Y over Z, a zero major component positive
  unsigned tied_faces = 0;   // bit f set for every face whose axis has the largest magnitude
  bool face_tie = false;     // more than one such face
  bool u_tie = false, v_tie = false;  // on `face`, u (v) an integer strictly inside (0, S): a texel boundary
  int x = 0, y = 0;          // nearest texel on `face`: floor(u), floor(v) clamped to the face
  bool tie() const { return face_tie || u_tie || v_tie; }
};
ExactAddress exact_address(const int64_t p[3], int face_size);

// The exact product M v of the quantised matrix and vector (no rounding).
void exact_product(const dp::Mat3q& m, const dp::Vec3q& v, int64_t p[3]);

// Whether texel (face, x, y) is right for the exact product p: on one of the
// tied faces, and on each axis the floor of the exact coordinate or, where
// that coordinate is an integer k, texel k - 1 or k.
bool texel_right(const int64_t p[3], int face_size, int face, int x, int y);

struct WorstCase {
  std::string set;
  double error = 0.0;              // texels
  double dir[3] = {0, 0, 0};       // head-frame direction
  double quat[4] = {1, 0, 0, 0};   // w x y z
  int golden_face = 0, datapath_face = 0;
  double golden_uv[2] = {0, 0}, datapath_uv[2] = {0, 0};
};

// Pixels where datapath and golden address the same face; pixels at a cube
// edge where they pick different faces (a near-tie decided differently by
// the fixed-point inputs) can show a different texel entirely and are
// counted apart, with their own maximum.
struct ColorStats {
  uint64_t pixels = 0;
  uint64_t edge_pixels = 0;      // face differs
  double edge_max_error = 0.0;
  double max_error = 0.0;        // display LSBs, largest channel difference
  double mean_error = 0.0;
  uint64_t exact = 0;            // pixels whose rounded golden colour equals the datapath's
  double p999_error = 0.0;       // 99.9th percentile of the per-pixel error
};

struct Report {
  dp::DatapathWidths widths;
  int face_size = 0;
  Stats frames, random, directed, overall;  // overall: frames + random + directed (the generic pool)
  Stats aligned;                            // the aligned views, pooled; not in overall
  std::vector<ViewStats> views;             // each whole-frame view: the generic ones, then the aligned
  ColorStats color;
  std::vector<WorstCase> worst;             // over every sample, aligned views included
};

// The view of one set (aligned or generic) with the lowest exact share among
// non-ties (then the largest max error); -1 if the set has none.
int worst_view(const Report& r, bool aligned);

Report run(const dp::ArpConfig& cfg, const Options& opt);

std::string to_text(const Report& r);
std::string to_json(const Report& r);  // pretty JSON text

}  // namespace arp::accuracy
