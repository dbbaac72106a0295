// The .pca file: a PcaModel (processing/core/pca_model.h) on disk, so `pca edit`, `fill
// --method pca` and the hybrid pipeline reuse a model without rebuilding it.
//
// Layout (little-endian): a 40-byte header {magic "MFPCA\r\n\x1a", u32 version, u32 header
// size, u64 payload size, u64 XXH64 of the payload, u64 reserved zero}, then the payload:
// the model's fields in a fixed order (strings as u32 length + bytes, vectors as u32 count +
// float64 values, matrices as u32 rows + u32 cols + column-major float64). Identical models
// give identical bytes.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "processing/core/pca_model.h"
#include "processing/core/status.h"

namespace mocapfill {

constexpr std::uint32_t kPcaFileVersion = 1;

// The file's bytes. The model should be valid (PcaModel::Validate); WritePcaModel checks.
std::string SerializePcaModel(const PcaModel& model);

// Parses bytes produced by SerializePcaModel. Every failure is kInvalidData saying what was
// wrong: "not a mocapfill PCA model (bad magic)", "unsupported version 7 (this build reads
// 1)", "truncated: header declares N payload bytes, file has M", "checksum mismatch (file
// corrupted)", "truncated while reading <field>", or the inconsistent field.
Result<PcaModel> ParsePcaModel(std::string_view bytes);

// Validates, then writes atomically (WriteFileAtomic). An invalid model is kInvalidArgument;
// an unwritable path kIoError naming it.
Status WritePcaModel(const PcaModel& model, const std::string& path);

// Reads and verifies a file; errors are prefixed with the path. Unreadable file: kIoError.
Result<PcaModel> ReadPcaModel(const std::string& path);

}  // namespace mocapfill
