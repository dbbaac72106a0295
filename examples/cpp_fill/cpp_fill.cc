// cpp_fill SKETCH OUT [DATABASE]: fills a keyframed sketch from a motion capture database
// (the default database when none is given) and writes the complete animation.
#include <cstdio>
#include <mocapfill/mocapfill.h>

int main(int argc, char** argv) {
  if (argc < 3 || argc > 4) {
    std::fprintf(stderr, "usage: cpp_fill SKETCH OUT [DATABASE]\n");
    return 1;
  }
  try {
    const mocapfill::api::Scene sketch = mocapfill::api::Load(argv[1]);
    const mocapfill::api::Database database =
        argc == 4 ? mocapfill::api::Database::Open(argv[3]) : mocapfill::api::Database::Default();
    const mocapfill::api::FillResult filled = mocapfill::api::Fill(sketch, database);
    mocapfill::api::Save(filled.scene, argv[2]);
    std::printf("%s: %d joints, %d frames filled from %s (%d clips); key error max %.4f deg\n", argv[2],
                filled.scene.joint_count(), static_cast<int>(filled.scene.clip(0).times_s.size()),
                database.name().c_str(), database.clip_count(), filled.key_error_max_deg);
    for (const std::string& warning : filled.warnings) std::fprintf(stderr, "warning: %s\n", warning.c_str());
    return 0;
  } catch (const mocapfill::api::Error& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return e.exit_code();
  }
}
