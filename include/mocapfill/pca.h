// The PCA model of a database (thesis chapter 5): the principal components of its poses,
// which the `pca` and `hybrid` fill methods fit to a sketch's keys.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "mocapfill/database.h"
#include "mocapfill/export.h"

namespace mocapfill::api {

struct PcaOptions {
  double variance_kept = 0.95;      // fewest components whose share of the variance reaches this
  int max_components = 30;
  std::vector<std::string> labels;  // only clips with one of these labels ("walk", "style=happy"); empty = all
};

class PcaModelAccess;

class MOCAPFILL_API PcaModel {
 public:
  // Throws Error (kUsage for bad options or labels no clip has).
  static PcaModel Build(const Database& database, const PcaOptions& options = {});
  // Reads a .pca file (`mocapfill pca build`). Throws Error (kInvalidInput).
  static PcaModel Open(const std::string& path);
  void Save(const std::string& path) const;  // throws Error (kOutput)

  int component_count() const;
  std::vector<double> variances() const;  // per component, largest first

 private:
  friend class PcaModelAccess;
  struct Impl;
  explicit PcaModel(std::shared_ptr<const Impl> impl);
  std::shared_ptr<const Impl> impl_;
};

}  // namespace mocapfill::api
