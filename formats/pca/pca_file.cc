#include "formats/pca/pca_file.h"

#include <bit>
#include <cstring>

#include "formats/file_io.h"
#include "formats/mfdb/xxhash64.h"

namespace mocapfill {

namespace {

static_assert(std::endian::native == std::endian::little, "the .pca writer assumes a little-endian host");

constexpr char kMagic[8] = {'M', 'F', 'P', 'C', 'A', '\r', '\n', '\x1a'};
constexpr std::uint32_t kHeaderSize = 40;

class Writer {
 public:
  template <typename T>
  void Pod(T value) {
    out_.append(reinterpret_cast<const char*>(&value), sizeof(T));
  }
  void String(const std::string& s) {
    Pod(static_cast<std::uint32_t>(s.size()));
    out_ += s;
  }
  void Strings(const std::vector<std::string>& list) {
    Pod(static_cast<std::uint32_t>(list.size()));
    for (const std::string& s : list) String(s);
  }
  void Vector(const Eigen::VectorXd& v) {
    Pod(static_cast<std::uint32_t>(v.size()));
    out_.append(reinterpret_cast<const char*>(v.data()), sizeof(double) * v.size());
  }
  void Matrix(const Eigen::MatrixXd& m) {
    Pod(static_cast<std::uint32_t>(m.rows()));
    Pod(static_cast<std::uint32_t>(m.cols()));
    out_.append(reinterpret_cast<const char*>(m.data()), sizeof(double) * m.size());
  }
  std::string& bytes() { return out_; }

 private:
  std::string out_;
};

// Bounds-checked reads; every count is checked against the bytes left before allocating,
// so a corrupted count cannot ask for gigabytes.
class Reader {
 public:
  explicit Reader(std::string_view bytes) : bytes_(bytes) {}
  template <typename T>
  Status Pod(const char* field, T& value) {
    RETURN_IF_ERROR(Need(field, sizeof(T)));
    std::memcpy(&value, bytes_.data() + pos_, sizeof(T));
    pos_ += sizeof(T);
    return OkStatus();
  }
  Status String(const char* field, std::string& s) {
    std::uint32_t size = 0;
    RETURN_IF_ERROR(Pod(field, size));
    RETURN_IF_ERROR(Need(field, size));
    s.assign(bytes_.data() + pos_, size);
    pos_ += size;
    return OkStatus();
  }
  Status Strings(const char* field, std::vector<std::string>& list) {
    std::uint32_t count = 0;
    RETURN_IF_ERROR(Pod(field, count));
    RETURN_IF_ERROR(Need(field, std::uint64_t{count} * 4));  // each string has a 4-byte length
    list.resize(count);
    for (std::string& s : list) RETURN_IF_ERROR(String(field, s));
    return OkStatus();
  }
  Status Vector(const char* field, Eigen::VectorXd& v) {
    std::uint32_t size = 0;
    RETURN_IF_ERROR(Pod(field, size));
    RETURN_IF_ERROR(Need(field, std::uint64_t{size} * sizeof(double)));
    v.resize(size);
    if (size > 0) std::memcpy(v.data(), bytes_.data() + pos_, sizeof(double) * size);  // data() is null when empty
    pos_ += sizeof(double) * size;
    return OkStatus();
  }
  Status Matrix(const char* field, Eigen::MatrixXd& m) {
    std::uint32_t rows = 0, cols = 0;
    RETURN_IF_ERROR(Pod(field, rows));
    RETURN_IF_ERROR(Pod(field, cols));
    const std::uint64_t size = std::uint64_t{rows} * cols;
    // Counted in doubles: rows * cols * 8 can pass 2^64 and wrap to a small byte count.
    if (size > remaining() / sizeof(double)) return InvalidData(std::string("truncated while reading ") + field);
    m.resize(rows, cols);
    if (size > 0) std::memcpy(m.data(), bytes_.data() + pos_, sizeof(double) * size);  // data() is null when empty
    pos_ += sizeof(double) * size;
    return OkStatus();
  }
  size_t remaining() const { return bytes_.size() - pos_; }

