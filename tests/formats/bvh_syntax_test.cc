// BVH syntax corners on small texts built from a real file's numbers (Boxing_Toes'
// first joints): partial channel layouts, whitespace and line-ending variants, Frame Time
// snapping, and the exact fast paths (numbers, Euler angles) against their references.
#include <gtest/gtest.h>

#include <algorithm>
#include <charconv>
#include <cstring>
#include <random>

#include "formats/bvh/bvh_common.h"
#include "formats/bvh/bvh_euler.h"
#include "formats/bvh/bvh_motion_rows.h"
#include "formats/bvh/bvh_number.h"
#include "formats/bvh/bvh_reader.h"
#include "processing/core/rotation.h"
#include "tests/formats/bvh_test_support.h"

namespace mocapfill {
namespace {

using testing::kExactM;

// Hips and Ab of Boxing_Toes.bvh with its first frame; `ab_channels` and `ab_values` vary.
std::string TwoJoints(const std::string& ab_channels, const std::string& ab_values,
                      const std::string& frame_time = "0.010000") {
  return "HIERARCHY\nROOT Hips\n{\n  OFFSET 0 0 0\n"
         "  CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation\n"
         "  JOINT Ab\n  {\n    OFFSET -0.000000 8.268300 -0.000000\n    CHANNELS " +
         ab_channels + "\n    End Site\n    {\n      OFFSET 0 17 0\n    }\n  }\n}\nMOTION\nFrames: 2\nFrame Time: " +
         frame_time + "\n-6.101614 91.753342 50.165031 1.327254 -1.993820 179.842245 " + ab_values +
         "\n-6.1 91.7 50.1 1.3 -1.9 179.8 " + ab_values + "\n";
}

Result<Scene> Read(const std::string& text, ImportOptions options = {}) {
  options.unit = "cm";
  return ReadBvh(text, "inline.bvh", options);
}

Eigen::Quaterniond Axis(int axis, double deg) {
  return Eigen::Quaterniond(Eigen::AngleAxisd(deg * kRadPerDeg, Eigen::Vector3d::Unit(axis)));
}

TEST(BvhSyntax, PartialAndEmptyChannelLayouts) {
  {
    const Result<Scene> s = Read(TwoJoints("0", ""));
    ASSERT_TRUE(s.ok()) << s.status().message();
    EXPECT_TRUE(s->skeleton.joint(1).bvh_channels.empty());
    EXPECT_EQ(s->clips[0].rotation(0, 1).coeffs(), Eigen::Quaterniond::Identity().coeffs());
    EXPECT_NEAR(s->clips[0].translation(0, 1).y(), 0.082683, kExactM);
  }
  {
    const Result<Scene> s = Read(TwoJoints("1 Xrotation", "0.259081"));
    ASSERT_TRUE(s.ok()) << s.status().message();
    EXPECT_LT(GeodesicAngle(s->clips[0].rotation(0, 1), Axis(0, 0.259081)), 1e-15);
  }
  {
    // Y position only: X and Z stay at the OFFSET; the joint moves, so it is animated.
    const Result<Scene> s = Read("HIERARCHY\nROOT Hips\n{\n OFFSET 1 2 3\n CHANNELS 2 Yposition Yrotation\n"
                                 " End Site\n {\n  OFFSET 0 1 0\n }\n}\nMOTION\nFrames: 2\nFrame Time: 0.01\n"
                                 "5 30\n6 -30\n");
    ASSERT_TRUE(s.ok()) << s.status().message();
    EXPECT_NEAR(s->clips[0].translation(1, 0).x(), 0.01, kExactM);
    EXPECT_NEAR(s->clips[0].translation(1, 0).y(), 0.06, kExactM);
    EXPECT_NEAR(s->clips[0].translation(1, 0).z(), 0.03, kExactM);
    EXPECT_TRUE(s->clips[0].translation_animated[0]);
    EXPECT_LT(GeodesicAngle(s->clips[0].rotation(1, 0), Axis(1, -30)), 1e-15);
  }
}

TEST(BvhSyntax, RotationIsIntrinsicInListedOrderForEveryPermutation) {
  const char* orders[] = {"XYZ", "XZY", "YXZ", "YZX", "ZXY", "ZYX"};
  const double angles[] = {-0.829542, 48.164647, -33.747334};
  for (const char* order : orders) {
    std::string channels = "3", values;
    for (int i = 0; i < 3; ++i) {
      channels += std::string(" ") + order[i] + "rotation";
      values += std::to_string(angles[i]) + " ";
    }
    const Result<Scene> s = Read(TwoJoints(channels, values));
    ASSERT_TRUE(s.ok()) << s.status().message();
    const Eigen::Quaterniond expected =
        Axis(order[0] - 'X', angles[0]) * Axis(order[1] - 'X', angles[1]) * Axis(order[2] - 'X', angles[2]);
    EXPECT_LT(GeodesicAngle(s->clips[0].rotation(0, 1), expected), 1e-14) << order;
  }
}

TEST(BvhSyntax, WhitespaceAndLineEndingVariants) {
  const std::string base = TwoJoints("3 Zrotation Xrotation Yrotation", "0.259081 -14.845615 0.399020");
  const Result<Scene> reference = Read(base);
  ASSERT_TRUE(reference.ok()) << reference.status().message();
  auto replace_all = [](std::string s, const std::string& from, const std::string& to) {
    for (size_t p = s.find(from); p != std::string::npos; p = s.find(from, p + to.size())) s.replace(p, from.size(), to);
    return s;
  };
  const std::vector<std::string> variants = {
      replace_all(base, "\n", "\r\n"),                       // CRLF
      replace_all(base, "\n", "\r"),                         // old Mac CR
      base.substr(0, base.size() - 1),                       // no final newline
      replace_all(base, " ", "\t \t"),                       // tabs and runs of blanks
      "\xEF\xBB\xBF" + base,                                 // UTF-8 byte order mark
      replace_all(base, "Frame Time: 0.010000", "Frame Time:\t.010000"),
      replace_all(replace_all(base, "ROOT Hips\n{", "ROOT Hips {"), "JOINT Ab\n  {", "JOINT Ab {"),
      base + "\n\n   \n",                                  // trailing blank lines
      replace_all(base, "End Site", "End site"),
  };
  for (size_t v = 0; v < variants.size(); ++v) {
    const Result<Scene> s = Read(variants[v]);
    ASSERT_TRUE(s.ok()) << "variant " << v << ": " << s.status().message();
    ASSERT_EQ(s->clips[0].num_frames, 2) << v;
    EXPECT_EQ(s->skeleton.name(1), "Ab") << v;
    EXPECT_EQ(s->clips[0].sample_rate_hz, 100.0) << v;
    for (int f = 0; f < 2; ++f)
      for (int j = 0; j < 2; ++j) {
        EXPECT_EQ(s->clips[0].rotation(f, j).coeffs(), reference->clips[0].rotation(f, j).coeffs()) << v;
        EXPECT_EQ(s->clips[0].translation(f, j), reference->clips[0].translation(f, j)) << v;
      }
  }
}

TEST(BvhSyntax, QuaternionTracksStayInOneHemisphereWhenAnglesWrap) {
  // Boxing_Toes' Hips turns near 180 degrees; a file that wraps 179 -> -179 is the same
  // small turn, and the quaternions must not jump to the other hemisphere.
  const std::string text = TwoJoints("3 Zrotation Xrotation Yrotation", "0 0 179.5") +
                           "-6.1 91.7 50.1 1.3 -1.9 179.8 0 0 -179.5\n";
  const Result<Scene> s = Read(text);
  ASSERT_TRUE(s.ok()) << s.status().message();
  const MotionClip& clip = s->clips[0];
  ASSERT_EQ(clip.num_frames, 3);
  EXPECT_GT(clip.rotation(2, 1).coeffs().dot(clip.rotation(1, 1).coeffs()), 0.99);
  EXPECT_LT(GeodesicAngle(clip.rotation(2, 1), Axis(1, -179.5)), 1e-14);
}

TEST(BvhSyntax, FrameTimeSnapsToRationalRates) {
  const std::pair<const char*, double> cases[] = {
      {"0.0333333", 30.0},          {".0083333", 120.0},         {"0.010000", 100.0},        {"0.0416667", 24.0},
      {"0.04", 25.0},               {"0.0166667", 60.0},         {"0.0333667", 30000.0 / 1001},
      {"0.0417083", 24000.0 / 1001}, {"0.0166833", 60000.0 / 1001}, {"0.3", 1.0 / 0.3},
      {"0.0123", 1.0 / 0.0123},
  };
  for (const auto& [text, rate] : cases) {
    const Result<Scene> s = Read(TwoJoints("0", "", text));
    ASSERT_TRUE(s.ok()) << text << ": " << s.status().message();
    EXPECT_EQ(s->clips[0].sample_rate_hz, rate) << text;
    EXPECT_EQ(s->source.source_frame_time_text, text);
  }
}

TEST(BvhSyntax, FrameTimeTextReadsBackAsTheSameRate) {
  for (double rate : {24.0, 25.0, 30.0, 50.0, 60.0, 100.0, 120.0, 240.0, 30000.0 / 1001, 24000.0 / 1001,
                      60000.0 / 1001, 1.0 / 0.3, 37.3, 7.0, 1.0, 0.5, 1000.0, 13.37}) {
    const std::string text = bvh::FormatFrameTime(rate);
    double frame_time = 0.0;
    std::from_chars(text.data(), text.data() + text.size(), frame_time);
    EXPECT_EQ(bvh::SnapFrameRate(frame_time), rate) << rate << " -> " << text;
  }
  EXPECT_EQ(bvh::FormatFrameTime(30.0), "0.0333333333");
}

TEST(BvhSyntax, PlainDecimalFastPathEqualsFromChars) {
  std::mt19937_64 rng(42);
  const std::vector<std::string> fixed = {"0", "-0", "1", "-17.3198", ".5", "5.", "+2.5", "0.0000001234",
                                          "123456789012345678", "9007199254740993", "0.30000000000000004",
                                          "179.842245", "-0.000000", "1e5", "12345.678901234567890",
                                          "5.1072e-06", "-1.87007e-05", "1e22", "1e23", "1e-22", "1e-23",
                                          "9007199254740993e-5", "2.5E+3", "1e00005",
                                          // 20 digits wrap a 64-bit mantissa (2^64 to 0): never the fast path
                                          "18446744073709551616", "18446744073709551617.5", "12345678901234567890",
                                          "0.00000000000000000001", "-1844674407370955161.7", "1234567890123456789",
                                          "9007199254740992", "9007199254740992.0", "0.000000", "7.", "-0"};
  std::vector<std::string> samples = fixed;
  for (int n = 0; n < 200000; ++n) {
    const int integer_digits = static_cast<int>(rng() % 6);
    const int fraction_digits = static_cast<int>(rng() % 12);
    std::string s = (rng() % 2) ? "-" : "";
    for (int i = 0; i < integer_digits; ++i) s += static_cast<char>('0' + rng() % 10);
    if (fraction_digits > 0 || integer_digits == 0) s += '.';
    for (int i = 0; i < fraction_digits; ++i) s += static_cast<char>('0' + rng() % 10);
    if (n % 4 == 0) s += (rng() % 2 ? "e-" : "E") + std::to_string(rng() % 30);  // "5.1072e-06" style
    samples.push_back(s);
  }
  // Each value at the end of the text and with a long row after it: digits, points and
  // signs after the blank must change nothing.
  const std::string after = "\n12345678.9012345678e-5-.9 1.5";
  int fast = 0;
  for (const std::string& s : samples) {
    for (const std::string& padded : {s + " 7", s + " " + after, s + "\t" + after, s + "\r" + after}) {
      double expected = 0.0, got = -1.0;
      const char* begin = s.data() + (s[0] == '+' ? 1 : 0);
      const auto ref = std::from_chars(begin, s.data() + s.size(), expected);
      const char* end = bvh::ParseNumber(padded.data(), padded.data() + padded.size(), got);
      if (ref.ec != std::errc() || ref.ptr != s.data() + s.size()) {
        EXPECT_EQ(end, nullptr) << s;
        continue;
      }
      ASSERT_EQ(end, padded.data() + s.size()) << s;
      EXPECT_EQ(got, expected) << s;
      EXPECT_EQ(std::signbit(got), std::signbit(expected)) << s;
      if (bvh::ParsePlainDecimal(padded.data(), padded.data() + padded.size(), got)) ++fast;
    }
  }
  EXPECT_GT(fast, 600000);  // the fast path, not from_chars, handled the typical values
  double v = 0.0;
  for (const char* bad : {"-", "+", ".", "1.2.3", "--1", "+-1", "1e", "1e+", "e5", "abc", "1x", "-.", "+.e5", "1.-2",
                          "12345678.1x", "1.23456789012345678901234567890x", "0..5", ".e1", "123456789."}) {
    for (const std::string& s : {std::string(bad), std::string(bad) + " " + after}) {
      const bool valid = std::string_view(bad) == "123456789.";  // the one good one: a long value
      const char* end = bvh::ParseNumber(s.data(), s.data() + s.size(), v);
      EXPECT_EQ(end != nullptr, valid) << s;
      if (valid) {
        EXPECT_EQ(v, 123456789.0);
      }
    }
  }
}

// ParseFiniteNumber is ParseNumber that refuses NaN and infinities (from_chars's), and
// nothing else.
TEST(BvhSyntax, FiniteNumberParsingRefusesOnlyNanAndInfinity) {
  for (const char* text : {"nan", "-nan", "inf", "-inf", "infinity", "1e400", "-1e309", "NaN"}) {
    const std::string s = text;
    double v = 0.0;
    EXPECT_EQ(bvh::ParseFiniteNumber(s.data(), s.data() + s.size(), v), nullptr) << s;
  }
  for (const char* text : {"0", "-17.3198", "5.1072e-06", "1e308", "123456789012345678901234567890", "4.9e-324", "+2"}) {
    const std::string s = std::string(text) + "\t";
    double finite = -1.0, any = -2.0;
    const char* end = bvh::ParseFiniteNumber(s.data(), s.data() + s.size(), finite);
    ASSERT_EQ(end, bvh::ParseNumber(s.data(), s.data() + s.size(), any)) << s;
    ASSERT_EQ(end, s.data() + s.size() - 1) << s;
    EXPECT_EQ(finite, any) << s;
  }
}

TEST(BvhSyntax, FastEulerCompositionEqualsTheReference) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> angle(-1000.0, 1000.0);
  const char* orders[] = {"XYZ", "XZY", "YXZ", "YZX", "ZXY", "ZYX"};
  for (const char* name : orders) {
    const EulerOrder order = *EulerOrder::Parse(name);
    for (int n = 0; n < 20000; ++n) {
      std::array<double, 3> a{angle(rng), angle(rng), angle(rng)};
      if (n % 7 == 0) a[n % 3] = 0.0;
      if (n % 11 == 0) a[(n + 1) % 3] = 90.0 * static_cast<int>(a[0] / 90.0);  // exact quarter turns
      const Eigen::Quaterniond fast = bvh::ComposeEulerDegrees(a, order);
      const Eigen::Quaterniond reference = EulerDegreesToQuaternion(a, order);
      const double sign = fast.coeffs().dot(reference.coeffs()) < 0 ? -1.0 : 1.0;
      EXPECT_LT((fast.coeffs() - sign * reference.coeffs()).cwiseAbs().maxCoeff(), 1e-14) << name;
      EXPECT_NEAR(fast.norm(), 1.0, 1e-15);
    }
  }
}

TEST(BvhSyntax, SinCosInDegreesMatchesLibm) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> wide(-1e6, 1e6), narrow(-400.0, 400.0);
  std::vector<double> angles = {0.0, -0.0, 45.0, -45.0, 90.0, 135.0, 180.0, -180.0, 270.0, 360.0, 1e9, -3e12};
  for (int n = 0; n < 100000; ++n) angles.push_back(n % 2 ? wide(rng) : narrow(rng));
  for (double deg : angles) {
    double s = 0.0, c = 0.0;
    bvh::SinCosDegrees(deg, s, c);
    // libm reduces the radian value, so compare at the precision of deg * pi / 180 itself.
    const double tolerance = 4e-16 + 2e-16 * std::abs(deg * kRadPerDeg);
    EXPECT_NEAR(s, std::sin(deg * kRadPerDeg), tolerance) << deg;
    EXPECT_NEAR(c, std::cos(deg * kRadPerDeg), tolerance) << deg;
  }
}

