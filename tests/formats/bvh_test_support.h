// Helpers shared by the BVH tests: an independent reading of motion rows from the raw
// text (so tests can check the importer against the numbers in the file), motion
// comparison with named tolerances, and the Euler-continuity check on written text.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "formats/motion_io.h"
#include "processing/core/scene.h"
#include "processing/core/status.h"

namespace mocapfill::testing {

constexpr double kRoundTripRotationToleranceDeg = 1e-6;
constexpr double kRoundTripTranslationToleranceM = 1e-9;
constexpr double kExactM = 1e-12;  // metres: values read straight from the text

// Reads fixtures/bvh/<name> with ReadBvh.
Result<Scene> ReadFixture(const std::string& name, const ImportOptions& options = {});

// Reads a whole file as bytes (test helper: fails the test on error and returns "").
std::string ReadText(const std::string& path);

// `text` with its motion rows repeated until the motion section holds at least `min_bytes`,
// and the Frames line rewritten to the new row count plus `frames_delta` (large inputs for
// the two-thread and streaming parsers, made from real captures).
std::string EnlargeMotion(const std::string& text, size_t min_bytes, int frames_delta = 0);

// The numbers of every frame row (the lines after "Frame Time"), split on whitespace.
std::vector<std::vector<double>> MotionRows(const std::string& bvh_text);

// Channel names per joint in file order, read from the CHANNELS lines of the raw text.
std::vector<std::vector<std::string>> ChannelLines(const std::string& bvh_text);

// The rotation a joint's listed channels describe, composed with Eigen's AngleAxis in
// listed order (independent of the importer's own Euler code).
Eigen::Quaterniond RotationFromChannels(const std::vector<std::string>& channels, const double* values);

// Largest change between consecutive frames of any rotation channel in BVH text.
double MaxRotationChannelJumpDeg(const std::string& bvh_text);

struct MotionDifference {
  double rotation_deg = 0.0;
  double translation_m = 0.0;
};

// Worst geodesic rotation and translation difference between the first clips of two
// scenes, matching joints by name (the scenes must have the same joint names and frames).
MotionDifference CompareMotion(const Scene& a, const Scene& b);

// Checks names, parents, channel layouts, end sites and rest translations agree.
void ExpectSameSkeleton(const Skeleton& a, const Skeleton& b, double tolerance_m);

}  // namespace mocapfill::testing
