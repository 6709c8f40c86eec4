#include "zbuffer.h"

#include <algorithm>
#include <limits>

namespace rastersim {

ZBuffer::ZBuffer(const Profile& p) : ZBufferState(p, pass_mask(p.depth_func)) { clear(); }

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
