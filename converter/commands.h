// The CLI's verbs. Each Add*Command adds one subcommand to the app; when the user picks
// it, `action` is set to the function that runs it and returns the exit code. Commands
// are thin: parse options, call formats/ and processing/, print, map errors to exit codes.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>

namespace mocapfill::cli {

using CommandAction = std::function<int()>;

void AddConvertCommand(CLI::App& app, CommandAction& action);
void AddInspectCommand(CLI::App& app, CommandAction& action);
void AddDbCommand(CLI::App& app, CommandAction& action);
void AddFilterCommand(CLI::App& app, CommandAction& action);
void AddAnalyzeCommand(CLI::App& app, CommandAction& action);
void AddFillCommand(CLI::App& app, CommandAction& action);
void AddEvalCommand(CLI::App& app, CommandAction& action);
void AddPcaCommand(CLI::App& app, CommandAction& action);
void AddRunCommand(CLI::App& app, CommandAction& action);
void AddRigCommand(CLI::App& app, CommandAction& action);

}  // namespace mocapfill::cli
