#include "formats/mfdb/mfdb_file.h"

#include <bit>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <algorithm>
#include <functional>
#include <memory>
#include <vector>

#include "formats/file_io.h"
#include "formats/mfdb/mfdb_meta.h"
#include "formats/mfdb/xxhash64.h"

namespace mocapfill {

static_assert(std::endian::native == std::endian::little, ".mfdb I/O copies little-endian memory as is");

namespace {

constexpr char kMagic[8] = {'M', 'F', 'D', 'B', '\r', '\n', '\x1a', '\n'};
constexpr size_t kHeaderSize = 64;
constexpr size_t kSectionHeaderSize = 64;
constexpr size_t kAlign = 64;

constexpr std::uint32_t Tag(const char (&s)[5]) {
  return std::uint32_t(std::uint8_t(s[0])) | std::uint32_t(std::uint8_t(s[1])) << 8 |
         std::uint32_t(std::uint8_t(s[2])) << 16 | std::uint32_t(std::uint8_t(s[3])) << 24;
}
constexpr std::uint32_t kMetaTag = Tag("META");
constexpr std::uint32_t kSignalsTag = Tag("SIGN");
constexpr std::uint32_t kTranslationsTag = Tag("TRAN");
constexpr std::uint32_t kBandTag = Tag("BAND");
constexpr std::uint32_t kCorrelationTag = Tag("CORR");
constexpr size_t kCorrelationEntryBytes = 12;  // float max_abs, float value, int32 lag

template <typename T>
void Put(std::string& out, size_t offset, T value) {
  std::memcpy(out.data() + offset, &value, sizeof(T));
}

void AppendSection(std::string& out, std::uint32_t tag, const void* data, size_t size) {
  const size_t at = out.size();
  out.resize(at + kSectionHeaderSize, '\0');
  Put(out, at, tag);
  Put(out, at + 8, static_cast<std::uint64_t>(size));
  out.append(static_cast<const char*>(data), size);
  out.resize((out.size() + kAlign - 1) / kAlign * kAlign, '\0');
}

size_t Padding(size_t size) { return (kAlign - size % kAlign) % kAlign; }

// Where the bytes come from: a memory buffer or a file read piece by piece, so a file is
// never held twice in memory.
class Source {
 public:
  virtual ~Source() = default;
  virtual bool Read(void* dst, size_t size) = 0;
};

class MemorySource : public Source {
 public:
  explicit MemorySource(std::string_view bytes) : bytes_(bytes) {}
  bool Read(void* dst, size_t size) override {
    if (size > bytes_.size() - pos_) return false;
    if (size == 0) return true;  // dst may be the null data() of an empty buffer
    std::memcpy(dst, bytes_.data() + pos_, size);
    pos_ += size;
    return true;
  }

 private:
  std::string_view bytes_;
  size_t pos_ = 0;
};

class FileSource : public Source {
 public:
  explicit FileSource(std::FILE* file) : file_(file) {}
  bool Read(void* dst, size_t size) override { return std::fread(dst, 1, size, file_) == size; }

 private:
  std::FILE* file_;
};

// Reads the payload section by section, hashing every byte.
class PayloadReader {
 public:
  PayloadReader(Source& source, std::uint64_t payload_size) : source_(source), remaining_(payload_size) {}

  // Reads one section whose tag must be `tag` and whose length must be `expected` bytes
  // (or at most the remaining payload when expected is kAnySize) into `dst` (resized by the
  // caller, or by `resize` for strings).
  static constexpr size_t kAnySize = ~size_t{0};
  Status Section(std::uint32_t tag, const char* name, size_t expected, const std::function<void*(size_t)>& dst) {
    unsigned char header[kSectionHeaderSize];
    RETURN_IF_ERROR(Take(header, sizeof(header), name));
    std::uint32_t got_tag;
    std::uint64_t length;
    std::memcpy(&got_tag, header, 4);
    std::memcpy(&length, header + 8, 8);
    if (got_tag != tag) return InvalidData(std::string("expected section ") + name + ", found another tag");
    if (length > remaining_ || (expected != kAnySize && length != expected))
      return InvalidData(std::string("section ") + name + " has length " + std::to_string(length) + ", expected " +
                         (expected == kAnySize ? "at most " + std::to_string(remaining_) : std::to_string(expected)));
    RETURN_IF_ERROR(Take(dst(length), length, name));
    unsigned char pad[kAlign];
    return Take(pad, Padding(length), name);
  }

