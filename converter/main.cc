// mocapfill: fill missing degrees of freedom of sketched animations from a motion
// capture database, and convert BVH/glTF/FBX to validator-clean glTF.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>

#include "converter/commands.h"
#include "converter/console.h"
#include "converter/exit_codes.h"

#ifndef MOCAPFILL_VERSION
#define MOCAPFILL_VERSION "0.0.0"
#endif

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
  AddConvertCommand(app, action);
  AddInspectCommand(app, action);
  AddDbCommand(app, action);
  AddFilterCommand(app, action);
  AddAnalyzeCommand(app, action);
  AddFillCommand(app, action);
  AddEvalCommand(app, action);
  AddPcaCommand(app, action);
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
