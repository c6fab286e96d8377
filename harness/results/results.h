// What one execution of a case produced, device or model, in one schema.
// A results bundle on disk is a folder: results.json (everything below but the
// image pixels), records.bin (the raw per-ray words), and one NAME.raw per
// image (raw little-endian 32-bit texels) plus NAME.png / NAME.exr when the
// binary is built with OpenImageIO. See results/results_io.h.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace rayspec {

struct Image {
  std::string name;
  std::string field;        // record field it shows
  uint32_t width = 0, height = 0, channels = 1;
  bool is_float = false;    // rgba32f (channels 4) or r32ui (channels 1)
  std::vector<uint32_t> texels;  // width*height*channels words (float bits when is_float)
};

// A ray the model's exact tier found numerically ambiguous, with the answers
// the specification allows for it.
struct Candidate {
  bool hit = false;          // false: a miss is a legal answer
  uint32_t instance = 0, geometry = 0, primitive = 0;
};
struct RayAmbiguity {
  uint32_t ray = 0;          // launch index y * width + x
  std::string reason;        // "edge", "vertex", "tmax-tie", "tmin-tie", "t-tie",
                             // "first-hit" (terminate_on_first_hit), "aabb-face",
                             // "shader-arith" (an intersection program decision within rounding)
  std::vector<Candidate> candidates;
  // edge / vertex: the triangles the model found within the error bound of
  // the shared edge or vertex (each once); a watertight device finds one.
  std::vector<Candidate> shared_triangles;
};

// A ray whose hit t a device may compute further from the model's than the
// default tolerance allows (exact tier; the rounding of an intersection
// program's arithmetic, such as a sphere root near tangency, R-PREC).
struct TBound {
  uint32_t ray = 0;
  float bound = 0;  // |device t - model t| may reach this
};

struct Results {
  std::string case_name;
  std::string backend;      // "vulkan" or "model"
  std::string device;       // Vulkan device name, or "embree-<tier>"
  std::string status;       // "ok", or "NotSupported: ..." / "Crash: ..." from the backend
  uint32_t width = 0, height = 0;
  std::map<std::string, uint64_t> counters;
  std::vector<uint32_t> records;  // width*height*recordWords() words
  std::vector<Image> images;
  std::vector<RayAmbiguity> ambiguous;  // model, exact tier: rays that are not clear
  std::vector<TBound> t_bounds;         // model, exact tier: clear rays with a wider t bound
  std::vector<std::string> validation_messages;  // validation-layer errors (device)
  double seconds = 0.0;     // wall time of the execution (setup + trace + read-back)
  std::string case_file;    // path of the case's YAML file (`rayspec compare` re-parses it)
};

}  // namespace rayspec
