#include "formats/pca/pca_file.h"
#include "library/api/access.h"
#include "processing/pca/pca_model_builder.h"

namespace mocapfill::api {

PcaModel PcaModelAccess::Wrap(mocapfill::PcaModel model) {
  auto impl = std::make_shared<PcaModel::Impl>();
  impl->model = std::move(model);
  return PcaModel(std::move(impl));
}

PcaModel::PcaModel(std::shared_ptr<const Impl> impl) : impl_(std::move(impl)) {}

PcaModel PcaModel::Build(const Database& database, const PcaOptions& options) {
  PcaModelOptions build;
  build.basis.variance_kept = options.variance_kept;
  build.basis.max_components = options.max_components;
  build.labels = options.labels;
  return PcaModelAccess::Wrap(
      ValueOrThrow(BuildPcaModel(DatabaseAccess::Get(database), build), FailureStage::kProcessing));
}

PcaModel PcaModel::Open(const std::string& path) {
  return PcaModelAccess::Wrap(ValueOrThrow(ReadPcaModel(path), FailureStage::kInput));
}

void PcaModel::Save(const std::string& path) const {
  ThrowIfError(WritePcaModel(impl_->model, path), FailureStage::kOutput);
}

int PcaModel::component_count() const { return impl_->model.num_components(); }

std::vector<double> PcaModel::variances() const {
  const Eigen::VectorXd& v = impl_->model.variances;
  return std::vector<double>(v.data(), v.data() + v.size());
}

}  // namespace mocapfill::api