// The vectorised batch is SinCosDegrees bit for bit (signs of zero included), on whichever
// clone the CPU picked, for every length (vector remainders) and the libm range.
TEST(BvhSyntax, SinCosBatchIsBitForBitTheScalarOne) {
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> narrow(-400.0, 400.0), wide(-1e12, 1e12);
  std::vector<double> angles = {0.0, -0.0, 45.0, -45.0, 90.0, -90.0, 135.0, 180.0, 225.0, -270.0, 360.0, 1e9,
                                -1e9, 999999999.5, 5e-324, -5e-324, 1e300, -1e300};
  for (int n = 0; n < 200000; ++n) angles.push_back(n % 5 == 0 ? wide(rng) : 0.5 * narrow(rng));
  for (size_t length : {size_t{1}, size_t{3}, size_t{7}, size_t{66}, angles.size()}) {
    std::vector<double> s(length), c(length);
    bvh::SinCosDegreesBatch(angles.data(), length, s.data(), c.data());
    for (size_t i = 0; i < length; ++i) {
      double s1 = 0.0, c1 = 0.0;
      bvh::SinCosDegrees(angles[i], s1, c1);
      ASSERT_EQ(std::memcmp(&s[i], &s1, sizeof(double)), 0) << angles[i] << " " << s[i] << " " << s1;
      ASSERT_EQ(std::memcmp(&c[i], &c1, sizeof(double)), 0) << angles[i] << " " << c[i] << " " << c1;
    }
  }
}

