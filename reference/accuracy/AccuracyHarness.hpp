// Accuracy harness: the datapath (bit-accurate, any widths) against the golden
// reference over (a) every display pixel for several orientations, (b) seeded
// random orientations and pixels, (c) directed extremes -- cube edges and
// corners (exact ties), zero and tiny components, the widest lens angles,
// matrix entries at +-1, the reciprocal at both ends of its range (major
// component 1 and 1/sqrt 3), 90/120/180 degree rotations -- and the colour of
// whole bilinear frames against the golden frame.
#pragma once
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "rtl_model/datapath/ArpConfig.hpp"

namespace arp::accuracy {

struct Options {
  int frame_orientations = 4;       // (a) full frames
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
  double mean_error() const { return samples ? sum_error / static_cast<double>(samples) : 0.0; }
  double exact_share() const { return samples ? static_cast<double>(exact) / static_cast<double>(samples) : 0.0; }
  void merge(const Stats& o);
};

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
  Stats frames, random, directed, overall;
  ColorStats color;
  std::vector<WorstCase> worst;
};

Report run(const dp::ArpConfig& cfg, const Options& opt);

std::string to_text(const Report& r);
std::string to_json(const Report& r);  // pretty JSON text

}  // namespace arp::accuracy
