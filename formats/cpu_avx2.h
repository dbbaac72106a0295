// Whether this CPU runs AVX2 code, as glibc recorded it at start-up. __builtin_cpu_supports
// and target_clones ask the CPU again through libgcc's start-up hook, whose cpuid
// instructions each trap to the hypervisor in the VMs mocapfill is measured on: 0.05-0.1 ms
// of every process (a static test program with the hook against one without, perf stat).
#pragma once

#if defined(__clang__) && !defined(_Bool)
// glibc 2.36's header declares its functions with C's _Bool, which g++ accepts in C++ and
// clang++ does not (the fuzz and sanitizer builds use clang).
#define _Bool bool
#include <sys/platform/x86.h>
#undef _Bool
#else
#include <sys/platform/x86.h>
#endif

namespace mocapfill {

inline bool CpuHasAvx2() {
  static const bool avx2 = CPU_FEATURE_ACTIVE(AVX2);
  return avx2;
}

}  // namespace mocapfill
