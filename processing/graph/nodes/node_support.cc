#include "processing/graph/nodes/node_support.h"

#include <cmath>

#include "processing/motion/resample.h"

namespace mocapfill::graph {

OptionSpec BoolOption(std::string name, bool default_value, std::string doc) {
  OptionSpec spec;
  spec.name = std::move(name);
  spec.type = OptionType::kBool;
  spec.default_value = OptionValue::Bool(default_value);
  spec.doc = std::move(doc);
  return spec;
}

OptionSpec IntOption(std::string name, int default_value, std::optional<double> min, std::optional<double> max,
                     std::string doc, std::string unit) {
  OptionSpec spec;
  spec.name = std::move(name);
  spec.type = OptionType::kInt;
  spec.default_value = OptionValue::Integer(default_value);
  spec.min = min;
  spec.max = max;
  spec.unit = std::move(unit);
  spec.doc = std::move(doc);
  return spec;
}

OptionSpec NumberOption(std::string name, double default_value, std::optional<double> min, bool min_exclusive,
                        std::optional<double> max, std::string unit, std::string doc) {
  OptionSpec spec;
  spec.name = std::move(name);
  spec.type = OptionType::kNumber;
  spec.default_value = OptionValue::Number(default_value, false);
  spec.min = min;
  spec.min_exclusive = min_exclusive;
  spec.max = max;
  spec.unit = std::move(unit);
  spec.doc = std::move(doc);
  return spec;
}

OptionSpec StringOption(std::string name, std::string default_value, std::vector<std::string> choices,
                        std::string doc) {
  OptionSpec spec;
  spec.name = std::move(name);
  spec.type = OptionType::kString;
  spec.default_value = OptionValue::String(std::move(default_value));
  spec.choices = std::move(choices);
  spec.doc = std::move(doc);
  return spec;
}

OptionSpec WithFlag(OptionSpec spec, std::string flag) {
  spec.flag = std::move(flag);
  return spec;
}

OptionSpec WithWords(OptionSpec spec, std::string yes, std::string no) {
  spec.words = {std::move(yes), std::move(no)};
  return spec;
}

OptionSpec WithCheck(OptionSpec spec, std::function<Status(const OptionValue&)> check) {
  spec.check = std::move(check);
  return spec;
}

OptionSpec WithBounds(OptionSpec spec, double min, double max) {
  spec.min = min;
  spec.max = max;
  return spec;
}

OptionSpec ListOption(std::string name, OptionType type, std::string doc) {
  OptionSpec spec;
  spec.name = std::move(name);
  spec.type = type;
  const bool map = type == OptionType::kNumberMap || type == OptionType::kStringMap;
  spec.default_value = map ? OptionValue::Object({}, {}) : OptionValue::Array({});
  spec.doc = std::move(doc);
  return spec;
}

Result<const MotionClip*> FirstClip(const Scene& scene, const std::string& port) {
  if (scene.clips.empty()) return InvalidData(port + ": the motion has no animation");
  if (scene.clips[0].num_frames < 1) return InvalidData(port + ": the motion's animation has no frames");
  return &scene.clips[0];
}

Value WithClip(const Scene& scene, MotionClip clip) {
  auto out = std::make_shared<Scene>(scene);
  out->clips = {std::move(clip)};
  return Value(std::shared_ptr<const Scene>(std::move(out)));
}

Result<MotionClip> AtRate(const MotionClip& clip, double rate_hz) {
  if (std::abs(clip.sample_rate_hz / rate_hz - 1.0) <= 1e-9) return clip;
  ResampleOptions options;
  options.rate_hz = rate_hz;
  return ResampleClip(clip, options);
}

Status CheckSameJoints(const Skeleton& a, const Skeleton& b, const std::string& a_port, const std::string& b_port) {
  if (a.num_joints() != b.num_joints())
    return InvalidData(a_port + " has " + std::to_string(a.num_joints()) + " joints, " + b_port + " has " +
                       std::to_string(b.num_joints()) + " (expected the same skeleton)");
  for (int j = 0; j < a.num_joints(); ++j)
    if (a.name(j) != b.name(j))
      return InvalidData("joint " + std::to_string(j) + " is '" + a.name(j) + "' in " + a_port + " but '" + b.name(j) +
                         "' in " + b_port + " (expected the same skeleton)");
  return OkStatus();
}

}  // namespace mocapfill::graph
