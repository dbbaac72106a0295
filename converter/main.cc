// mocapfill: fill missing degrees of freedom of sketched animations from a motion
// capture database, and convert BVH/glTF/FBX to validator-clean glTF.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <cstring>
#include <exception>
#include <string_view>

#include "converter/commands.h"
#include "converter/console.h"
#include "converter/exit_codes.h"

#ifndef MOCAPFILL_VERSION
#define MOCAPFILL_VERSION "0.0.0"
#endif

namespace {

using mocapfill::cli::CommandAction;

struct Verb {
  const char* name;
  void (*add)(CLI::App&, CommandAction&);
};

constexpr Verb kVerbs[] = {
    {"convert", mocapfill::cli::AddConvertCommand}, {"inspect", mocapfill::cli::AddInspectCommand},
    {"db", mocapfill::cli::AddDbCommand},           {"filter", mocapfill::cli::AddFilterCommand},
    {"analyze", mocapfill::cli::AddAnalyzeCommand}, {"fill", mocapfill::cli::AddFillCommand},
    {"eval", mocapfill::cli::AddEvalCommand},       {"pca", mocapfill::cli::AddPcaCommand},
    {"run", mocapfill::cli::AddRunCommand},
};

// The verb the command line names: its first argument that is not one of the top-level
// flags. Building every verb's options costs about as much as a small conversion (the
// fill and eval verbs have dozens), so when the verb is known only it is built; help,
// --version and unknown verbs get them all, and CLI11 reports exactly as before.
const Verb* NamedVerb(int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if (arg == "-q" || arg == "--quiet") continue;
    for (const Verb& verb : kVerbs)
      if (arg == verb.name) return &verb;
    return nullptr;
  }
  return nullptr;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace mocapfill::cli;
  CLI::App app{"mocapfill " MOCAPFILL_VERSION
               ": complete sparse keyframed animations from a motion capture database; "
               "convert BVH, glTF and FBX to glTF 2.0"};
  app.set_version_flag("--version", std::string("mocapfill ") + MOCAPFILL_VERSION);
  bool quiet = false;
  app.add_flag("-q,--quiet", quiet, "Print only errors")->configurable(false);
  app.require_subcommand(1);
  app.footer(
      "Exit codes: 0 ok, 1 usage, 2 invalid input, 3 processing failure, 4 output failure.\n"
      "Run 'mocapfill <command> --help' for the options and examples of a command.");
  CommandAction action;
  if (const Verb* verb = NamedVerb(argc, argv)) {
    verb->add(app, action);
  } else {
    for (const Verb& v : kVerbs) v.add(app, action);
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? kExitOk : kExitUsage;
  }
  SetQuiet(quiet);
  try {
    return action ? action() : kExitUsage;
  } catch (const std::exception& e) {
    // Last resort: library code reports failures as Status; reaching here is a bug.
    PrintError(std::string("internal error: ") + e.what());
    return kExitProcessing;
  }
}
