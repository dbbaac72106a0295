// Real data for the PCA tests: Bandai-Namco dataset-1 clips from the shared corpus, imported
// and built into an in-memory database, and sketches of held-out clips (root and legs keyed
// every k frames).
#pragma once

#include <string>
#include <vector>

#include "processing/core/motion_clip.h"
#include "processing/core/motion_database.h"
#include "processing/core/pca_model.h"
#include "processing/core/scene.h"

namespace mocapfill::testing {

// Corpus path of "dataset-1_<content>_<style>_<id>.bvh".
std::string BandaiClipPath(const std::string& content, const std::string& style, int id = 1);

// Imports the files (with their Bandai-Namco labels) and builds a database at 30 Hz.
// Fails the calling test (ADD_FAILURE) and returns an empty result on any error.
Result<MotionDatabase> BuildBandaiDatabase(const std::vector<std::string>& paths);

// Paths of the given content for every style except `held_out_style` (ids 1 and 2).
std::vector<std::string> BandaiPathsExcept(const std::string& content, const std::string& held_out_style);

// Imports one clip (first clip of the scene), all frames keyed, at the file's 30 Hz.
Result<Scene> ImportBandaiClip(const std::string& path);

// The legs-and-root sketch joints of the Bandai-Namco skeleton (task T1).
std::vector<std::string> BandaiLegJoints();

}  // namespace mocapfill::testing
