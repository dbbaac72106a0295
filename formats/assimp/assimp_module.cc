// The entry points of mocapfill_assimp.so (see assimp_module_abi.h).
#include "formats/assimp/assimp_module_abi.h"
#include "formats/assimp/assimp_reader.h"

#include <exception>
#include <string_view>

extern "C" {

[[gnu::visibility("default")]] uint64_t mocapfill_assimp_module_abi() { return mocapfill::assimp_module::kAbiKey; }

[[gnu::visibility("default")]] void mocapfill_assimp_module_read(const std::string* path,
                                                                 const mocapfill::ImportOptions* options,
                                                                 mocapfill::Result<mocapfill::Scene>* out) {
  // Nothing may unwind across the dlopen boundary.
  try {
    *out = mocapfill::ReadWithAssimp(*path, *options);
  } catch (const std::exception& e) {
    *out = mocapfill::Internal(*path + ": the Assimp reader failed: " + e.what());
  } catch (...) {
    *out = mocapfill::Internal(*path + ": the Assimp reader failed");
  }
}

}  // extern "C"

// The loader looks these up by name: keep the names in one place.
static_assert(std::string_view("mocapfill_assimp_module_abi") == mocapfill::assimp_module::kAbiSymbol);
static_assert(std::string_view("mocapfill_assimp_module_read") == mocapfill::assimp_module::kReadSymbol);
