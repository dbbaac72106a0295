#include "formats/mfdb/mfdb_file.h"

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>

#include "formats/file_io.h"
#include "formats/mfdb/xxhash64.h"
#include "processing/database/motion_database_builder.h"
#include "processing/database/stored_clips.h"
#include "tests/processing/synthetic_motion.h"
#include "tests/support/test_paths.h"

namespace mocapfill {
namespace {

MotionDatabase WalkerDatabase() {
  MotionDatabaseBuilder builder;
  const Skeleton skeleton = testing::WalkerSkeleton();
  for (int i = 0; i < 2; ++i) {
    testing::WalkerParams p;
    p.duration_s = 3.0 + i;
    MotionClip clip = testing::WalkerClip(skeleton, p);
    clip.name = "walk_" + std::to_string(i);
    EXPECT_TRUE(builder.Add(skeleton, clip, {{"style", "odd \"quoted\" ü"}, {"id", std::to_string(i)}}).ok());
  }
  return builder.Build().value();
}

TEST(Xxh64, MatchesReferenceVectors) {
  EXPECT_EQ(Xxh64().Digest(), 0xEF46DB3751D8E999ULL);  // empty input
  Xxh64 abc;
  abc.Update("abc", 3);
  EXPECT_EQ(abc.Digest(), 0x44BC2CF5AD770999ULL);
  // Streaming in odd pieces equals one call.
  std::string text(1000, '\0');
  for (size_t i = 0; i < text.size(); ++i) text[i] = static_cast<char>(i * 31 + 7);
  Xxh64 whole, pieces;
  whole.Update(text.data(), text.size());
  for (size_t at = 0, step = 1; at < text.size(); at += step, step = step % 37 + 3)
    pieces.Update(text.data() + at, std::min(step, text.size() - at));
  EXPECT_EQ(whole.Digest(), pieces.Digest());
}

TEST(MfdbFile, RoundTripGivesIdenticalDatabaseAndBytes) {
  const MotionDatabase db = WalkerDatabase();
  const std::string bytes = SerializeMfdb(db);
  EXPECT_EQ(bytes, SerializeMfdb(WalkerDatabase()));  // deterministic
  Result<MotionDatabase> back = ParseMfdb(bytes);
  ASSERT_TRUE(back.ok()) << back.status().message();
  EXPECT_TRUE(back->signals() == db.signals());
  EXPECT_TRUE(back->parts().translations == db.parts().translations);
  ASSERT_EQ(back->bands().size(), db.bands().size());
  for (size_t b = 0; b < db.bands().size(); ++b) EXPECT_TRUE(back->bands()[b].values == db.bands()[b].values);
  EXPECT_EQ(back->clip(1).labels, db.clip(1).labels);
  EXPECT_EQ(back->clip(1).start_position_m, db.clip(1).start_position_m);
  EXPECT_EQ(back->correlation().entries.size(), db.correlation().entries.size());
  EXPECT_EQ(back->correlation().at(3, 7).value, db.correlation().at(3, 7).value);
  for (int j = 0; j < db.num_joints(); ++j) EXPECT_EQ(back->joint_means()[j].coeffs(), db.joint_means()[j].coeffs());
  // Reconstructed clips are bit-identical, and the serialised copy serialises to the same bytes.
  EXPECT_TRUE(ReconstructClip(*back, 1)->rotations == ReconstructClip(db, 1)->rotations);
  EXPECT_EQ(SerializeMfdb(*back), bytes);
}

TEST(MfdbFile, RejectsCorruptedTruncatedAndForeignFiles) {
  const std::string bytes = SerializeMfdb(WalkerDatabase());
  auto message = [](std::string_view b) {
    Result<MotionDatabase> r = ParseMfdb(b);
    EXPECT_FALSE(r.ok());
    EXPECT_EQ(r.status().code(), ErrorCode::kInvalidData);
    return r.status().message();
  };
  // A flipped byte anywhere in the payload: META, a matrix, the last section.
  for (size_t at : {size_t{100}, bytes.size() / 2, bytes.size() - 70}) {
    std::string flipped = bytes;
    flipped[at] ^= 0x20;
    EXPECT_NE(message(flipped).find("checksum mismatch"), std::string::npos) << "byte " << at;
  }
  EXPECT_NE(message(bytes.substr(0, bytes.size() - 1000)).find("truncated"), std::string::npos);
  EXPECT_NE(message(bytes.substr(0, 40)).find("truncated"), std::string::npos);
  EXPECT_NE(message(bytes + "junk").find("after the declared end"), std::string::npos);
  std::string magic = bytes;
  magic[0] = 'X';
  EXPECT_NE(message(magic).find("bad magic"), std::string::npos);
  EXPECT_NE(message("MF").find("too short"), std::string::npos);
  std::string version = bytes;
  version[8] = 7;
  EXPECT_NE(message(version).find("unsupported .mfdb version 7"), std::string::npos);
}

TEST(MfdbFile, WritesAndReadsFilesNamingThePath) {
  const std::string dir = testing::ScratchDir("mfdb_file");
  const std::string path = dir + "/walk.mfdb";
  const MotionDatabase db = WalkerDatabase();
  ASSERT_TRUE(WriteMfdb(db, path).ok());
  EXPECT_TRUE(LooksLikeMfdb(path));
  Result<MotionDatabase> back = ReadMfdb(path);
  ASSERT_TRUE(back.ok()) << back.status().message();
  EXPECT_TRUE(back->signals() == db.signals());
  const Result<MotionDatabase> missing = ReadMfdb(dir + "/none.mfdb");
  EXPECT_EQ(missing.status().code(), ErrorCode::kIoError);
  std::string bytes = ReadFileBytes(path).value();
  bytes.resize(bytes.size() / 3);
  ASSERT_TRUE(WriteFileAtomic(dir + "/cut.mfdb", bytes).ok());
  const Result<MotionDatabase> cut = ReadMfdb(dir + "/cut.mfdb");
  EXPECT_EQ(cut.status().code(), ErrorCode::kInvalidData);
  EXPECT_EQ(cut.status().message().rfind(dir + "/cut.mfdb: truncated", 0), 0u) << cut.status().message();
  EXPECT_FALSE(LooksLikeMfdb(dir + "/none.mfdb"));
}

}  // namespace
}  // namespace mocapfill
