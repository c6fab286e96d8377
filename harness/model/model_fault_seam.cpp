// The model's fault seam (model_fault_seam.h): built from the options.
#include "model/model_fault_seam.h"

#include "model/model_engine.h"

namespace rayspec {

ModelFaultSeam::ModelFaultSeam(const ModelOptions& opt) : f_(opt.faults) {}

std::optional<ModelFaultSeam::Answer> ModelFaultSeam::answerTaken(size_t legal,
                                                                  size_t leaks) const {
  if (f_.pass_between_edges && leaks > 0) return Answer{true, 0};
  if (f_.legal_answer && legal > 0) return Answer{false, f_.legal_answer % legal};
  return std::nullopt;
}

}  // namespace rayspec
