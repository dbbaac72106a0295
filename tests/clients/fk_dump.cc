// Test support for the client checks (tests/clients): the world position of every joint at
// every frame of a motion file, by mocapfill's own import and forward kinematics, as JSON
// that the Blender and three.js checks compare the clients' readings with.
//
// Usage: mocapfill_fk_dump IN OUT.json
// Writes {"source", "rate_hz", "metres_per_unit" (the unit the import applied, which a BVH
// written back with --out-unit auto uses), "joints": [names], "positions": [frame][joint][xyz]}
// in metres, glTF axes (Y up). Exit 1 on a file it cannot read or write.
#include <cstdio>
#include <string>

#include "formats/motion_io.h"
#include "processing/core/kinematics.h"

namespace {

void AppendNumber(std::string& out, double v) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.17g", v);
  out += text;
}

void AppendString(std::string& out, const std::string& s) {
  out += '"';
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  out += '"';
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: mocapfill_fk_dump IN OUT.json\n");
    return 2;
  }
  const mocapfill::Result<mocapfill::Scene> scene = mocapfill::ImportFile(argv[1]);
  if (!scene.ok()) {
    std::fprintf(stderr, "error: %s\n", scene.status().message().c_str());
    return 1;
  }
  if (scene->clips.empty()) {
    std::fprintf(stderr, "error: %s: no clip\n", argv[1]);
    return 1;
  }
  const mocapfill::Skeleton& skeleton = scene->skeleton;
  const mocapfill::MotionClip& clip = scene->clips[0];
  const std::vector<Eigen::Vector3d> world = mocapfill::ComputeWorldPositions(skeleton, clip);
  std::string out = "{\"source\": ";
  AppendString(out, argv[1]);
  out += ", \"rate_hz\": ";
  AppendNumber(out, clip.sample_rate_hz);
  out += ", \"metres_per_unit\": ";
  AppendNumber(out, scene->source.unit_scale_to_m);
  out += ", \"joints\": [";
  for (int j = 0; j < skeleton.num_joints(); ++j) {
    if (j > 0) out += ", ";
    AppendString(out, skeleton.name(j));
  }
  out += "],\n\"positions\": [";
  const int joints = skeleton.num_joints();
  for (int f = 0; f < clip.num_frames; ++f) {
    out += f > 0 ? ",\n[" : "[";
    for (int j = 0; j < joints; ++j) {
      const Eigen::Vector3d& p = world[static_cast<size_t>(f) * joints + j];
      out += j > 0 ? ", [" : "[";
      for (int a = 0; a < 3; ++a) {
        if (a > 0) out += ", ";
        AppendNumber(out, p[a]);
      }
      out += ']';
    }
    out += ']';
  }
  out += "]}\n";
  std::FILE* file = std::fopen(argv[2], "wb");
  if (file == nullptr || std::fwrite(out.data(), 1, out.size(), file) != out.size() || std::fclose(file) != 0) {
    std::fprintf(stderr, "error: %s: cannot write\n", argv[2]);
    return 1;
  }
  return 0;
}
