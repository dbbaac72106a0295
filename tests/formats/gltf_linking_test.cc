// libdraco, which Assimp links, embeds an older tinygltf that exports the same symbol
// names as Debian's libtinygltf 2.7 with a different class layout. Whichever library
// comes first in an executable's NEEDED list wins every tinygltf call, and calls landing
// in draco's copy crashed (LoadBinaryFromFile) or misread fields (the fs callbacks).
// mocapfill_gltf compiles in its own copy under a private namespace name; the test support
// code here calls Debian's libtinygltf, which mocapfill_test_tinygltf (tests/CMakeLists.txt)
// puts first. This binary links libdraco ahead of everything (tests_gltf.cmake), so it
// checks that the fix holds in the worst case.
#include <dlfcn.h>
#include <gtest/gtest.h>

#include <string>

namespace mocapfill {
namespace {

TEST(GltfLinking, TinygltfCallsBindToLibtinygltfWhenDracoIsLinkedFirst) {
  if (dlopen("libdraco.so.7", RTLD_NOW | RTLD_NOLOAD) == nullptr)
    GTEST_SKIP() << "libdraco is not loaded in this binary: no competing tinygltf copy";
  const char* symbols[] = {
      "_ZN8tinygltf8TinyGLTF20LoadBinaryFromMemoryEPNS_5ModelEPNSt7__cxx1112basic_stringIcSt11char_traitsIcESaIcEEES9_PKhjRKS8_j",
      "_ZN8tinygltf8TinyGLTF19LoadASCIIFromStringEPNS_5ModelEPNSt7__cxx1112basic_stringIcSt11char_traitsIcESaIcEEES9_PKcjRKS8_j",
      "_ZN8tinygltf8TinyGLTF14SetImageLoaderEPFbPNS_5ImageEiPNSt7__cxx1112basic_stringIcSt11char_traitsIcESaIcEEES9_iiPKhiPvESC_",
  };
  for (const char* symbol : symbols) {
    void* address = dlsym(RTLD_DEFAULT, symbol);
    ASSERT_NE(address, nullptr) << symbol;
    Dl_info info;
    ASSERT_NE(dladdr(address, &info), 0) << symbol;
    EXPECT_NE(std::string(info.dli_fname).find("libtinygltf"), std::string::npos)
        << symbol << " binds to " << info.dli_fname;
  }
}

}  // namespace
}  // namespace mocapfill
