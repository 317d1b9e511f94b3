// An HMD frame as an image the user can open: eyes side by side (left eye on
// the left), display colour rescaled to 8 bits per channel.
#pragma once
#include "host/cubemap/CubeMapImages.hpp"
#include "rtl_model/datapath/HmdFrame.hpp"

namespace arp::sim {

host::RgbImage frame_to_image(const HmdFrame& f);

}  // namespace arp::sim