 private:
  Status Need(const char* field, std::uint64_t size) const {
    if (size > remaining()) return InvalidData(std::string("truncated while reading ") + field);
    return OkStatus();
  }
  std::string_view bytes_;
  size_t pos_ = 0;
};

std::string SerializePayload(const PcaModel& m) {
  Writer w;
  w.Strings(m.joint_names);
  w.Pod(static_cast<std::uint32_t>(m.joint_means.size()));
  for (const Eigen::Quaterniond& q : m.joint_means) {
    w.Pod(q.w());
    w.Pod(q.x());
    w.Pod(q.y());
    w.Pod(q.z());
  }
  w.Pod(static_cast<std::int32_t>(m.root_joint));
  w.Pod(static_cast<std::int32_t>(m.num_root_features));
  w.Pod(m.sample_rate_hz);
  w.Vector(m.channel_weights);
  w.Pod(static_cast<std::int32_t>(m.window_frames));
  w.Vector(m.mean);
  w.Matrix(m.components);
  w.Vector(m.variances);
  w.Vector(m.spectrum);
  w.Vector(m.residual_variance);
  w.Vector(m.coefficient_accel_rms);
  w.Vector(m.channel_accel_rms);
  w.Pod(static_cast<std::int64_t>(m.num_samples));
  w.Strings(m.labels);
  w.Strings(m.clips);
  return std::move(w.bytes());
}

Status ParsePayload(std::string_view payload, PcaModel& m) {
  Reader r(payload);
  RETURN_IF_ERROR(r.Strings("joint names", m.joint_names));
  std::uint32_t means = 0;
  RETURN_IF_ERROR(r.Pod("joint means", means));
  if (means != m.joint_names.size()) return InvalidData("joint means: count differs from the joint count");
  m.joint_means.resize(means);
  for (Eigen::Quaterniond& q : m.joint_means) {
    double w = 0, x = 0, y = 0, z = 0;
    RETURN_IF_ERROR(r.Pod("joint means", w));
    RETURN_IF_ERROR(r.Pod("joint means", x));
    RETURN_IF_ERROR(r.Pod("joint means", y));
    RETURN_IF_ERROR(r.Pod("joint means", z));
    q = Eigen::Quaterniond(w, x, y, z);
  }
  std::int32_t root = 0, features = 0, window = 0;
  std::int64_t samples = 0;
  RETURN_IF_ERROR(r.Pod("root joint", root));
  RETURN_IF_ERROR(r.Pod("root feature count", features));
  RETURN_IF_ERROR(r.Pod("sample rate", m.sample_rate_hz));
  RETURN_IF_ERROR(r.Vector("channel weights", m.channel_weights));
  RETURN_IF_ERROR(r.Pod("window frames", window));
  RETURN_IF_ERROR(r.Vector("mean", m.mean));
  RETURN_IF_ERROR(r.Matrix("components", m.components));
  RETURN_IF_ERROR(r.Vector("variances", m.variances));
  RETURN_IF_ERROR(r.Vector("spectrum", m.spectrum));
  RETURN_IF_ERROR(r.Vector("residual variance", m.residual_variance));
  RETURN_IF_ERROR(r.Vector("coefficient smoothness", m.coefficient_accel_rms));
  RETURN_IF_ERROR(r.Vector("channel smoothness", m.channel_accel_rms));
  RETURN_IF_ERROR(r.Pod("sample count", samples));
  RETURN_IF_ERROR(r.Strings("labels", m.labels));
  RETURN_IF_ERROR(r.Strings("clip names", m.clips));
  if (r.remaining() != 0) return InvalidData(std::to_string(r.remaining()) + " unexpected bytes after the model");
  m.root_joint = root;
  m.num_root_features = features;
  m.window_frames = window;
  m.num_samples = samples < 0 || samples > (1LL << 40) ? -1 : static_cast<int>(samples);
  if (m.num_samples < 0) return InvalidData("sample count is out of range");
  return m.Validate();
}

template <typename T>
T Load(std::string_view bytes, size_t offset) {
  T value;
  std::memcpy(&value, bytes.data() + offset, sizeof(T));
  return value;
}

std::uint64_t Hash(std::string_view bytes) {
  Xxh64 hash;
  hash.Update(bytes.data(), bytes.size());
  return hash.Digest();
}

}  // namespace

std::string SerializePcaModel(const PcaModel& model) {
  const std::string payload = SerializePayload(model);
  Writer header;
  header.bytes().append(kMagic, sizeof(kMagic));
  header.Pod(kPcaFileVersion);
  header.Pod(kHeaderSize);
  header.Pod(static_cast<std::uint64_t>(payload.size()));
  header.Pod(Hash(payload));
  header.Pod(std::uint64_t{0});
  return header.bytes() + payload;
}

Result<PcaModel> ParsePcaModel(std::string_view bytes) {
  if (bytes.size() < sizeof(kMagic) || std::memcmp(bytes.data(), kMagic, sizeof(kMagic)) != 0)
    return InvalidData("not a mocapfill PCA model (bad magic)");
  if (bytes.size() < kHeaderSize)
    return InvalidData("truncated: the header needs " + std::to_string(kHeaderSize) + " bytes, file has " +
                       std::to_string(bytes.size()));
  const auto version = Load<std::uint32_t>(bytes, 8);
  if (version != kPcaFileVersion)
    return InvalidData("unsupported version " + std::to_string(version) + " (this build reads " +
                       std::to_string(kPcaFileVersion) + ")");
  if (Load<std::uint32_t>(bytes, 12) != kHeaderSize) return InvalidData("bad header size");
  const auto payload_size = Load<std::uint64_t>(bytes, 16);
  const std::uint64_t present = bytes.size() - kHeaderSize;
  if (payload_size > present)
    return InvalidData("truncated: header declares " + std::to_string(payload_size) + " payload bytes, file has " +
                       std::to_string(present));
  if (payload_size < present)
    return InvalidData(std::to_string(present - payload_size) + " unexpected bytes after the declared payload");
  const std::string_view payload = bytes.substr(kHeaderSize);
  if (Hash(payload) != Load<std::uint64_t>(bytes, 24)) return InvalidData("checksum mismatch (file corrupted)");
  PcaModel model;
  RETURN_IF_ERROR(ParsePayload(payload, model));
  return model;
}

Status WritePcaModel(const PcaModel& model, const std::string& path) {
  const Status valid = model.Validate();
  if (!valid.ok()) return InvalidArgument(path + ": refusing to write an invalid PCA model: " + valid.message());
  return WriteFileAtomic(path, SerializePcaModel(model));
}

Result<PcaModel> ReadPcaModel(const std::string& path) {
  ASSIGN_OR_RETURN(const std::string bytes, ReadFileBytes(path));
  Result<PcaModel> model = ParsePcaModel(bytes);
  if (!model.ok()) return model.status().WithContext(path);
  return model;
}

}  // namespace mocapfill
