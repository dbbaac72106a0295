// The fast path's stand-in for builds without it (MOCAPFILL_FAST_CONVERT off: any platform
// other than Linux on x86-64 with glibc, or by choice): ConvertFile's general path does all.
#include "formats/fast_convert/fast_convert.h"

namespace mocapfill::fast_convert {

std::optional<ConvertResult> ConvertBvh(const std::string&, const std::string&, const ImportOptions&,
                                        const ExportOptions&, const ConvertOptions&, AtomicWriter*,
                                        const SceneExport&) {
  return std::nullopt;
}

void PrepareProcess() {}

void PrepareBatch() {}

}  // namespace mocapfill::fast_convert
