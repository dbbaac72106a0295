// mocapfill analyze: band energies per joint, motion phases, the joint-correlation table
// (of a database with --db, else of the clip itself), and an SVG figure of one DOF with its
// Gaussian levels, Laplacian bands and phase boundaries.
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>

#include "converter/commands.h"
#include "converter/console.h"
#include "converter/database_arg.h"
#include "converter/exit_codes.h"
#include "converter/import_flags.h"
#include "formats/file_io.h"
#include "formats/motion_io.h"
#include "formats/plot/svg_plot.h"
#include "processing/analysis/clip_analysis.h"
#include "processing/analysis/correlation.h"
#include "processing/core/rotation.h"

namespace mocapfill::cli {

namespace {

using Json = nlohmann::ordered_json;

struct AnalyzeArgs {
  std::string input;
  std::string db;
  bool json = false;
  std::string plot;
  std::string joint;
  std::string axis;
  double band_hz = 1.0;
  int levels = 0;
  int partners = 8;
  ImportOptions import;
};

// The correlation table used for the report, with the channel names of its columns.
struct CorrelationSource {
  std::string source;  // "database <path>" or "clip"
  CorrelationTable table;
  std::vector<std::string> names;
};

std::vector<std::string> ClipChannelNames(const Skeleton& skeleton, int root_features) {
  std::vector<std::string> names;
  for (int j = 0; j < skeleton.num_joints(); ++j)
    for (const char* axis : {".x", ".y", ".z"}) names.push_back(skeleton.name(j) + axis);
  for (int f = 0; f < root_features; ++f) names.push_back(RootFeatureName(f));
  return names;
}

Result<CorrelationSource> Correlations(const AnalyzeArgs& args, const Skeleton& skeleton, const MotionClip& clip,
                                       const ClipAnalysis& analysis) {
  CorrelationSource out;
  if (!args.db.empty()) {
    ASSIGN_OR_RETURN(MotionDatabase db, LoadDatabaseArg(args.db));
    out.source = "database " + args.db;
    out.table = db.correlation();
    for (int c = 0; c < db.num_channels(); ++c) out.names.push_back(db.ChannelName(c));
    return out;
  }
  // Same definition on the clip alone: its phase band, lags up to 0.25 s.
  const Eigen::MatrixXf band = analysis.pyramid.bands[analysis.phase_band].cast<float>();
  const FrameSegment whole[] = {{0, clip.num_frames}};
  ASSIGN_OR_RETURN(out.table, ComputeCorrelationTable(band, whole, static_cast<int>(std::lround(0.25 * clip.sample_rate_hz))));
  out.table.band = analysis.phase_band;
  out.table.rate_hz = clip.sample_rate_hz;
  out.source = "clip";
  out.names = ClipChannelNames(skeleton, static_cast<int>(analysis.signals.root_features.cols()));
  return out;
}

// Channels most correlated with `name`'s channel, other joints only, strongest first.
std::vector<int> Partners(const CorrelationSource& corr, const std::string& channel, int count) {
  const auto it = std::find(corr.names.begin(), corr.names.end(), channel);
  if (it == corr.names.end() || corr.table.empty()) return {};
  const int a = static_cast<int>(it - corr.names.begin());
  const std::string joint = channel.substr(0, channel.rfind('.'));
  std::vector<int> others;
  for (int b = 0; b < corr.table.num_channels; ++b)
    if (corr.names[b].substr(0, corr.names[b].rfind('.')) != joint) others.push_back(b);
  std::stable_sort(others.begin(), others.end(),
                   [&](int x, int y) { return corr.table.at(a, x).max_abs > corr.table.at(a, y).max_abs; });
  others.resize(std::min<size_t>(others.size(), count));
  return others;
}

PlotFigure Figure(const Skeleton& skeleton, const MotionClip& clip, const ClipAnalysis& a) {
  const int channel = 3 * a.master_joint + a.master_axis;
  const std::string name = skeleton.name(a.master_joint) + "." + "xyz"[a.master_axis];
  std::vector<double> time(clip.num_frames);
  for (int f = 0; f < clip.num_frames; ++f) time[f] = clip.time_s(f);
  auto degrees = [&](const Eigen::MatrixXd& m) {
    std::vector<double> y(clip.num_frames);
    for (int f = 0; f < clip.num_frames; ++f) y[f] = m(f, channel) * kDegPerRad;
    return y;
  };
  std::vector<double> cuts;
  for (size_t i = 1; i < a.phases.size(); ++i) cuts.push_back(clip.time_s(a.phases[i].first));
  PlotFigure figure;
  figure.title = "'" + clip.name + "': " + name + " tangent angle, multiresolution bands and phases";
  figure.x_label = "time (s)";
  PlotPanel curve{"g0: " + name + " (" + std::to_string(a.phases.size()) + " phases from L" +
                      std::to_string(a.phase_band) + ")",
                  "angle (deg)", {{"g0", time, degrees(a.pyramid.Gaussian(0)), "#000000"}}, cuts};
  figure.panels.push_back(curve);
  PlotPanel gaussians{"Gaussian levels (low-pass)", "angle (deg)", {}, {}};
  for (int k = 1; k <= a.pyramid.levels(); ++k)
    gaussians.series.push_back({"g" + std::to_string(k), time, degrees(a.pyramid.Gaussian(k)), ""});
  figure.panels.push_back(gaussians);
  char title[96];
  for (int k = 0; k < a.pyramid.levels(); ++k) {
    std::snprintf(title, sizeof(title), "l%d: Laplacian band L%d, peak %.2f Hz%s", k, k,
                  BandPeakHz(k, clip.sample_rate_hz), k == a.phase_band ? " (phase band)" : "");
    figure.panels.push_back({title, "angle (deg)", {{"l" + std::to_string(k), time, degrees(a.pyramid.bands[k]), "#1f77b4"}},
                             k == a.phase_band ? cuts : std::vector<double>{}});
  }
  return figure;
}

Json Report(const Skeleton& skeleton, const MotionClip& clip, const ClipAnalysis& a, const CorrelationSource& corr,
            const AnalyzeArgs& args) {
  Json out;
  out["file"] = args.input;
  out["clip"] = clip.name;
  out["frames"] = clip.num_frames;
  out["rate_hz"] = clip.sample_rate_hz;
  out["levels"] = a.pyramid.levels();
  Json peaks = Json::array();
  for (int k = 0; k < a.pyramid.levels(); ++k) peaks.push_back(BandPeakHz(k, clip.sample_rate_hz));
  out["band_peak_hz"] = peaks;
  Json energy = Json::object();
  for (int j = 0; j < skeleton.num_joints(); ++j) {
    std::vector<double> row(a.band_energy_rad2.cols());
    for (int k = 0; k < a.band_energy_rad2.cols(); ++k) row[k] = a.band_energy_rad2(j, k);
    energy[skeleton.name(j)] = row;
  }
  out["band_energy_rad2"] = energy;  // per joint: L0..L(levels-1), then the residual
  const std::string master = skeleton.name(a.master_joint) + "." + "xyz"[a.master_axis];
  Json phases = Json::array();
  for (const Phase& p : a.phases)
    phases.push_back({{"first", p.first}, {"last", p.last}, {"start_s", clip.time_s(p.first)},
                      {"end_s", clip.time_s(p.last)}, {"rising", p.rising}});
  out["phases"] = {{"master", master}, {"band", a.phase_band}, {"band_peak_hz", BandPeakHz(a.phase_band, clip.sample_rate_hz)},
                   {"list", phases}};
  Json table;
  table["source"] = corr.source;
  table["band"] = corr.table.band;
  table["max_lag_frames"] = corr.table.max_lag_frames;
  table["channels"] = corr.names;
  Json max_abs = Json::array(), value = Json::array(), lag = Json::array();
  for (int i = 0; i < corr.table.num_channels; ++i) {
    Json r1 = Json::array(), r2 = Json::array(), r3 = Json::array();
    for (int k = 0; k < corr.table.num_channels; ++k) {
      r1.push_back(corr.table.at(i, k).max_abs);
      r2.push_back(corr.table.at(i, k).value);
      r3.push_back(corr.table.at(i, k).lag_frames);
    }
    max_abs.push_back(r1), value.push_back(r2), lag.push_back(r3);
  }
  table["max_abs"] = max_abs;
  table["value"] = value;
  table["lag_frames"] = lag;
  out["correlation"] = table;
  return out;
}

void PrintText(const Skeleton& skeleton, const MotionClip& clip, const ClipAnalysis& a, const CorrelationSource& corr,
               const AnalyzeArgs& args) {
  const double rate = clip.sample_rate_hz;
  std::printf("clip '%s': %d frames at %g Hz (%.2f s), %d band-pass levels\n", clip.name.c_str(), clip.num_frames, rate,
              clip.duration_s(), a.pyramid.levels());
  std::printf("band energy as RMS angle per band (deg):\n  %-16s", "joint");
  for (int k = 0; k < a.pyramid.levels(); ++k) std::printf(" L%d %4.1fHz", k, BandPeakHz(k, rate));
  std::printf("  residual\n");
  for (int j = 0; j < skeleton.num_joints(); ++j) {
    std::printf("  %-16s", skeleton.name(j).c_str());
    for (int k = 0; k <= a.pyramid.levels(); ++k) std::printf(" %9.2f", std::sqrt(a.band_energy_rad2(j, k)) * kDegPerRad);
    std::printf("\n");
  }
  const std::string master = skeleton.name(a.master_joint) + "." + "xyz"[a.master_axis];
  std::printf("phases of %s in band L%d (%.2f Hz): %zu\n", master.c_str(), a.phase_band, BandPeakHz(a.phase_band, rate),
              a.phases.size());
  for (size_t i = 0; i < a.phases.size(); ++i)
    std::printf("  %3zu  frames %4d-%4d  %6.2f-%6.2f s  %s\n", i, a.phases[i].first, a.phases[i].last,
                clip.time_s(a.phases[i].first), clip.time_s(a.phases[i].last), a.phases[i].rising ? "rising" : "falling");
  std::printf("correlation (%s, band L%d, lags up to %d frames): strongest partners of %s\n", corr.source.c_str(),
              corr.table.band, corr.table.max_lag_frames, master.c_str());
  const auto it = std::find(corr.names.begin(), corr.names.end(), master);
  for (int b : Partners(corr, master, args.partners)) {
    const CorrelationEntry& e = corr.table.at(static_cast<int>(it - corr.names.begin()), b);
    std::printf("  %-22s %+6.3f at lag %+d frames (%+.3f s)\n", corr.names[b].c_str(), e.value, e.lag_frames,
                e.lag_frames / corr.table.rate_hz);
  }
}

int RunAnalyze(const AnalyzeArgs& args) {
  if (!args.plot.empty() && LowerExtension(args.plot) != ".svg")
    return Fail(InvalidArgument(args.plot + ": the plot file must end in .svg"), Stage::kOutput);
  if (!args.plot.empty() && IsSameFile(args.plot, args.input))
    return Fail(IoError(args.plot + ": refusing to overwrite the input file"), Stage::kOutput);
  Result<Scene> scene = ImportFile(args.input, args.import);
  if (!scene.ok()) return Fail(scene.status(), Stage::kInput);
  for (const std::string& warning : scene->warnings) PrintWarning(args.input + ": " + warning);
  if (scene->clips.empty()) return Fail(InvalidData(args.input + ": no animation to analyse"), Stage::kInput);
  const Skeleton& skeleton = scene->skeleton;
  const MotionClip& clip = scene->clips.front();
  ClipAnalysisOptions options;
  options.pyramid.levels = args.levels;
  options.phase_band_hz = args.band_hz;
  if (!args.joint.empty()) {
    const Result<int> j = FindJointNamed(skeleton, args.joint, "--joint");
    if (!j.ok()) return Fail(j.status(), Stage::kInput);
    options.master_joint = *j;
  }
  if (!args.axis.empty()) options.master_axis = args.axis == "x" ? 0 : args.axis == "y" ? 1 : 2;
  Result<ClipAnalysis> analysis = AnalyzeClip(skeleton, clip, options);
  if (!analysis.ok()) return Fail(analysis.status().WithContext(args.input), Stage::kProcessing);
  Result<CorrelationSource> corr = Correlations(args, skeleton, clip, *analysis);
  if (!corr.ok()) return Fail(corr.status(), Stage::kInput);
  if (args.json) {
    std::cout << Report(skeleton, clip, *analysis, *corr, args).dump(1) << "\n";
  } else if (!IsQuiet()) {
    PrintText(skeleton, clip, *analysis, *corr, args);
  }
  if (!args.plot.empty()) {
    const Status written = WriteFileAtomic(args.plot, RenderSvg(Figure(skeleton, clip, *analysis)));
    if (!written.ok()) return Fail(written, Stage::kOutput);
  }
  return kExitOk;
}

}  // namespace

void AddAnalyzeCommand(CLI::App& app, CommandAction& action) {
  auto args = std::make_shared<AnalyzeArgs>();
  CLI::App* command = app.add_subcommand(
      "analyze", "Band energies per joint, motion phases, joint correlations, and an SVG plot of one DOF");
  command->add_option("input", args->input, "Input motion file (.bvh .gltf .glb .fbx); the first clip is analysed")
      ->required();
  command->add_option("--db", args->db, "Report the correlation table of this database (.mfdb file or motion folder)");
  command->add_flag("--json", args->json, "Print a JSON report (energies, phases, full correlation table)");
  command->add_option("--plot", args->plot, "Write an SVG figure: the DOF, its Gaussian levels, Laplacian bands, phases");
  command->add_option("--joint", args->joint, "Joint whose DOF is plotted and cut into phases (default: most active)");
  command->add_option("--axis", args->axis, "Tangent component of that joint (default: most active)")
      ->check(CLI::IsMember({"x", "y", "z"}));
  command->add_option("--band-hz", args->band_hz, "Frequency of the phase band (nearest band; 1 Hz = stride)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  command->add_option("--levels", args->levels, "Band-pass levels (default: automatic)")->check(CLI::Range(0, 16));
  command->add_option("--partners", args->partners, "Correlation partners to list")->check(CLI::Range(1, 1000));
  AddImportFlags(*command, args->import);
  command->footer(
      "Examples:\n"
      "  mocapfill analyze walk.bvh --plot curves.svg --joint UpperLeg_L\n"
      "  mocapfill analyze walk.bvh --db bn1.mfdb --json | jq .phases");
  command->callback([args, &action] { action = [args] { return RunAnalyze(*args); }; });
}

}  // namespace mocapfill::cli
