// Reading and writing motion files by extension. The only entry points the CLI and
// the tests need; each format lives in its own folder behind these two functions.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "processing/core/scene.h"
#include "processing/core/status.h"

namespace mocapfill {

class AtomicWriter;  // formats/atomic_writer.h

struct ImportOptions {
  // Length unit of the source: "auto" (format default, or detected from skeleton height
  // when that default is implausible), or a name of UnitNames() (units_axes.h).
  // Everything is converted to metres on import.
  std::string unit = "auto";
  // Up axis of the source: "auto" (format default: Y for BVH/glTF, the file's own for FBX),
  // "y" or "z". Z-up sources are rotated to glTF's Y-up on import.
  std::string up = "auto";
  // Sampling rate for keyed sources (glTF, FBX), Hz. 0 = detect from the key times.
  double rate_hz = 0.0;
  // glTF/FBX: which animation to import, by name or index. Empty = every animation.
  std::string animation;
  // Promote recoverable warnings (e.g. a BVH frame-count mismatch) to errors.
  bool strict = false;
};

// glTF output for a scene without a skinned mesh of its own (a BVH, or bare animated nodes).
// Importers of game engines and Blender build a skeleton only from a skin.
enum class GltfSkeleton {
  kNodes,         // the joints as plain animated nodes (no skin)
  kSkin,          // plus a skin over every joint, bound in the rest pose
  kSkinAndMesh,   // plus a stick-figure mesh bound to that skin, so the skeleton shows
};

// BVH output layout.
enum class BvhLayout {
  kSource,    // each joint's channels as the source had them (exact re-export)
  // Three rotation channels on every joint; position channels (XYZ, with a zero OFFSET)
  // only on joints whose translation moves. Readers that add position channels to the
  // OFFSET and readers that replace it then read the same motion.
  kStandard,
};

struct ExportOptions {
  // BVH output unit: "auto" writes in the source's unit (recorded on import), else as ImportOptions::unit.
  std::string unit = "auto";
  // glTF: pretty-print the JSON of .gltf output.
  bool pretty = true;
  GltfSkeleton gltf_skeleton = GltfSkeleton::kSkin;
  BvhLayout bvh_layout = BvhLayout::kSource;
};

// Parses "nodes" / "skin" / "mesh" and "source" / "standard" (the CLI and pipeline spellings).
std::optional<GltfSkeleton> ParseGltfSkeleton(const std::string& name);
std::optional<BvhLayout> ParseBvhLayout(const std::string& name);

// Reads any supported file: .bvh, .gltf, .glb, and (through Assimp) .fbx and other
// Assimp formats. Errors name the file and the line or field.
Result<Scene> ImportFile(const std::string& path, const ImportOptions& options = {});

// Writes .gltf, .glb or .bvh by the extension of `path`. The write is atomic: the file
// appears complete or not at all, and an existing file is replaced only on success. A
// caller writing many files passes its own `writer` (one per thread), which recycles the
// replaced files (atomic_writer.h).
Status ExportFile(const Scene& scene, const std::string& path, const ExportOptions& options = {},
                  AtomicWriter* writer = nullptr);

// How ConvertFile may use the machine; the bytes written are the same whatever they say.
struct ConvertOptions {
  // Threads that may work on this one file: 0 = the converter decides (a large BVH motion
  // section is parsed on two), 1 = the calling thread only (for callers that already spread
  // many files over the cores).
  int threads = 0;
  // For a process that ends soon after this conversion (one file converted from the command
  // line): a mapped input is left mapped for the process's exit to tear down, which it does
  // without the cross-CPU TLB flush an munmap pays once a second thread has run, and so
  // smaller inputs are mapped. Many conversions in one process leave it false, or their
  // mappings pile up.
  bool leave_input_to_exit = false;
};

// ImportFile then ExportFile, in one step: what a converter calls. Where the build has the
// convert fast path (formats/fast_convert/, on x86-64 glibc), a BVH becoming a .glb is
// streamed: its rows go straight into the .glb's float32 tracks, with no double-precision
// clip in between, when the import is a plain one (no warning, Y-up); the bytes written are
// the same either way. `failed_writing` tells an output failure from an input failure.
struct ConvertResult {
  Status status;
  bool failed_writing = false;
  std::vector<std::string> warnings;  // of the import
};
ConvertResult ConvertFile(const std::string& input, const std::string& output, const ImportOptions& import_options,
                          const ExportOptions& export_options, const ConvertOptions& convert_options = {},
                          AtomicWriter* writer = nullptr);

// For a process about to convert files and exit (the command line's convert): prepares the
// process's memory for that where the fast path can (a heap grown and mapped up front, so
// that small allocations do not fault in one page at a time); nothing elsewhere.
void PrepareConversionProcess();
// For a process about to convert many files one after another: freed buffers stay with the
// process for the next file instead of going back to the kernel and being faulted in afresh
// (where the fast path can; nothing elsewhere).
void PrepareBatchConversion();

// Every importable file under `paths` (files are taken as given, folders recursively),
// sorted by path and de-duplicated. Errors: a path that does not exist (kIoError), no
// importable file found (kInvalidArgument).
Result<std::vector<std::string>> ListMotionFiles(const std::vector<std::string>& paths);

// True when the extension is one ImportFile reads / ExportFile writes.
bool IsImportExtension(const std::string& path);
// True when ImportFile reads the file through Assimp (.fbx, .dae and the other Assimp formats).
bool IsAssimpInput(const std::string& path);
bool IsExportExtension(const std::string& path);

}  // namespace mocapfill
