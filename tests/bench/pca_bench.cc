// Speed of the PCA key fit (target: Ceres fit of a 300-frame clip with up to 30 components
// under 200 ms), stage by stage, against a direct sparse solve of the same
// linear problem (Eigen SimplicialLDLT on the normal equations) in the same run.
//   pca_bench [data-dir] [repeats]
// Model: Bandai-Namco walks of 14 styles (the "sad" style held out), 30 components.
// Clip: the first 300 frames of walk_sad_001, root and legs keyed every 8 frames.
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <algorithm>
#include <chrono>
#include <ctime>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "formats/mfdb/motion_folder.h"
#include "formats/motion_io.h"
#include "processing/core/kinematics.h"
#include "processing/core/rotation.h"
#include "processing/database/motion_database_builder.h"
#include "processing/evaluation/metrics.h"
#include "processing/evaluation/sketch_maker.h"
#include "processing/pca/closed_form_fit.h"
#include "processing/pca/pca_clip.h"
#include "processing/pca/ceres_fit/pca_fit.h"
#include "processing/pca/pca_model_builder.h"
#include "processing/pca/pca_sketch.h"

namespace mocapfill {
namespace {

using Clock = std::chrono::steady_clock;
double Ms(Clock::time_point since) { return std::chrono::duration<double, std::milli>(Clock::now() - since).count(); }
// Process CPU time (ms): less sensitive than wall time to other jobs on a shared machine.
double CpuMs() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return 1000.0 * t.tv_sec + 1e-6 * t.tv_nsec;
}

constexpr int kFrames = 300;
constexpr int kKeyEvery = 8;
const char* const kStyles[] = {"active", "angry", "childish", "chimpira", "feminine", "giant",  "happy", "masculinity",
                               "musical", "normal", "not-confident", "old", "proud", "sad", "tired"};

std::string ClipPath(const std::string& data, const std::string& style, int id) {
  return data + "/bandai-namco-1/data/dataset-1_walk_" + style + "_00" + std::to_string(id) + ".bvh";
}

// Independent solve of the linear subspace problem (keys, prior, smoothness): the peer.
double DirectSolveMs(const PcaModel& m, const PcaKeyProblem& p, const PcaFitOptions& o) {
  const Clock::time_point start = Clock::now();
  const int k = m.num_components(), frames = p.num_frames;
  const Eigen::VectorXd sigma = [&] {
    Eigen::VectorXd s(m.pose_dim());
    for (int c = 0; c < m.pose_dim(); ++c)
      s[c] = c < 3 * m.num_joints() ? o.key_sigma_deg * kRadPerDeg * m.channel_weights[c] : o.root_key_sigma;
    return s;
  }();
  std::vector<Eigen::Triplet<double>> entries;
  std::vector<double> rhs;
  for (int t = 0; t < frames; ++t) {
    for (int c = 0; c < m.pose_dim(); ++c) {
      if (!p.key_mask(t, c)) continue;
      const int row = static_cast<int>(rhs.size());
      for (int i = 0; i < k; ++i) entries.emplace_back(row, t * k + i, m.components(c, i) / sigma[c]);
      rhs.push_back((p.key_values(t, c) - m.mean[c]) / sigma[c]);
    }
    for (int i = 0; i < k; ++i) {
      entries.emplace_back(static_cast<int>(rhs.size()), t * k + i, 1.0 / std::sqrt(m.variances[i]));
      rhs.push_back(0.0);
    }
  }
  for (int t = 1; t + 1 < frames; ++t)
    for (int i = 0; i < k; ++i) {
      const int row = static_cast<int>(rhs.size());
      const double w = 1.0 / m.coefficient_accel_rms[i];
      entries.emplace_back(row, (t - 1) * k + i, w);
      entries.emplace_back(row, t * k + i, -2.0 * w);
      entries.emplace_back(row, (t + 1) * k + i, w);
      rhs.push_back(0.0);
    }
  Eigen::SparseMatrix<double> a(static_cast<int>(rhs.size()), frames * k);
  a.setFromTriplets(entries.begin(), entries.end());
  const Eigen::Map<Eigen::VectorXd> b(rhs.data(), rhs.size());
  const Eigen::SparseMatrix<double> normal = a.transpose() * a;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(normal);
  const Eigen::VectorXd x = ldlt.solve(a.transpose() * b);
  const double ms = Ms(start);
  return x.allFinite() ? ms : -1.0;
}

void PrintFit(const char* name, const PcaSketchFit& f, double cpu_ms, double key_mean_deg, double key_max_deg) {
  const SolverReport& r = f.fit.report;
  std::printf("%-26s %7.1f %7.1f %7.1f %7.1f %7.1f %7.1f %7.1f %7.1f %7.1f %5d %-12s key mean/max deg %.3f/%.3f\n", name,
              1000 * f.encode_s, 1000 * f.fit.initial_guess_s, 1000 * f.fit.build_s, 1000 * r.preprocess_time_s,
              1000 * r.jacobian_time_s, 1000 * r.linear_solver_time_s, 1000 * f.fit.solve_s, 1000 * f.decode_s, cpu_ms,
              r.iterations, r.termination_type.c_str(), key_mean_deg, key_max_deg);
}

int Run(const std::string& data, int repeats) {
  std::vector<std::string> paths;
  for (const char* style : kStyles)
    if (std::string(style) != "sad")
      for (int id = 1; id <= 2; ++id) paths.push_back(ClipPath(data, style, id));
  Result<std::vector<LabeledScene>> scenes = ImportMotionFiles(paths, ImportOptions{}, 0);
  if (!scenes.ok()) return std::printf("error: %s\n", scenes.status().message().c_str()), 1;
  MotionDatabaseBuilder builder;
  for (LabeledScene& s : *scenes)
    for (MotionClip& clip : s.scene.clips)
      if (!builder.Add(s.scene.skeleton, std::move(clip), s.labels).ok()) return 1;
  Result<MotionDatabase> db = builder.Build();
  if (!db.ok()) return 1;
  PcaModelOptions model_options;
  model_options.basis.variance_kept = 0.9999;
  model_options.basis.max_components = 30;
  Clock::time_point start = Clock::now();
  Result<PcaModel> model = BuildPcaModel(*db, model_options);
  if (!model.ok()) return std::printf("error: %s\n", model.status().message().c_str()), 1;
  std::printf("model: %d components, %d frames, built in %.1f ms\n", model->num_components(), model->num_samples, Ms(start));

  Result<Scene> scene = ImportFile(ClipPath(data, "sad", 1), ImportOptions{});
  if (!scene.ok()) return 1;
  MotionClip truth = scene->clips[0];
  truth.num_frames = kFrames;
  truth.rotations.resize(static_cast<size_t>(kFrames) * truth.num_joints);
  truth.translations.resize(static_cast<size_t>(kFrames) * truth.num_joints);
  truth.KeyAllFrames();
  SketchSpec spec;
  spec.keep_joints = {"Hips", "UpperLeg_L", "LowerLeg_L", "Foot_L", "Toes_L", "UpperLeg_R", "LowerLeg_R", "Foot_R", "Toes_R"};
  spec.key_every_frames = kKeyEvery;
  const Skeleton& skeleton = scene->skeleton;
  Result<MotionClip> sketch = MakeSketch(skeleton, truth, spec);
  if (!sketch.ok()) return 1;
  const int hips = *skeleton.Find("Hips");
  const std::vector<Eigen::Vector3d> world = ComputeWorldPositions(skeleton, truth);
  std::vector<SketchPositionKey> feet;
  for (const char* foot : {"Foot_L", "Foot_R"})
    for (int f : SketchKeyFrames(kFrames, kKeyEvery))
      feet.push_back({f, foot, world[static_cast<size_t>(f) * truth.num_joints + *skeleton.Find(foot)]});

  std::printf("clip: walk_sad_001, %d frames, %zu keyed joints every %d frames, %zu foot position keys, %d threads\n",
              kFrames, spec.keep_joints.size(), kKeyEvery, feet.size(), PcaFitOptions{}.num_threads);
  std::printf("%-26s %7s %7s %7s %7s %7s %7s %7s %7s %7s %5s %-12s (best of %d, ms; cpu = whole fit)\n", "fit",
              "encode", "init", "build", "prep", "jacob", "linsol", "solve", "decode", "cpu", "iter", "termination",
              repeats);
  struct Case {
    const char* name;
    bool full_pose;
    bool positions;
  };
  const Case cases[] = {{"subspace (linear keys)", false, false},
                        {"subspace + foot positions", false, true},
                        {"full-pose (exact keys)", true, false}};
  double best_subspace_ms = 1e30;
  const int only_case = std::getenv("PCA_BENCH_CASE") ? std::atoi(std::getenv("PCA_BENCH_CASE")) : -1;
  for (const Case& c : cases) {
    if (only_case >= 0 && &c - cases != only_case) continue;
    PcaSketchFitOptions options;
    options.full_pose = c.full_pose;
    Result<PcaSketchFit> best = Status(ErrorCode::kInternal, "not run");
    double best_cpu_ms = 1e30;
    for (int r = 0; r < repeats; ++r) {
      const double cpu_start = CpuMs();
      Result<PcaSketchFit> fit =
          FitSketchToKeys(*model, skeleton, *sketch, c.positions ? feet : std::vector<SketchPositionKey>{}, nullptr, options);
      if (!fit.ok()) return std::printf("error: %s\n", fit.status().message().c_str()), 1;
      best_cpu_ms = std::min(best_cpu_ms, CpuMs() - cpu_start);
      if (!best.ok() || fit->fit.solve_s < best->fit.solve_s) best = fit;
    }
    Result<FillMetrics> metrics = ScoreFill(skeleton, truth, *sketch, best->clip, hips);
    PrintFit(c.name, *best, best_cpu_ms, metrics->key_error_mean_deg, metrics->key_error_max_deg);
    if (!c.full_pose && !c.positions) best_subspace_ms = 1000 * (best->fit.build_s + best->fit.solve_s);
  }
  // Peer: the same linear problem assembled and solved directly.
  Result<PcaBinding> binding = BindPcaModel(*model, skeleton);
  PcaKeyProblem problem;
  problem.num_frames = kFrames;
  problem.key_values = EncodeClip(*model, *binding, skeleton, *sketch).poses;
  problem.key_mask = ChannelMask::Constant(kFrames, model->pose_dim(), false);
  for (int m = 0; m < model->num_joints(); ++m)
    for (int f : sketch->keys[binding->model_to_skeleton[m]].rotation_frames) problem.key_mask.row(f).segment<3>(3 * m) = true;
  for (int f : sketch->keys[hips].rotation_frames) problem.key_mask.row(f).tail(model->num_root_features) = true;
  double direct_ms = 1e30, direct_cpu_ms = 1e30;
  for (int r = 0; r < repeats; ++r) {
    const double cpu_start = CpuMs();
    direct_ms = std::min(direct_ms, DirectSolveMs(*model, problem, {}));
    direct_cpu_ms = std::min(direct_cpu_ms, CpuMs() - cpu_start);
  }
  std::printf("peer: direct SimplicialLDLT of the linear problem %.1f ms (cpu %.1f ms); Ceres subspace (build + solve) "
              "/ direct = %.2fx\n", direct_ms, direct_cpu_ms, best_subspace_ms / direct_ms);
  return 0;
}

}  // namespace
}  // namespace mocapfill

int main(int argc, char** argv) {
  const std::string data = argc > 1 && argv[1][0] != 0 ? argv[1] : MOCAPFILL_DATA_DIR;
  const int repeats = argc > 2 ? std::max(1, std::atoi(argv[2])) : 5;
  return mocapfill::Run(data, repeats);
}
