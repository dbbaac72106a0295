// Command-line flags of the fill methods, shared by `fill` and `eval`.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "processing/synthesis/fill_options.h"

namespace mocapfill::cli {

// Raw text of the enum flags, parsed after CLI11 is done so errors read as ours.
struct FillFlagText {
  std::string join = "cost-matrix";
  std::string texture = "on";
  std::string match = "lowpass";
};

// Adds --join, --texture, --candidates, --blend, --match, --context, --drivers, --phases,
// --samples, --fragment-hz, --threads bound to `options` / `text`.
void AddFillFlags(CLI::App& command, FillOptions& options, FillFlagText& text);

// Applies the parsed enum texts to `options`; kInvalidArgument on an unknown value.
Status ApplyFillFlagText(const FillFlagText& text, FillOptions& options);

}  // namespace mocapfill::cli
