// BVH parse throughput of mocapfill's ReadBvh against Assimp's BVH importer, interleaved
// in one process (best of N rounds each, in thread CPU time so that a busy machine's
// scheduling does not count), so machine load affects both alike. Built and run by
// bench/bvh_read_bench.sh.
//   bvh_read_bench ROUNDS FILE...
#include <assimp/Importer.hpp>
#include <assimp/scene.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "bench/thread_cpu_time.h"
#include "formats/bvh/bvh_reader.h"
#include "formats/file_io.h"

using mocapfill::bench::ThreadCpuSeconds;

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: %s ROUNDS FILE...\n", argv[0]);
    return 1;
  }
  const int rounds = std::max(1, std::atoi(argv[1]));
  const std::vector<std::string> paths(argv + 2, argv + argc);
  double megabytes = 0.0;
  long frames = 0;
  for (const std::string& path : paths) {
    const auto text = mocapfill::ReadFileBytes(path);
    if (!text.ok()) return 1;
    megabytes += text->size() / 1e6;
  }
  double best_ours = 1e30, best_assimp = 1e30;
  for (int round = 0; round < rounds; ++round) {
    frames = 0;
    const double t0 = ThreadCpuSeconds();
    for (const std::string& path : paths) {  // file read included, as in the CLI
      const auto text = mocapfill::ReadFileBytes(path);
      const auto scene = mocapfill::ReadBvh(*text, path, {});
      if (!scene.ok()) {
        std::fprintf(stderr, "%s\n", scene.status().message().c_str());
        return 1;
      }
      frames += scene->clips[0].num_frames;
    }
    const double t1 = ThreadCpuSeconds();
    for (const std::string& path : paths) {
      Assimp::Importer importer;
      if (!importer.ReadFile(path, 0)) {
        std::fprintf(stderr, "assimp: %s\n", importer.GetErrorString());
        return 1;
      }
    }
    const double t2 = ThreadCpuSeconds();
    best_ours = std::min(best_ours, t1 - t0);
    best_assimp = std::min(best_assimp, t2 - t1);
  }
  std::printf("%zu files, %.2f MB, %ld frames\n", paths.size(), megabytes, frames);
  std::printf("  mocapfill ReadBvh  %8.2f ms  %7.1f MB/s  %5.2f ms/MB\n", best_ours * 1e3, megabytes / best_ours,
              best_ours * 1e3 / megabytes);
  std::printf("  assimp ReadFile    %8.2f ms  %7.1f MB/s  %5.2f ms/MB\n", best_assimp * 1e3, megabytes / best_assimp,
              best_assimp * 1e3 / megabytes);
  std::printf("  speed-up           %8.1fx\n", best_assimp / best_ours);
  return 0;
}
