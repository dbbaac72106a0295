// Command-line flags of the fill methods, shared by `fill` and `eval`.
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "processing/synthesis/fill_options.h"

namespace mocapfill::cli {

// Raw text of the enum flags, parsed after CLI11 is done so errors read as ours.
struct FillFlagText {
  std::string join = "cost-matrix";
  std::string texture = "on";
  std::string coverage = "blend";        // blend or warn
  std::string coverage_prior = "mean";   // mean or nn
  std::string match = "lowpass";
  std::string pca_fit = "subspace";      // hybrid: subspace or full-pose
  std::string keyed_base = "fit";        // hybrid: fit or sketch
  std::string texture_synthesized = "on";
  std::vector<std::string> dials;        // hybrid: "<component>=<sigmas>", 1-based
};

// Adds --join, --texture, --candidates, --blend, --match, --context, --drivers, --phases,
// --samples, --fragment-hz, --threads, --coverage, --coverage-prior, --coverage-poor, --coverage-none bound to `options` / `text`.
void AddFillFlags(CLI::App& command, FillOptions& options, FillFlagText& text);

// Adds the PCA-method flags (`pca`, `hybrid`): --pca-fit, --guide-deg, --key-deg, --variance,
// --max-components, --keyed-base, --texture-synth, --gains, --dial.
void AddPcaMethodFlags(CLI::App& command, FillOptions& options, FillFlagText& text);

// Applies the parsed enum texts to `options`; kInvalidArgument on an unknown value.
Status ApplyFillFlagText(const FillFlagText& text, FillOptions& options);

}  // namespace mocapfill::cli
