// mocapfill-full: every verb of the mocapfill CLI. Users run `mocapfill`, which executes
// the format verbs itself and replaces itself with this program for the others (main.cc).
#include <iterator>

#include "converter/verb_dispatch.h"

namespace {

using namespace mocapfill::cli;

constexpr Verb kVerbs[] = {
    {"convert", AddConvertCommand}, {"inspect", AddInspectCommand}, {"db", AddDbCommand},
    {"filter", AddFilterCommand},   {"analyze", AddAnalyzeCommand}, {"fill", AddFillCommand},
    {"eval", AddEvalCommand},       {"pca", AddPcaCommand},         {"run", AddRunCommand},
    {"rig", AddRigCommand},
};

}  // namespace

int main(int argc, char** argv) { return RunCommandLine(argc, argv, kVerbs); }
