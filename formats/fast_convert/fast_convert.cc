#include "formats/fast_convert/fast_convert.h"

#include <malloc.h>

#include <string_view>
#include <utility>

#include "formats/atomic_writer.h"
#include "formats/bvh/bvh_reader.h"
#include "formats/fast_convert/bvh_to_glb.h"
#include "formats/fast_convert/file_text.h"
#include "formats/fast_convert/large_buffer.h"
#include "formats/fast_convert/rows_in_parallel.h"
#include "formats/file_io.h"

namespace mocapfill::fast_convert {

namespace {

// The heap a one-shot conversion of a typical clip uses (about 460 KB for a Bandai-Namco
// clip), mapped at once instead of faulted in a page at a time.
constexpr size_t kStartHeapBytes = size_t{512} << 10;

}  // namespace

std::optional<ConvertResult> ConvertBvh(const std::string& input, const std::string& output,
                                        const ImportOptions& import_options, const ExportOptions& export_options,
                                        const ConvertOptions& convert_options, AtomicWriter* writer,
                                        const SceneExport& export_scene) {
  if (LowerExtension(input) != ".bvh") return std::nullopt;
  ConvertResult result;
  Result<FileText> text =
      ReadFileText(input, convert_options.leave_input_to_exit ? kMapLeftInputMinBytes : kMapFileMinBytes);
  if (!text.ok()) {
    result.status = text.status();
    return result;
  }
  if (LowerExtension(output) == ".glb") {
    std::optional<StreamedGlb> glb =
        StreamBvhToGlb(text->view(), input, import_options, export_options, convert_options.threads);
    if (glb && text->intact()) {
      const std::string_view tail(reinterpret_cast<const char*>(glb->tail.data()), glb->tail.size());
      result.status = WriteFileAtomicParts(output, {glb->head, glb->tracks.view(), tail}, writer);
      result.failed_writing = !result.status.ok();
      if (convert_options.leave_input_to_exit) text->LeaveToExit();
      return result;
    }
  }
  Result<Scene> scene =
      ReadBvh(text->view(), input, import_options, convert_options.threads == 1 ? nullptr : &ParseRowsIntoClip);
  // A file truncated while mapped: what it holds now, read afresh by the general path, is the input.
  if (!text->intact()) return std::nullopt;
  if (convert_options.leave_input_to_exit) text->LeaveToExit();
  if (!scene.ok()) {
    result.status = scene.status();
    return result;
  }
  result.warnings = std::move(scene->warnings);
  result.status = export_scene(*scene);
  result.failed_writing = !result.status.ok();
  return result;
}

void PrepareProcess() { ReserveMappedHeap(kStartHeapBytes); }

void PrepareBatch() {
  mallopt(M_MMAP_THRESHOLD, 32 << 20);
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
}

}  // namespace mocapfill::fast_convert
