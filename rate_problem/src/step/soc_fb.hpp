#pragma once
// The FB / SOC-FB kernels live in lcp (cpkit/lcp/detail/soc_fb.hpp), shared with the friction
// solver fb-soc; the 3-D step solvers use them under their old names.
#include "cpkit/lcp/detail/soc_fb.hpp"

namespace cpkit::rate3d::detail {
using cpkit::lcp::detail::fb_scalar;
using cpkit::lcp::detail::fb_soc;
using cpkit::lcp::detail::kFbZero;
}  // namespace cpkit::rate3d::detail
