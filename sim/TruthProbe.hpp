// The error of a priority-rendered walk against the truth, for `arpsim run
// --walk`: fresh memories rendered, everything, for the true eye positions at
// the frame's middle and read through the same pipeline. Per measured frame:
// PSNR, the largest tracked-point displacement, the share of pixels showing
// another object (found through the pipeline's own addressing and depth
// composition), and with regions the tear, gap and crack pixels along the
// seams (host/error/SeamMetrics) and the magnified tear (host/error/TearImage).
#pragma once
#include <nlohmann/json.hpp>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "host/cubemap/CubeMapImages.hpp"
#include "host/error/TearImage.hpp"
#include "host/motion/WalkPath.hpp"
#include "host/priority/HostSimulation.hpp"
#include "rtl_model/datapath/VideoTiming.hpp"
#include "host/regions/Segmentation.hpp"
#include "rtl_model/datapath/ArpConfig.hpp"
#include "rtl_model/datapath/CubeFaceAddressGenerator.hpp"
#include "rtl_model/datapath/LensVectorTable.hpp"
#include "rtl_model/datapath/OrientationMatrixUnit.hpp"
#include "rtl_model/functional/FunctionalModel.hpp"

namespace arp::sim {

struct TruthProbeSetup {
  const dp::ArpConfig* config = nullptr;
  const host::Scene* scene = nullptr;
  const host::WalkPath* walk = nullptr;
  const host::HostSimulation* host = nullptr;
  const dp::DisplayMemorySet* memories = nullptr;
  const dp::OrientationStream* orientation = nullptr;
  const host::Segmented* segmented = nullptr;  // region mode with segmentation; nullptr otherwise
  double ipd_m = dp::kDefaultIpdM;
  int threads = 0;
  int64_t first_frame = 0, frames = 1, every = 1;  // the frames measured: first + k * every
  int truth_face_size = 0;  // 0: the truth reads as the run does; N: one reference at face size N (TruthProbe.cpp)
  int supersample = 1;      // the truth's pixels: the mean of N x N samples over each (its pipeline at N x the resolution)
  std::string tear_image, tear_at;                 // --tear-image, --tear-at FRAME:EYE:X:Y
};

// The truth's image pipeline at n times the display's resolution over the same field: every active and
// blanking count n times and the pixel clock n^2 times, so the frame and each display line keep their time
// (the n rows of samples of a display line are taken within it, each in 1/n of its time: up to a line,
// 32 us at the default display, from the instant the run takes the pixel's sample), and the lens centre's
// offset n times. At n = 1, `truth` itself.
dp::ArpConfig truth_image_config(const dp::ArpConfig& truth, int n);

// Where --tear-at FRAME:EYE:X:Y puts the magnified tear window (frame -1: none given).
struct TearAt {
  int64_t frame = -1;
  int eye = 0, x = 0, y = 0;
};
// --tear-at read and checked against the run: four non-negative whole numbers, a frame the run measures
// (first_frame + k x every, before first_frame + frames), a window inside one eye's image of `t`; else an InputError
// naming --tear-at. The run checks it before any work, the probe reads it again.
TearAt parse_tear_at(const std::string& text, int64_t first_frame, int64_t frames, int64_t every, const dp::VideoTimingConfig& t);

class TruthProbe {
 public:
  // InputError for a --tear-at that this run will not measure or that falls outside the image.
  explicit TruthProbe(const TruthProbeSetup& s);
  ~TruthProbe();
  // Measures frame `frame` (shown as `f`); its per-frame figures go into out["error"].
  void measure(const HmdFrame& f, int64_t frame, nlohmann::json& out);
  bool measured() const { return !psnrs_.empty(); }
  // The run's summary (means and worsts) for the report.
  nlohmann::json summary() const;
  // Writes the magnified tear; returns the line to print. InputError if no measured frame had a seam.
  std::string write_tear_image() const;

  static constexpr int kTearWindowW = 48, kTearWindowH = 32, kTearScale = 8;

 private:
  TruthProbeSetup s_;
  TearAt tear_at_;
  dp::ArpConfig truth_cfg_;        // the truth's memory and arithmetic, at the run's display (what each pixel addresses)
  dp::ArpConfig truth_image_cfg_;  // the same at N x the display's resolution (its image; = truth_cfg_ at N = 1)
  dp::VideoTiming timing_;         // the run's
  std::unique_ptr<dp::DisplayMemorySet> truth_mem_;
  std::unique_ptr<FunctionalModel> truth_model_;
  dp::LensVectorTable lens_;
  dp::RotateParams rot_;
  dp::AddressGeneratorParams addr_;
  bool own_truth_;  // the truth reads as the run does (its face size, widths and format)
  std::optional<dp::LensVectorTable> truth_lens_;  // only when the truth's widths are its own
  dp::RotateParams truth_rot_;
  dp::AddressGeneratorParams truth_addr_;
  dp::LatchRule latch_;
  double px_rad_;
  std::vector<std::vector<host::FaceImage>> truth_ids_;
  std::vector<double> psnrs_;
  double worst_object_share_ = 0;
  double worst_rad_ = 0;  // the largest tracked-point displacement, an angle (pixels: / px_rad_)
  std::vector<int64_t> tears_, gaps_, cracks_;
  host::TearWindow tear_best_;
  int64_t tear_frame_ = -1;
  host::RgbImage tear_picture_;
};

}  // namespace arp::sim
