#include "converter/verb_dispatch.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <exception>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "converter/console.h"
#include "converter/exit_codes.h"

#ifndef MOCAPFILL_VERSION
#define MOCAPFILL_VERSION "0.0.0"
#endif

namespace mocapfill::cli {

namespace {

constexpr const char* kFullExecutable = "mocapfill-full";

bool IsTopLevelFlag(std::string_view arg) { return arg == "-q" || arg == "--quiet"; }

}  // namespace

const Verb* NamedVerb(int argc, char** argv, std::span<const Verb> verbs) {
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if (IsTopLevelFlag(arg)) continue;
    for (const Verb& verb : verbs)
      if (arg == verb.name) return &verb;
    return nullptr;
  }
  return nullptr;
}

int RunCommandLine(int argc, char** argv, std::span<const Verb> verbs) {
  CLI::App app{"mocapfill " MOCAPFILL_VERSION
               ": complete sparse keyframed animations from a motion capture database; "
               "convert BVH, glTF and FBX to glTF 2.0"};
  app.set_version_flag("--version", std::string("mocapfill ") + MOCAPFILL_VERSION);
  bool quiet = false;
  app.add_flag("-q,--quiet", quiet, "Print only errors")->configurable(false);
  app.require_subcommand(1);
  // Options a verb does not know go to the top level: `mocapfill convert a.bvh a.glb -q`.
  app.fallthrough();
  app.footer(
      "Exit codes: 0 ok, 1 usage, 2 invalid input, 3 processing failure, 4 output failure.\n"
      "Run 'mocapfill <command> --help' for the options and examples of a command.");
  CommandAction action;
  if (const Verb* verb = NamedVerb(argc, argv, verbs)) {
    verb->add(app, action);
  } else {
    for (const Verb& v : verbs) v.add(app, action);
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

int ExecFullExecutable(char** argv) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path dir = fs::read_symlink("/proc/self/exe", ec).parent_path();
  if (ec) {
    PrintError(std::string("cannot locate this executable to find ") + kFullExecutable + ": " + ec.message());
    return kExitProcessing;
  }
  const std::vector<fs::path> candidates = {dir / kFullExecutable,
                                            dir.parent_path() / "libexec" / "mocapfill" / kFullExecutable};
  std::string tried;
  for (const fs::path& path : candidates) {
    ::execv(path.c_str(), argv);  // returns only on failure
    tried += "\n  " + path.string() + " (" + std::strerror(errno) + ")";
  }
  PrintError(std::string("cannot run ") + kFullExecutable +
             ", which carries every verb but convert and inspect; tried:" + tried);
  return kExitProcessing;
}

}  // namespace mocapfill::cli
