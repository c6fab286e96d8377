// Case mutations at the ends of the ray interval: the model run as a device
// that judges an exactly representable end the wrong way (the model's test-only
// deviation, model/model_faults.h). Only rays that meet a candidate at exactly
// an end answer differently.
#include "fault/fault_impl.h"

namespace rayspec {

std::string closedTriangleInterval(Case&, ModelOptions& o) {
  o.faults.deviation = ModelDeviation::ClosedTriangleInterval;
  return "triangles at exactly tmin or tmax are candidates (a closed interval)";
}

std::string openAabbInterval(Case&, ModelOptions& o) {
  o.faults.deviation = ModelDeviation::OpenAabbInterval;
  return "reportIntersectionEXT at exactly tmin or the current tmax returns false (an open "
         "interval)";
}

}  // namespace rayspec
