// The model's fault seam (model_fault_seam.h): built from the options.
#include "model/model_fault_seam.h"

#include "model/model_engine.h"

namespace rayspec {

ModelFaultSeam::ModelFaultSeam(const ModelOptions& opt) : f_(opt.faults) {}

// splitmix64 of the key and the seed: a shuffle that is the same on every run.
uint64_t ModelFaultSeam::permutedRank(uint32_t instance, uint32_t geometry,
                                      uint32_t primitive) const {
  uint64_t x = (uint64_t{instance} << 40) ^ (uint64_t{geometry} << 24) ^ primitive ^
               (uint64_t{f_.order_seed} * 0x9E3779B97F4A7C15ull);
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

std::optional<ModelFaultSeam::Answer> ModelFaultSeam::answerTaken(size_t legal,
                                                                  size_t leaks) const {
  if (f_.pass_between_edges && leaks > 0) return Answer{true, 0};
  if (f_.legal_answer && legal > 0) return Answer{false, f_.legal_answer % legal};
  return std::nullopt;
}

}  // namespace rayspec
