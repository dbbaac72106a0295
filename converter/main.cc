// mocapfill: fill missing degrees of freedom of sketched animations from a motion
// capture database, and convert BVH/glTF/FBX to validator-clean glTF.
//
// This executable runs the format verbs (convert, inspect) itself and hands every other
// command line, help and --version included, to mocapfill-full (verb_dispatch.h). The
// reason is start-up time: a converter runs once per file in asset pipelines, and the
// solver behind the fill verbs (Ceres, with glog, gflags, SuiteSparse and BLAS) costs every
// process start static initialisers that look up the user name through NSS, more shared
// objects and thousands of relocations, before any work. The verbs that need it run for
// hundreds of milliseconds and do not notice one exec. Without it, this executable is
// linked statically (no dynamic loader, no relocations; docs/performance.md has the
// figures), so Assimp inputs (FBX...), which need the dynamically loaded Assimp plug-in,
// go to mocapfill-full as well (front_end_assimp.cc).
#include <string>
#include <string_view>

#include "converter/verb_dispatch.h"
#include "formats/motion_io.h"

namespace {

using namespace mocapfill::cli;

constexpr Verb kFormatVerbs[] = {{"convert", AddConvertCommand}, {"inspect", AddInspectCommand}};

// Whether any argument names an Assimp input. An option value that merely looks like one
// only sends the command line to mocapfill-full, which runs it just the same.
bool NamesAssimpInput(int argc, char** argv) {
  for (int i = 1; i < argc; ++i)
    if (mocapfill::IsAssimpInput(argv[i])) return true;
  return false;
}

// Retargeting (convert --retarget) is no plain conversion; mocapfill-full runs it.
bool AsksToRetarget(int argc, char** argv) {
  for (int i = 1; i < argc; ++i)
    if (std::string_view(argv[i]).starts_with("--retarget")) return true;
  return false;
}

}  // namespace

int main(int argc, char** argv) {
  if (NamedVerb(argc, argv, kFormatVerbs) != nullptr && !NamesAssimpInput(argc, argv) && !AsksToRetarget(argc, argv)) {
    mocapfill::PrepareConversionProcess();
    return RunCommandLine(argc, argv, kFormatVerbs);
  }
  return ExecFullExecutable(argv);
}
