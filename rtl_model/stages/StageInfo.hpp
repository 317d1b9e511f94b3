// The pipeline's stages by name, in data-flow order: each block's name (its
// module's instance), what its input and output carry (the FIFO between two
// stages is named by the first one's output, which is the next one's input)
// and what its three waveform data probes show. One table: the stages, the
// modules, the FIFOs and the waveforms take their names from here.
#pragma once
#include "StageContext.hpp"

namespace arp::stage {

constexpr int id_of(dp::Stage s) { return static_cast<int>(s); }

inline constexpr StageInfo kVideoTimingInfo{-1, "video_timing_generator", nullptr, "pixel_requests", {}};
inline constexpr StageInfo kLensVectorInfo{id_of(dp::Stage::Lens), "lens_vector_table", "pixel_requests", "view_vectors", {"view_x", "view_y", "view_z"}};
inline constexpr StageInfo kOrientationInfo{id_of(dp::Stage::Rotate), "orientation_matrix_unit", "view_vectors", "world_vectors", {"world_x", "world_y", "world_z"}};
inline constexpr StageInfo kAddressInfo{id_of(dp::Stage::Address), "cube_face_address_generator", "world_vectors", "cube_addresses", {"face", "texel_x", "texel_y"}};
inline constexpr StageInfo kMemoryReadInfo{id_of(dp::Stage::Fetch), "display_memory_banks", "cube_addresses", "texel_words", {"word_tap0_mem0", "weight_x", "weight_y"}};
inline constexpr StageInfo kCompositionInfo{id_of(dp::Stage::Compose), "composition_unit", "texel_words", "composed_taps", {"color_tap0", "color_tap1", "weight_x"}};
inline constexpr StageInfo kFilterInfo{id_of(dp::Stage::Filter), "anti_aliasing_filter", "composed_taps", "pixel_colors", {"color", "x", "y"}};
inline constexpr StageInfo kScanOutInfo{id_of(dp::Stage::ScanOut), "hmd_scan_out", "pixel_colors", nullptr, {}};

}  // namespace arp::stage
