// The .pca model file: exact round trips, and every way a file can be bad is
// rejected with kInvalidData naming the problem, never a crash or a partial model.
#include "formats/pca/pca_file.h"

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>

#include "formats/file_io.h"
#include "processing/pca/pca_model_builder.h"
#include "tests/processing/pca_test_data.h"
#include "tests/support/test_paths.h"

namespace mocapfill {
namespace {

PcaModel WalkModel() {
  std::vector<std::string> paths = testing::BandaiPathsExcept("walk", "normal");
  paths.resize(6);
  Result<MotionDatabase> db = testing::BuildBandaiDatabase(paths);
  EXPECT_TRUE(db.ok()) << db.status().message();
  PcaModelOptions options;
  options.labels = {"walk"};
  Result<PcaModel> model = BuildPcaModel(*db, options);
  EXPECT_TRUE(model.ok()) << model.status().message();
  return model.ok() ? *model : PcaModel{};
}

void ExpectInvalid(const std::string& bytes, const std::string& fragment) {
  Result<PcaModel> parsed = ParsePcaModel(bytes);
  ASSERT_FALSE(parsed.ok()) << "expected failure containing '" << fragment << "'";
  EXPECT_EQ(parsed.status().code(), ErrorCode::kInvalidData);
  EXPECT_NE(parsed.status().message().find(fragment), std::string::npos) << parsed.status().message();
}

TEST(PcaFile, RoundTripIsExactAndDeterministic) {
  MOCAPFILL_REQUIRE_CORPUS();
  const PcaModel model = WalkModel();
  const std::string bytes = SerializePcaModel(model);
  Result<PcaModel> parsed = ParsePcaModel(bytes);
  ASSERT_TRUE(parsed.ok()) << parsed.status().message();
  EXPECT_EQ(SerializePcaModel(*parsed), bytes);
  EXPECT_EQ(parsed->joint_names, model.joint_names);
  EXPECT_EQ(parsed->root_joint, model.root_joint);
  EXPECT_EQ(parsed->components, model.components);
  EXPECT_EQ(parsed->variances, model.variances);
  EXPECT_EQ(parsed->residual_variance, model.residual_variance);
  EXPECT_EQ(parsed->labels, model.labels);
  EXPECT_EQ(parsed->clips, model.clips);
  EXPECT_EQ(parsed->num_samples, model.num_samples);
  EXPECT_EQ(SerializePcaModel(WalkModel()), bytes);  // same data, same bytes
}

TEST(PcaFile, RejectsBadMagicVersionTruncationAndCorruption) {
  MOCAPFILL_REQUIRE_CORPUS();
  const std::string bytes = SerializePcaModel(WalkModel());
  ExpectInvalid("", "bad magic");
  ExpectInvalid("glTF this is not a model", "bad magic");
  std::string version = bytes;
  version[8] = 7;
  ExpectInvalid(version, "unsupported version 7");
  // Every truncation point, header and payload alike.
  for (size_t size = 8; size < bytes.size(); size += 97) ExpectInvalid(bytes.substr(0, size), "truncated");
  ExpectInvalid(bytes + "x", "1 unexpected bytes");
  std::string flipped = bytes;
  flipped[bytes.size() / 2] ^= 0x40;
  ExpectInvalid(flipped, "checksum mismatch");
}

TEST(PcaFile, RejectsAnInconsistentModelWithAValidChecksum) {
  MOCAPFILL_REQUIRE_CORPUS();
  PcaModel model = WalkModel();
  model.variances[0] = -1.0;
  ExpectInvalid(SerializePcaModel(model), "variances");
  model = WalkModel();
  model.components.col(0) *= 2.0;
  ExpectInvalid(SerializePcaModel(model), "orthonormal");
  model = WalkModel();
  model.channel_weights.conservativeResize(model.channel_weights.size() - 1);
  ExpectInvalid(SerializePcaModel(model), "channel_weights");
}

TEST(PcaFile, WriteRefusesInvalidModelsAndReadNamesThePath) {
  MOCAPFILL_REQUIRE_CORPUS();
  const std::string dir = testing::ScratchDir("pca_file");
  const std::string path = dir + "/walk.pca";
  PcaModel model = WalkModel();
  ASSERT_TRUE(WritePcaModel(model, path).ok());
  Result<PcaModel> read = ReadPcaModel(path);
  ASSERT_TRUE(read.ok()) << read.status().message();
  EXPECT_EQ(read->mean, model.mean);
  model.mean[0] = std::nan("");
  const std::string bad = dir + "/bad.pca";
  EXPECT_EQ(WritePcaModel(model, bad).code(), ErrorCode::kInvalidArgument);
  EXPECT_FALSE(std::filesystem::exists(bad));
  EXPECT_EQ(ReadPcaModel(dir + "/missing.pca").status().code(), ErrorCode::kIoError);
  ASSERT_TRUE(WriteFileAtomic(bad, SerializePcaModel(WalkModel()).substr(0, 50)).ok());
  Result<PcaModel> truncated = ReadPcaModel(bad);
  EXPECT_EQ(truncated.status().code(), ErrorCode::kInvalidData);
  EXPECT_EQ(truncated.status().message().rfind(bad, 0), 0u) << truncated.status().message();
}

}  // namespace
}  // namespace mocapfill
