#include "processing/core/signal_layout.h"

namespace mocapfill {

const char* RootFeatureName(int feature) {
  switch (feature) {
    case kRootHeight: return "root.height_m";
    case kRootForward: return "root.forward_mps";
    case kRootLateral: return "root.lateral_mps";
    case kRootYawRate: return "root.yaw_rate_radps";
    default: return "root.unknown";
  }
}

}  // namespace mocapfill
