// mocapfill: fill missing degrees of freedom of sketched animations from a motion
// capture database, and convert BVH/glTF/FBX to validator-clean glTF.
//
// This executable runs the format verbs (convert, inspect) itself and hands every other
// command line, help and --version included, to mocapfill-full (verb_dispatch.h). The
// reason is start-up time: a converter runs once per file in asset pipelines, and the
// solver behind the fill verbs (Ceres, with glog, gflags, SuiteSparse and BLAS) cost
// about 0.8 ms of every process start (static initialisers that look up the user name
// through NSS, three more shared objects, thousands of relocations) before any work.
// The verbs that need it run for hundreds of milliseconds and do not notice one exec.
#include "converter/verb_dispatch.h"

namespace {

using namespace mocapfill::cli;

constexpr Verb kFormatVerbs[] = {{"convert", AddConvertCommand}, {"inspect", AddInspectCommand}};

}  // namespace

int main(int argc, char** argv) {
  if (NamedVerb(argc, argv, kFormatVerbs) != nullptr) return RunCommandLine(argc, argv, kFormatVerbs);
  return ExecFullExecutable(argv);
}
