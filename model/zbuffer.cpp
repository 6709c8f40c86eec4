#include "zbuffer.h"

#include <algorithm>
#include <limits>

namespace rastersim {

ZBuffer::ZBuffer(const Profile& p)
    : width_(p.width), height_(p.height), pass_mask_(pass_mask(p.depth_func)), depth_write_(p.depth_write),
      latency_(p.memory_latency), run_kernel_(selected_run_kernel_version().kernel),
      run_kernel_name_(selected_run_kernel_version().name),
      short_run_limit_(selected_run_kernel_version().short_run_limit), memory_(p),
      inflight_address_(size_t(p.memory_latency)), inflight_cycle_(size_t(p.memory_latency)) {
  clear();
}

void ZBuffer::clear() {
  memory_.clear();
  std::fill(inflight_address_.begin(), inflight_address_.end(), std::numeric_limits<uint32_t>::max());
  std::fill(inflight_cycle_.begin(), inflight_cycle_.end(), std::numeric_limits<int64_t>::min() / 2);
  slot_ = 0;
  fresh_ = 0;
  busy_until_ = -1;
  last_read_ = read_before_last_ = -2;
  counters_ = {};
}

}  // namespace rastersim
