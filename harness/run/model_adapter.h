// The Embree reference model as a Backend.
#pragma once

#include "model/model_engine.h"
#include "run/backend.h"

namespace rayspec {

class ModelAdapter : public Backend {
 public:
  explicit ModelAdapter(const ModelOptions& options) : options_(options) {}
  std::string name() const override { return "model"; }
  std::string description() const override;
  Result<Results> run(const Case& c, const Plan& plan) override {
    return runOnModel(c, plan, options_);
  }
  std::vector<std::string> close() override { return {}; }

 private:
  ModelOptions options_;
};

}  // namespace rayspec
