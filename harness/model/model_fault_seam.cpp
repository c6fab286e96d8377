// The model's fault seam (model_fault_seam.h): built from the options.
#include "model/model_fault_seam.h"

#include "case/case.h"
#include "model/model_engine.h"

namespace rayspec {

ModelFaultSeam::ModelFaultSeam(const ModelOptions& opt, const Pipeline* inlining)
    : f_(opt.faults),
      inlined_from_depth_(!inlining                    ? 0
                          : inlining->ray_query        ? 1
                          : inlining->ray_query_in_hit ? 2
                                                       : 0) {}

ModelFaultSeam::InlinedQuery ModelFaultSeam::inlinedQuery(uint32_t depth) const {
  InlinedQuery q;
  if (!inlined_from_depth_ || depth < inlined_from_depth_) return q;
  q.opaque_offered = f_.rq_opaque_offered;
  q.confirm_ignored = f_.rq_confirm_ignored;
  q.confirm_only_first = f_.rq_confirm_only_first;
  q.generate_ignored = f_.rq_generate_ignored;
  q.terminate_ignored = f_.rq_terminate_ignored;
  q.commit_keeps_interval = f_.rq_commit_keeps_interval;
  q.candidate_type_swapped = f_.rq_candidate_type_swapped;
  q.front_face_inverted = f_.rq_front_face_inverted;
  q.custom_index_is_instance_id = f_.rq_custom_index_is_instance_id;
  return q;
}

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
