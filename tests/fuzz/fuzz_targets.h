// Fuzz targets: each takes arbitrary bytes and hands them to one reader of the tool. A
// refused input is the expected outcome; crashes, sanitizer reports, leaks, hangs and
// out-of-memory are the findings. The same functions are linked into the libFuzzer
// programs (fuzz_entry.cc, built by tools/fuzz.sh) and into the replay test that runs the
// kept regression inputs in the ordinary test run (fuzz_replay_test.cc).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace mocapfill::fuzz {

using FuzzFunction = int (*)(const uint8_t* data, size_t size);

int FuzzBvh(const uint8_t* data, size_t size);       // BVH text (ReadBvh)
int FuzzGltf(const uint8_t* data, size_t size);      // .gltf JSON or .glb, external buffers beside it
int FuzzMfdb(const uint8_t* data, size_t size);      // motion database file (ParseMfdb)
int FuzzPca(const uint8_t* data, size_t size);       // PCA model file (ParsePcaModel)
int FuzzPipeline(const uint8_t* data, size_t size);  // pipeline JSON, parsed and validated as `run --dry-run` does
int FuzzMaps(const uint8_t* data, size_t size);      // joint-name map (db build --map) and rig map (fill --map)
int FuzzFbx(const uint8_t* data, size_t size);       // .fbx through ImportFile: Assimp in its child process
int FuzzWire(const uint8_t* data, size_t size);      // the child's answer (DecodeSceneResult), raw and patched

struct FuzzTarget {
  const char* name;  // also the folder of its regression inputs: tests/fuzz/regressions/<name>/
  FuzzFunction run;
};

// Every target, in the order tools/fuzz.sh runs them.
const std::vector<FuzzTarget>& AllFuzzTargets();

}  // namespace mocapfill::fuzz