// Rows composed by FrameComposer give every joint exactly the EulerComposer rotation turned
// to the hemisphere of the frame before, whether it was composed or kept because its text
// repeated (joints hold still on some frames, some rows are all zeros).
TEST(BvhSyntax, FrameComposerEqualsComposingJointByJoint) {
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> angle(-720.0, 720.0);
  const char* orders[] = {"XYZ", "XZY", "YXZ", "YZX", "ZXY", "ZYX"};
  std::vector<bvh::rows::JointSampler> samplers;
  std::vector<bvh::rows::ChannelGroup> groups;
  int channel = 0;
  for (int j = 0; j < 18; ++j) {
    bvh::rows::JointSampler s;
    const EulerOrder order = *EulerOrder::Parse(orders[j % 6]);
    s.compose = bvh::HalfAngleComposerFor(order);
    s.num_rotations = j % 9 == 8 ? 0 : (j % 4 == 3 ? 2 : 3);  // joints without, and with two, rotation channels
    if (j % 5 == 1) {  // rotation channels split into two groups by a position channel between them
      s.rotation_index[0] = channel;
      s.position_index[1] = channel + 1;
      for (int i = 1; i < s.num_rotations; ++i) s.rotation_index[i] = channel + 1 + i;
      groups.push_back({channel, 1});
      groups.push_back({channel + 1, 1});
      groups.push_back({channel + 2, s.num_rotations - 1});
      channel += s.num_rotations + 1;
    } else {
      for (int i = 0; i < s.num_rotations; ++i) s.rotation_index[i] = channel + i;
      if (s.num_rotations > 0) groups.push_back({channel, s.num_rotations});
      channel += s.num_rotations;
    }
    samplers.push_back(s);
  }
  bvh::rows::FrameComposer composer(samplers, groups), positions_composer(samplers, groups, false);
  bvh::rows::RowScanner scanner(groups, channel);
  const size_t joints = samplers.size();
  std::vector<Eigen::Quaterniond> rotations(3000 * joints);
  std::vector<Eigen::Vector3d> translations(joints);
  std::vector<std::string> texts;  // every row's text stays in place, as a file's does
  texts.reserve(3000);
  std::vector<double> values(channel), row(channel);
  size_t kept = 0;
  for (int frame = 0; frame < 3000; ++frame) {
    for (int c = 0; c < channel; ++c)
      if (frame == 0 || (frame + c / 4) % 3 != 0) values[c] = frame % 5 == 0 ? 0.0 : angle(rng);  // a third hold
    if (frame % 7 == 0) values[frame % channel] = -0.0;
    std::string text;
    for (int c = 0; c < channel; ++c) {
      char number[32];
      const auto end = std::to_chars(number, number + sizeof number, values[c]).ptr;
      text.append(number, end).push_back(c + 1 < channel ? ' ' : '\n');
    }
    texts.push_back(std::move(text));
    const char* p = texts.back().data();
    ASSERT_EQ(scanner.Scan(p, p + texts.back().size(), row.data()).kind, bvh::rows::RowEnd::kComplete);
    Eigen::Quaterniond* now = &rotations[frame * joints];
    const Eigen::Quaterniond* before = frame > 0 ? now - joints : nullptr;
    composer.Compose(scanner, row.data(), before, now, translations.data());
    // Without every translation: the same rotations, position joints' translations, nothing else.
    std::vector<Eigen::Quaterniond> now_again(joints);
    std::vector<Eigen::Vector3d> positions_only(joints, Eigen::Vector3d::Constant(-99.0));
    positions_composer.Compose(scanner, row.data(), before, now_again.data(), positions_only.data());
    for (size_t j = 0; j < joints; ++j) {
      ASSERT_EQ(std::memcmp(now_again[j].coeffs().data(), now[j].coeffs().data(), 4 * sizeof(double)), 0) << j;
      const bool positioned = samplers[j].position_index[1] >= 0;
      ASSERT_EQ(positions_only[j], positioned ? translations[j] : Eigen::Vector3d::Constant(-99.0)) << j;
    }
    for (size_t j = 0; j < joints; ++j) {
      const bvh::rows::JointSampler& s = samplers[j];
      std::array<double, 3> a{0.0, 0.0, 0.0};
      for (int i = 0; i < 3; ++i)
        if (s.rotation_index[i] >= 0) a[i] = values[s.rotation_index[i]];
      Eigen::Quaterniond expected = s.num_rotations == 0 ? Eigen::Quaterniond::Identity()
                                                         : bvh::ComposeEulerDegrees(a, *EulerOrder::Parse(orders[j % 6]));
      if (before != nullptr && expected.coeffs().dot(before[j].coeffs()) < 0.0) expected.coeffs() = -expected.coeffs();
      ASSERT_EQ(std::memcmp(now[j].coeffs().data(), expected.coeffs().data(), 4 * sizeof(double)), 0)
          << "frame " << frame << " joint " << j;
      if (s.position_index[1] >= 0) {
        ASSERT_EQ(translations[j].y(), values[s.position_index[1]]);
      }
    }
    // composed() and kept() list every joint once between them, each in order.
    std::vector<uint32_t> listed(composer.composed().begin(), composer.composed().end());
    listed.insert(listed.end(), composer.kept().begin(), composer.kept().end());
    ASSERT_TRUE(std::is_sorted(composer.composed().begin(), composer.composed().end()));
    ASSERT_TRUE(std::is_sorted(composer.kept().begin(), composer.kept().end()));
    std::sort(listed.begin(), listed.end());
    ASSERT_EQ(listed.size(), joints);
    for (size_t j = 0; j < joints; ++j) ASSERT_EQ(listed[j], j);
    if (frame == 0) {
      ASSERT_TRUE(composer.kept().empty());
    }
    kept += composer.kept().size();
  }
  EXPECT_GT(kept, 3000u * joints / 5);  // the kept path was taken, and often
}

