// What the public API's classes hold, and the one way their implementations turn a Status
// into a thrown Error. Not installed.
#pragma once

#include <memory>
#include <string>

#include "library/failure_class.h"
#include "mocapfill/database.h"
#include "mocapfill/error.h"
#include "mocapfill/pca.h"
#include "mocapfill/scene.h"
#include "processing/core/motion_database.h"
#include "processing/core/pca_model.h"
#include "processing/core/scene.h"

namespace mocapfill::api {

struct Scene::Impl {
  mocapfill::Scene scene;
};

struct Database::Impl {
  MotionDatabase database;
  std::string name;
};

struct PcaModel::Impl {
  mocapfill::PcaModel model;
};

class SceneAccess {
 public:
  static const mocapfill::Scene& Get(const Scene& scene) { return scene.impl_->scene; }
  static mocapfill::Scene& Get(Scene& scene) { return scene.impl_->scene; }
  static Scene Wrap(mocapfill::Scene scene);
};

class DatabaseAccess {
 public:
  static const MotionDatabase& Get(const Database& database) { return database.impl_->database; }
  static const std::string& Name(const Database& database) { return database.impl_->name; }
  static Database Wrap(MotionDatabase database, std::string name);
};

class PcaModelAccess {
 public:
  static const mocapfill::PcaModel& Get(const PcaModel& model) { return model.impl_->model; }
  static PcaModel Wrap(mocapfill::PcaModel model);
};

// Throws Error of the status's class; does nothing for OK.
void ThrowIfError(const Status& status, FailureStage stage);

template <typename T>
T ValueOrThrow(Result<T> result, FailureStage stage) {
  ThrowIfError(result.status(), stage);
  return std::move(result).value();
}

}  // namespace mocapfill::api
