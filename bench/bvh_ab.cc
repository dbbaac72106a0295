// Driver of bench/bvh_ab.sh: the BVH-to-.glb streaming code of two revisions, built into
// this one program under the namespaces bvh_a/bvh_glb_a (the base revision) and
// bvh_x/bvh_glb_x (the working tree), converts each file with one and then the other,
// alternating which goes first, and sums each side's thread CPU time. Both sides see the
// same stretch of machine within milliseconds of each other, so a VM whose speed drifts from
// second to second still resolves differences of a few per cent (docs/performance.md).
//   bvh_ab ROUNDS FILE...
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "bench/thread_cpu_time.h"
#include "formats/file_io.h"
#include "formats/large_buffer.h"
#include "formats/motion_io.h"

// The two renamed copies of formats/bvh_glb/bvh_to_glb.h's declarations (its #pragma once
// lets it be included only once).
#define MOCAPFILL_DECLARE_STREAM(ns)                                                                 \
  namespace mocapfill::ns {                                                                         \
  struct StreamedGlb {                                                                              \
    std::string head;                                                                               \
    LargeBuffer tracks;                                                                             \
    std::vector<unsigned char> tail;                                                                \
  };                                                                                                \
  std::optional<StreamedGlb> StreamBvhToGlb(std::string_view text, const std::string& path,         \
                                            const ImportOptions& options,                           \
                                            const ExportOptions& export_options = {});              \
  }
MOCAPFILL_DECLARE_STREAM(bvh_glb_a)
MOCAPFILL_DECLARE_STREAM(bvh_glb_x)

namespace {

using mocapfill::bench::ThreadCpuSeconds;

// Converts `text` with one side; the .glb's size, or -1 when that side fell back (the
// clip path would then be timed for neither).
template <class Convert>
long Time(Convert convert, double& seconds) {
  const double t0 = ThreadCpuSeconds();
  const auto glb = convert();
  seconds += ThreadCpuSeconds() - t0;
  return glb ? static_cast<long>(glb->head.size() + glb->tracks.size()) : -1;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: %s ROUNDS FILE...\n", argv[0]);
    return 1;
  }
  const int rounds = std::max(1, std::atoi(argv[1]));
  const std::vector<std::string> paths(argv + 2, argv + argc);
  std::vector<std::string> texts;
  for (const std::string& path : paths) {
    auto text = mocapfill::ReadFileBytes(path);
    if (!text.ok()) {
      std::fprintf(stderr, "%s\n", text.status().message().c_str());
      return 1;
    }
    texts.push_back(std::move(*text));
  }
  mocapfill::ImportOptions options;
  options.threads = 1;  // CPU time of one thread: the row loop itself
  double base = 0.0, work = 0.0;
  for (int round = 0; round < rounds; ++round) {
    for (size_t i = 0; i < texts.size(); ++i) {
      const auto run_base = [&] { return mocapfill::bvh_glb_a::StreamBvhToGlb(texts[i], paths[i], options); };
      const auto run_work = [&] { return mocapfill::bvh_glb_x::StreamBvhToGlb(texts[i], paths[i], options); };
      long base_bytes = 0, work_bytes = 0;
      if ((round + i) % 2 == 0) {
        base_bytes = Time(run_base, base);
        work_bytes = Time(run_work, work);
      } else {
        work_bytes = Time(run_work, work);
        base_bytes = Time(run_base, base);
      }
      if (base_bytes < 0 || work_bytes < 0) {
        std::fprintf(stderr, "%s: not a streamed conversion on one side\n", paths[i].c_str());
        return 1;
      }
      if (base_bytes != work_bytes) std::fprintf(stderr, "note: %s: .glb sizes differ (%ld vs %ld)\n", paths[i].c_str(), base_bytes, work_bytes);
    }
  }
  std::printf("base %.3f ms  working tree %.3f ms  working/base %.4f  (%d rounds, %zu files, one thread)\n",
              base * 1e3 / rounds, work * 1e3 / rounds, work / base, rounds, paths.size());
  return 0;
}
