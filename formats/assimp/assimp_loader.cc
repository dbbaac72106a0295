#include "formats/assimp/assimp_loader.h"

#include <dlfcn.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <vector>

#include "formats/assimp/assimp_module_abi.h"
#include "formats/assimp/isolated_read.h"

#ifndef MOCAPFILL_ASSIMP_MODULE_BUILD_PATH
#define MOCAPFILL_ASSIMP_MODULE_BUILD_PATH ""
#endif

namespace mocapfill {

namespace {

namespace fs = std::filesystem;

// Where the module may be, in order: $MOCAPFILL_ASSIMP_MODULE (an explicit file), beside
// the executable (the build tree), <prefix>/lib/mocapfill/ (installed: the executable is
// in <prefix>/bin, or mocapfill-full in <prefix>/libexec/mocapfill), <libdir>/mocapfill/
// beside the shared library holding this code (the public API's, in <prefix>/lib), and the
// path it was built at (test programs in the build tree).
std::vector<std::string> Candidates() {
  std::vector<std::string> paths;
  if (const char* env = std::getenv("MOCAPFILL_ASSIMP_MODULE"); env != nullptr && *env != '\0') {
    paths.emplace_back(env);
    return paths;  // explicit: nothing else is tried
  }
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const fs::path dir = exe.parent_path();
    paths.push_back((dir / assimp_module::kFileName).string());
    paths.push_back((dir.parent_path() / "lib" / "mocapfill" / assimp_module::kFileName).string());
    paths.push_back((dir.parent_path().parent_path() / "lib" / "mocapfill" / assimp_module::kFileName).string());
  }
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&ReadWithAssimpModule), &info) != 0 && info.dli_fname != nullptr) {
    const fs::path library = fs::weakly_canonical(fs::absolute(info.dli_fname, ec), ec);
    if (!ec && library.filename().string().find(".so") != std::string::npos)
      paths.push_back((library.parent_path() / "mocapfill" / assimp_module::kFileName).string());
  }
  const std::string built = MOCAPFILL_ASSIMP_MODULE_BUILD_PATH;
  if (!built.empty()) paths.push_back(built);
  return paths;
}

struct Module {
  assimp_module::ReadFunction read = nullptr;
  std::string error;  // why it could not be loaded
};

Module Load() {
  Module module;
  std::string tried;
  for (const std::string& path : Candidates()) {
    tried += "\n  " + path;
    std::error_code ec;
    if (!fs::exists(path, ec)) {
      tried += " (not found)";
      continue;
    }
    // RTLD_LOCAL: libassimp's dependencies (libdraco embeds an old tinygltf) stay out of
    // the global symbol scope.
    void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (handle == nullptr) {
      const char* why = dlerror();
      tried += std::string(" (") + (why ? why : "dlopen failed") + ")";
      continue;
    }
    auto abi = reinterpret_cast<assimp_module::AbiFunction>(dlsym(handle, assimp_module::kAbiSymbol));
    auto read = reinterpret_cast<assimp_module::ReadFunction>(dlsym(handle, assimp_module::kReadSymbol));
    if (abi == nullptr || read == nullptr || abi() != assimp_module::kAbiKey) {
      tried += " (from another build of mocapfill)";
      dlclose(handle);
      continue;
    }
    module.read = read;  // kept loaded for the life of the process
    return module;
  }
  module.error = std::string("the Assimp plug-in ") + assimp_module::kFileName +
                 " is not installed or cannot be loaded; looked in:" + tried;
  return module;
}

const Module& GetModule() {
  static std::once_flag once;
  static Module module;
  std::call_once(once, [] { module = Load(); });
  return module;
}

}  // namespace

Result<Scene> ReadWithAssimpModule(const std::string& path, const ImportOptions& options) {
  const Module& module = GetModule();  // loaded here, before the fork, so the child need not
  if (module.read == nullptr) return Unsupported(path + ": cannot read this format: " + module.error);
  // Assimp is known to crash on some files (a 200,000-deep BVH overflows its stack): it reads
  // in a child process, whose failure becomes this file's error.
  return ReadIsolated(path, IsolationLimitsFromEnvironment(), [&]() -> Result<Scene> {
    Result<Scene> scene = Status(ErrorCode::kInternal, "the Assimp plug-in returned nothing");
    module.read(&path, &options, &scene);
    return scene;
  });
}

}  // namespace mocapfill
