#include "AddressStage.hpp"

namespace arp::stage {

AddressStage::AddressStage(const StageContext& ctx)
    : RegisteredStage(ctx),
      addr_(ctx.config().widths, ctx.config().memory.face_size),
      memo_(dp::tabulate_aligned_reciprocal(addr_, ctx.config().widths)),
      memo_ptr_(memo_.empty() ? nullptr : memo_.data()) {}

}  // namespace arp::stage
