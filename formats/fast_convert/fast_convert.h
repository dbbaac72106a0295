// The convert fast path, as ConvertFile (formats/motion_io.h) reaches it: everything in this
// folder exists to make a BVH conversion faster, not different. Inputs are mapped rather than
// read (file_text.h), large motion sections are parsed on two threads (rows_in_parallel.h),
// a BVH becoming a .glb goes straight into its float32 tracks (bvh_to_glb.h), and memory comes
// in huge pages where it is large (large_buffer.h). It needs Linux and glibc (mmap, SIGBUS,
// thread affinity, glibc's CPU features) and is built when MOCAPFILL_FAST_CONVERT is on;
// otherwise portable.cc stands in, and ConvertFile's general path gives the same bytes.
#pragma once

#include <functional>
#include <optional>
#include <string>

#include "formats/motion_io.h"

namespace mocapfill::fast_convert {

// Writes a converted scene as ExportFile does (given by ConvertFile, which owns export).
using SceneExport = std::function<Status(const Scene&)>;

// ConvertFile for a BVH input: the text read or mapped once; a .glb output streamed from it
// when the import is a plain one; otherwise the clip read from it (rows on two threads when
// they are many) and handed to `export_scene`. nullopt for any other input, or where the
// build has no fast path: ConvertFile's general path converts it.
std::optional<ConvertResult> ConvertBvh(const std::string& input, const std::string& output,
                                        const ImportOptions& import_options, const ExportOptions& export_options,
                                        const ConvertOptions& convert_options, AtomicWriter* writer,
                                        const SceneExport& export_scene);

// PrepareConversionProcess and PrepareBatchConversion (motion_io.h).
void PrepareProcess();
void PrepareBatch();

}  // namespace mocapfill::fast_convert
