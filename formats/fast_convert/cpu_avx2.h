// Whether this CPU runs AVX2 code, as glibc recorded it at start-up, for the row loop's and
// the track packer's AVX2 variants. __builtin_cpu_supports and target_clones would ask the
// CPU again through libgcc's start-up hook, whose cpuid instructions trap to the hypervisor
// in a VM on every process start. Only x86-64 glibc builds with the fast path
// (MOCAPFILL_FAST_CONVERT) have the AVX2 variants: MOCAPFILL_AVX2_VARIANTS says so, and
// elsewhere CpuHasAvx2() is false and the portable loops run.
#pragma once

#include <cstddef>  // defines __GLIBC__ where the C library is glibc

#if defined(MOCAPFILL_FAST_CONVERT) && defined(__x86_64__) && defined(__GLIBC__)
#define MOCAPFILL_AVX2_VARIANTS 1
#if defined(__clang__) && !defined(_Bool)
// glibc 2.36's header declares its functions with C's _Bool, which g++ accepts in C++ and
// clang++ does not (the fuzz and sanitizer builds use clang).
#define _Bool bool
#include <sys/platform/x86.h>
#undef _Bool
#else
#include <sys/platform/x86.h>
#endif
#else
#define MOCAPFILL_AVX2_VARIANTS 0
#endif

namespace mocapfill {

inline bool CpuHasAvx2() {
#if MOCAPFILL_AVX2_VARIANTS
  static const bool avx2 = CPU_FEATURE_ACTIVE(AVX2);
  return avx2;
#else
  return false;
#endif
}

}  // namespace mocapfill
