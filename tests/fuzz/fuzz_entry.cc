// The libFuzzer entry point of one fuzz program: MOCAPFILL_FUZZ_FUNCTION names the target
// (tests/fuzz/CMakeLists.txt builds one program per target from this file).
#include "tests/fuzz/fuzz_targets.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return mocapfill::fuzz::MOCAPFILL_FUZZ_FUNCTION(data, size);
}
