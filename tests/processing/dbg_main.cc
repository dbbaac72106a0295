#include <cstdio>
#include <string>
#include <filesystem>
#include <algorithm>
#include "formats/motion_io.h"
#include "processing/retargeting/retarget_scene.h"
#include "processing/sketch_fill/sketch_fill.h"
#include "processing/evaluation/sketch_maker.h"
#include "processing/synthesis/fill.h"
#include "tests/support/bone_directions.h"
using namespace mocapfill;
int main(int argc, char** argv) {
  MotionDatabaseBuilder builder;
  std::vector<std::string> files;
  for (const auto& e : std::filesystem::directory_iterator("fixtures/default_db")) if (e.path().extension() == ".bvh") files.push_back(e.path().string());
  std::sort(files.begin(), files.end());
  for (auto& f : files) { Scene s = *ImportFile(f); (void)builder.Add(s.skeleton, s.clips[0], {{"file", f}}); }
  MotionDatabase db = *builder.Build();
  Scene bandai = *ImportFile(argv[1]);
  SketchSpec spec; spec.keep_joints = {"Hips","UpperLeg_L","LowerLeg_L","Foot_L","Toes_L","UpperLeg_R","LowerLeg_R","Foot_R","Toes_R"};
  MotionClip sk = *MakeSketch(bandai.skeleton, bandai.clips[0], spec);
  Scene sketch = bandai; sketch.clips = {sk};
  auto rig = *PrepareRig(bandai);
  for (const char* m : {"mean", "nn", "hierarchical"}) {
    SketchFillOptions o; o.fill.method = *ParseFillMethod(m);
    auto r = FillSketch(sketch, db, o);
    if (!r.ok()) { std::printf("%s\n", r.status().message().c_str()); continue; }
    for (auto seg : testing::UpperBodySegments())
      std::printf("%s %s->%s %.2f\n", m, HumanoidBoneName(seg.first), HumanoidBoneName(seg.second), testing::MeanDirectionErrorDeg(rig.rig, bandai.clips[0], rig.rig, r->scene.clips[0], {seg}));
    // also old path
    FillEngine engine(db);
    auto direct = engine.Fill(sk, o.fill);
    if (direct.ok()) std::printf("%s direct engine: %.2f  sketch-fill: %.2f\n", m, testing::MeanDirectionErrorDeg(rig.rig, bandai.clips[0], rig.rig, direct->clip, testing::UpperBodySegments()), testing::MeanDirectionErrorDeg(rig.rig, bandai.clips[0], rig.rig, r->scene.clips[0], testing::UpperBodySegments()));
  }
}
