// Image error of a displayed frame against a reference frame (PSNR over the
// colour channels), and the displacement of tracked points: for each object,
// the angle between where its memory's image shows it (seen from the eye
// position and at the time that image was rendered) and where it truly is at
// photon time, in display pixels.
#pragma once
#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

#include "rtl_model/datapath/HmdFrame.hpp"

namespace arp::host {

struct ImageError {
  double mse = 0;         // per channel, in display codes squared
  double psnr_db = 0;     // infinity when identical
  double differing = 0;   // share of pixels with any channel different
};

ImageError image_error(const HmdFrame& shown, const HmdFrame& reference);

// A frame n times as wide and as high brought to its own size: each pixel's channels the mean of the n x n
// pixels over it, rounded to the nearest code (halves up). Photon times are not kept.
HmdFrame area_mean(const HmdFrame& fine, int n);

// Angle (radians) between two directions from eyes to a point seen then and now.
double displacement_rad(const glm::dvec3& eye_then, const glm::dvec3& point_then, const glm::dvec3& eye_now,
                        const glm::dvec3& point_now);

}  // namespace arp::host
