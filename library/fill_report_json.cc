#include "library/fill_report_json.h"

#include <nlohmann/json.hpp>

namespace mocapfill {

namespace {

// Frames of the fill (at the database rate) as seconds of the sketch; a takes ratio that
// could not be measured (a one-clip database) as null.
nlohmann::ordered_json CoverageJson(const CoverageReport& c, double rate_hz) {
  const auto ratio = [](double r) { return r < 0.0 ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(r); };
  nlohmann::ordered_json out;
  out["measured"] = c.measured;
  out["poor_share"] = c.poor_share;
  out["none_share"] = c.none_share;
  out["texture_poor_share"] = c.texture_poor_share;
  out["texture_none_share"] = c.texture_none_share;
  out["takes_distance"] = c.reference_distance;
  out["prior"] = c.prior.empty() ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(c.prior);
  nlohmann::ordered_json poor = nlohmann::ordered_json::array();
  for (const PoorlyCoveredStretch& p : c.poor)
    poor.push_back({{"from_s", p.first_frame / rate_hz}, {"to_s", p.last_frame / rate_hz},
                    {"worst_unexplained", p.worst_unexplained}, {"worst_takes_ratio", ratio(p.worst_takes_ratio)},
                    {"max_prior_weight", p.max_prior_weight}});
  out["poorly_covered"] = poor;
  nlohmann::ordered_json fragments = nlohmann::ordered_json::array();
  for (const FragmentCoverage& f : c.fragments)
    fragments.push_back({{"from_s", f.first_frame / rate_hz}, {"to_s", f.last_frame / rate_hz},
                         {"distance", f.distance}, {"unexplained", f.unexplained},
                         {"takes_ratio", ratio(f.takes_ratio)}, {"prior_weight", f.prior_weight},
                         {"texture_weight", f.texture_weight}});
  out["fragments"] = fragments;
  return out;
}

nlohmann::ordered_json ReportObject(const SketchFillResult& result, const std::string& db_name, double load_s) {
  const FillReport& r = result.report;
  nlohmann::ordered_json out;
  out["method"] = r.method;
  out["join"] = r.join;
  out["database"] = db_name;
  out["frames"] = result.scene.clips.front().num_frames;
  out["rate_hz"] = result.output_rate_hz;
  out["uniform"] = result.uniform;
  out["database_rate_hz"] = result.database_rate_hz;
  out["rig"] = {{"family", result.rig.family},
                {"rest", result.rig.rest},
                {"same_as_database", result.rig.same_as_database},
                {"mapped_bones", result.rig.mapped_bones},
                {"warnings", result.rig.warnings}};
  out["key_spacing_frames"] = r.key_spacing_frames;
  out["master_channel"] = r.master_channel;
  out["fragment_band"] = r.fragment_band;
  out["sketch_fragments"] = r.sketch_fragments;
  out["seams"] = r.seams;
  // Measured on the file written, at the sketch's exact key times.
  out["key_error_mean_deg"] = result.key_error_mean_deg;
  out["key_error_max_deg"] = result.key_error_max_deg;
  out["root_key_error_max_m"] = result.translation_key_error_max_m;
  out["max_frame_jump_deg"] = result.max_frame_jump_deg;
  nlohmann::ordered_json contacts = nlohmann::ordered_json::array();
  for (const FootContact& c : result.feet.contacts)
    contacts.push_back({{"foot", c.side}, {"part", c.part}, {"from_s", c.start_s}, {"to_s", c.end_s},
                        {"keys", c.keys}, {"max_correction_m", c.max_correction_m}, {"found_on", c.found_on}});
  nlohmann::ordered_json legs = nlohmann::ordered_json::array();
  for (const PlantedLeg& leg : result.feet.legs) legs.push_back({{"foot", leg.side}, {"correction_m", leg.correction_m}});
  out["feet"] = {{"contacts", contacts}, {"frames_held", result.feet.frames_held},
                 {"max_correction_m", result.feet.max_correction_m}, {"contacts_skipped", result.feet.contacts_skipped},
                 {"correction_per_frame", legs}};
  nlohmann::ordered_json joints = nlohmann::ordered_json::array();
  for (const JointFillInfo& j : result.joints)
    joints.push_back({{"joint", j.name}, {"kind", j.kind}, {"keys", j.keys},
                      {"key_error_mean_deg", j.key_error_mean_deg}, {"key_error_max_deg", j.key_error_max_deg}});
  out["joints"] = joints;
  nlohmann::ordered_json fragments = nlohmann::ordered_json::array();
  for (const FragmentSource& f : r.fragments)
    fragments.push_back({{"group", f.group}, {"frames", {f.first_frame, f.last_frame}}, {"clip", f.clip},
                         {"clip_frames", {f.clip_first_frame, f.clip_last_frame}}, {"distance", f.distance},
                         {"blended", f.blended}, {"travel_mps", f.travel_mps}});
  out["fragments"] = fragments;
  out["group_order"] = r.group_order;
  out["coverage"] = CoverageJson(r.coverage, result.database_rate_hz);
  if (!r.pca_model_source.empty())
    out["pca_model"] = {{"source", r.pca_model_source}, {"components", r.pca_components}};
  if (r.has_solver) {
    const SolverReport& s = r.solver;
    out["pca_solver"] = {{"termination", s.termination_type}, {"converged", s.converged},
                         {"iterations", s.iterations},        {"initial_cost", s.initial_cost},
                         {"final_cost", s.final_cost},        {"linear_solver", s.linear_solver},
                         {"parameters", s.num_parameters},    {"residuals", s.num_residuals},
                         {"solve_seconds", s.solve_time_s},   {"message", s.message}};
  }
  out["warnings"] = result.warnings;
  nlohmann::ordered_json stages = nlohmann::ordered_json::object();
  stages["load_database"] = load_s;
  for (const StageTime& s : r.stages) stages[s.stage] = s.seconds;
  out["stage_seconds"] = stages;
  return out;
}

}  // namespace

std::string FillReportJson(const SketchFillResult& result, const std::string& database, double load_database_s,
                           int indent) {
  return ReportObject(result, database, load_database_s).dump(indent);
}

}  // namespace mocapfill