  // Hashes whatever is left; true when the whole payload matches `expected_hash`.
  bool DrainAndVerify(std::uint64_t expected_hash) {
    std::vector<unsigned char> scratch(1 << 20);
    while (remaining_ > 0) {
      const size_t n = std::min<std::uint64_t>(remaining_, scratch.size());
      if (!source_.Read(scratch.data(), n)) return false;
      hash_.Update(scratch.data(), n);
      remaining_ -= n;
    }
    return hash_.Digest() == expected_hash;
  }

  std::uint64_t remaining() const { return remaining_; }

 private:
  Status Take(void* dst, size_t size, const char* name) {
    if (size > remaining_) return InvalidData(std::string("section ") + name + " runs past the end of the payload");
    // Read and hash in cache-sized pieces, so each byte is hashed while still in cache.
    constexpr size_t kPiece = 256 * 1024;
    unsigned char* out = static_cast<unsigned char*>(dst);
    for (size_t done = 0; done < size;) {
      const size_t n = std::min(kPiece, size - done);
      if (!source_.Read(out + done, n)) return InvalidData(std::string("truncated inside section ") + name);
      hash_.Update(out + done, n);
      done += n;
    }
    remaining_ -= size;
    return OkStatus();
  }

  Source& source_;
  std::uint64_t remaining_;
  Xxh64 hash_;
};

Status ReadSections(PayloadReader& reader, MotionDatabase::Parts& parts) {
  std::string meta;
  RETURN_IF_ERROR(reader.Section(kMetaTag, "META", PayloadReader::kAnySize, [&](size_t n) {
    meta.resize(n);
    return static_cast<void*>(meta.data());
  }));
  ASSIGN_OR_RETURN(const mfdb::Layout layout, mfdb::DecodeMeta(meta, parts));
  // Each matrix is sized only after its section's length matched the declared shape, and
  // lengths are bounded by the real payload size, so a corrupt header cannot make us allocate
  // more than the file holds.
  auto matrix = [&](Eigen::MatrixXf& m, long rows, long cols) {
    return [&m, rows, cols](size_t) {
      m.resize(rows, cols);
      return static_cast<void*>(m.data());
    };
  };
  const size_t matrix_bytes = sizeof(float) * static_cast<size_t>(layout.frames) * layout.channels;
  RETURN_IF_ERROR(reader.Section(kSignalsTag, "SIGN", matrix_bytes, matrix(parts.signals, layout.frames, layout.channels)));
  RETURN_IF_ERROR(reader.Section(kTranslationsTag, "TRAN",
                                 sizeof(float) * static_cast<size_t>(layout.frames) * layout.translation_columns,
                                 matrix(parts.translations, layout.frames, layout.translation_columns)));
  for (StoredBand& band : parts.bands)
    RETURN_IF_ERROR(reader.Section(kBandTag, "BAND", matrix_bytes, matrix(band.values, layout.frames, layout.channels)));
  const size_t entries = static_cast<size_t>(layout.correlation_channels) * layout.correlation_channels;
  std::vector<unsigned char> packed;
  RETURN_IF_ERROR(reader.Section(kCorrelationTag, "CORR", entries * kCorrelationEntryBytes, [&](size_t n) {
    packed.resize(n);
    return static_cast<void*>(packed.data());
  }));
  parts.correlation.entries.resize(entries);
  for (size_t i = 0; i < entries; ++i) {
    CorrelationEntry& e = parts.correlation.entries[i];
    std::memcpy(&e.max_abs, &packed[i * kCorrelationEntryBytes], 4);
    std::memcpy(&e.value, &packed[i * kCorrelationEntryBytes + 4], 4);
    std::int32_t lag;
    std::memcpy(&lag, &packed[i * kCorrelationEntryBytes + 8], 4);
    e.lag_frames = lag;
  }
  if (reader.remaining() != 0) return InvalidData(std::to_string(reader.remaining()) + " unexpected bytes after the last section");
  return OkStatus();
}

Result<MotionDatabase> ReadDatabase(Source& source, std::uint64_t file_size) {
  unsigned char header[kHeaderSize];
  if (file_size < sizeof(kMagic)) return InvalidData("not a mocapfill database (file too short)");
  if (!source.Read(header, std::min<std::uint64_t>(file_size, kHeaderSize)))
    return InvalidData("truncated: cannot read the header");
  if (std::memcmp(header, kMagic, sizeof(kMagic)) != 0) return InvalidData("not a mocapfill database (bad magic)");
  if (file_size < kHeaderSize)
    return InvalidData("truncated: " + std::to_string(file_size) + " bytes, the header alone needs " +
                       std::to_string(kHeaderSize));
  std::uint32_t version, header_size;
  std::uint64_t payload_size, payload_hash;
  std::memcpy(&version, header + 8, 4);
  std::memcpy(&header_size, header + 12, 4);
  std::memcpy(&payload_size, header + 16, 8);
  std::memcpy(&payload_hash, header + 24, 8);
  if (version != kMfdbVersion)
    return InvalidData("unsupported .mfdb version " + std::to_string(version) + " (this build reads version " +
                       std::to_string(kMfdbVersion) + "; rebuild the database)");
  if (header_size != kHeaderSize) return InvalidData("corrupted header (header size " + std::to_string(header_size) + ")");
  if (payload_size > file_size - kHeaderSize)
    return InvalidData("truncated: the header declares " + std::to_string(payload_size + kHeaderSize) +
                       " bytes, the file has " + std::to_string(file_size));
  if (payload_size < file_size - kHeaderSize)
    return InvalidData("corrupted: " + std::to_string(file_size - kHeaderSize - payload_size) +
                       " bytes after the declared end of the database");
  PayloadReader reader(source, payload_size);
  MotionDatabase::Parts parts;
  const Status sections = ReadSections(reader, parts);
  // A checksum mismatch explains any structural error better than the error itself.
  if (!reader.DrainAndVerify(payload_hash)) return InvalidData("checksum mismatch (the file is corrupted)");
  RETURN_IF_ERROR(sections);
  return MotionDatabase::FromParts(std::move(parts));
}

}  // namespace

std::string SerializeMfdb(const MotionDatabase& database) {
  const MotionDatabase::Parts& parts = database.parts();
  const std::string meta = mfdb::EncodeMeta(parts);
  size_t total = kHeaderSize + 5 * (kSectionHeaderSize + kAlign) + meta.size() +
                 sizeof(float) * (parts.signals.size() + parts.translations.size()) +
                 parts.correlation.entries.size() * kCorrelationEntryBytes;
  for (const StoredBand& band : parts.bands) total += kSectionHeaderSize + kAlign + sizeof(float) * band.values.size();
  std::string out;
  out.reserve(total);  // one allocation: the sections are tens of MB
  out.resize(kHeaderSize, '\0');
  AppendSection(out, kMetaTag, meta.data(), meta.size());
  AppendSection(out, kSignalsTag, parts.signals.data(), sizeof(float) * parts.signals.size());
  AppendSection(out, kTranslationsTag, parts.translations.data(), sizeof(float) * parts.translations.size());
  for (const StoredBand& band : parts.bands)
    AppendSection(out, kBandTag, band.values.data(), sizeof(float) * band.values.size());
  std::string packed(parts.correlation.entries.size() * kCorrelationEntryBytes, '\0');
  for (size_t i = 0; i < parts.correlation.entries.size(); ++i) {
    const CorrelationEntry& e = parts.correlation.entries[i];
    Put(packed, i * kCorrelationEntryBytes, e.max_abs);
    Put(packed, i * kCorrelationEntryBytes + 4, e.value);
    Put(packed, i * kCorrelationEntryBytes + 8, static_cast<std::int32_t>(e.lag_frames));
  }
  AppendSection(out, kCorrelationTag, packed.data(), packed.size());
  Xxh64 hash;
  hash.Update(out.data() + kHeaderSize, out.size() - kHeaderSize);
  std::memcpy(out.data(), kMagic, sizeof(kMagic));
  Put(out, 8, kMfdbVersion);
  Put(out, 12, static_cast<std::uint32_t>(kHeaderSize));
  Put(out, 16, static_cast<std::uint64_t>(out.size() - kHeaderSize));
  Put(out, 24, hash.Digest());
  return out;
}

Result<MotionDatabase> ParseMfdb(std::string_view bytes) {
  MemorySource source(bytes);
  return ReadDatabase(source, bytes.size());
}

Status WriteMfdb(const MotionDatabase& database, const std::string& path) {
  return WriteFileAtomic(path, SerializeMfdb(database));
}

Result<MotionDatabase> ReadMfdb(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return IoError(path + ": no such database file");
  const std::uint64_t size = std::filesystem::file_size(path, ec);
  if (ec) return IoError(path + ": cannot read the size (" + ec.message() + ")");
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"), &std::fclose);
  if (!file) return IoError(path + ": cannot open (" + std::strerror(errno) + ")");
  FileSource source(file.get());
  Result<MotionDatabase> db = ReadDatabase(source, size);
  if (!db.ok()) return db.status().WithContext(path);
  return db;
}

bool LooksLikeMfdb(const std::string& path) {
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"), &std::fclose);
  char magic[sizeof(kMagic)];
  return file && std::fread(magic, 1, sizeof(magic), file.get()) == sizeof(magic) &&
         std::memcmp(magic, kMagic, sizeof(kMagic)) == 0;
}

}  // namespace mocapfill
