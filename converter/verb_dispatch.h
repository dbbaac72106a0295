// Running the verb a command line names. Shared by the two executables: `mocapfill`, which
// runs the format verbs (convert, inspect) itself and hands every other command line to
// `mocapfill-full`, which runs them all (see main.cc for why there are two).
#pragma once

#include <span>

#include "converter/commands.h"

namespace mocapfill::cli {

struct Verb {
  const char* name;
  void (*add)(CLI::App&, CommandAction&);
};

// The verb the command line names: its first argument that is not a top-level flag (-q),
// when that is one of `verbs`; nullptr otherwise (help, --version, an unknown verb).
const Verb* NamedVerb(int argc, char** argv, std::span<const Verb> verbs);

// Parses the command line and runs its verb; returns the exit code. Only the named verb's
// options are built (the fill and eval verbs have dozens, and building every verb cost about
// as much as a small conversion); without a named verb all of `verbs` are, so that help and
// errors come out as CLI11 reports them.
int RunCommandLine(int argc, char** argv, std::span<const Verb> verbs);

// Replaces this process with mocapfill-full, passing the command line on unchanged. Looks
// beside this executable (the build tree), then in <prefix>/libexec/mocapfill (installed).
// Returns only on failure, with the exit code after printing why.
int ExecFullExecutable(char** argv);

}  // namespace mocapfill::cli