// RowScanner reuses a channel group's values when its text repeats the previous row's, and
// must otherwise be ScanRow exactly: same values, same stops and positions, same errors.
TEST(BvhSyntax, RowScannerIsScanRowRowAfterRow) {
  const std::vector<bvh::rows::ChannelGroup> groups = {{0, 3}, {3, 3}, {6, 2}, {8, 1}};
  const std::vector<std::string> rows = {
      "1.5 2.5 3.5 10 20 30 0.0000 0.0000 7\n",
      "1.5 2.5 3.5 11 20 30 0.0000 0.0000 7\n",     // first group repeats
      "1.5 2.5 3.55 11 20 30 0.0000 0.0000 7\n",    // a token grows: not the same text
      "1.5 2.5 3.55\t11 20 30 0.0000 0.0000 7\n",  // a tab where a space was: parsed again
      "1.5 2.5 3.55 11 20 30 0.0000 0.0000 8\r\n",
      "1.5 2.5 3.55 11 20 30 0.0000 0.0000 8 9\n",  // one value too many
      "1.5 2.5 3.55 11 20 30 0.0000\n",             // ends inside a group
      "1.5 2.5 3.55 11 20 nan 0.0000 0.0000 8\n",   // bad value after a repeated group
      "1.5 2.5 3.55 11 20 30 0.0000 0.0000 8",       // no line break at the very end
      "1.5 2.5 3.55 11 20 30 0.0000 0.0000 8\n",
  };
  std::vector<double> scanned(9, -1.0), reference(9, -1.0);
  bvh::rows::RowScanner scanner(groups, 9);
  std::vector<std::string> texts;  // all alive, as a file's rows are while they are scanned
  texts.reserve(rows.size());
  for (const std::string& row : rows) {
    const std::string& text = texts.emplace_back(row + "     padding past the row");
    const char* a = text.data();
    const char* b = text.data();
    const char* end = text.data() + row.size();
    const bvh::rows::RowEnd x = scanner.Scan(a, end, scanned.data());
    const bvh::rows::RowEnd y = bvh::rows::ScanRow(b, end, reference.data(), 9);
    EXPECT_EQ(x.kind, y.kind) << row;
    EXPECT_EQ(x.values, y.values) << row;
    EXPECT_EQ(a, b) << row;
    // Reused values are the ones the text gives (bitwise: a NaN is reported, then held).
    EXPECT_EQ(std::memcmp(scanned.data(), reference.data(), 9 * sizeof(double)), 0) << row;
  }
}

}  // namespace
}  // namespace mocapfill
