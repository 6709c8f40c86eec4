#include "zbuffer.h"

#include <algorithm>
#include <limits>

namespace rastersim {

ZBuffer::ZBuffer(const Profile& p)
    : width_(p.width), height_(p.height), pass_mask_(pass_mask(p.depth_func)), depth_write_(p.depth_write),
      clear_depth_(p.depth_clear_value()), latency_(p.memory_latency),
      depth_(size_t(p.width) * p.height), color_(size_t(p.width) * p.height),
      inflight_address_(size_t(p.memory_latency)), inflight_cycle_(size_t(p.memory_latency)) {
  clear();
}

void ZBuffer::clear() {
  std::fill(depth_.begin(), depth_.end(), clear_depth_);
  std::fill(color_.begin(), color_.end(), 0u);
  std::fill(inflight_address_.begin(), inflight_address_.end(), std::numeric_limits<uint32_t>::max());
  std::fill(inflight_cycle_.begin(), inflight_cycle_.end(), std::numeric_limits<int64_t>::min() / 2);
  slot_ = 0;
  fresh_ = 0;
  busy_until_ = -1;
  counters_ = {};
}

}  // namespace rastersim
