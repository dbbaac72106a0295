#include "formats/gltf/gltf_tracks.h"

namespace mocapfill {

Status PackFrameTimes(const std::string& clip_name, size_t frames, double rate_hz, float* times) {
  for (size_t f = 0; f < frames; ++f) {
    times[f] = static_cast<float>(static_cast<double>(f) / rate_hz);
    if (f > 0 && times[f] <= times[f - 1])
      return Unsupported("clip '" + clip_name + "': frame times " + std::to_string(f - 1) + " and " +
                         std::to_string(f) + " are equal in float32; the clip is too long for its frame rate");
  }
  return OkStatus();
}

}  // namespace mocapfill
