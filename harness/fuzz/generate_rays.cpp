// The rays of a generated case: a list aimed at the scene's primitives or
// from around it, a grid looking down, or the `aim` form over a mesh; tmin,
// tmax, flags, cull masks, miss indices, 3D launches and the indirect
// command.
#include "fuzz/case_generator.h"

namespace rayspec {

// At most one flag of each group that the specification lets go together
// (VUID-RuntimeSpirv-OpTraceRayKHR and the like: one opacity flag, one
// culling or skipping flag).
std::string CaseGenerator::rayFlags() {
  static const std::vector<std::string> kOpacity = {"opaque", "no_opaque", "cull_opaque",
                                                    "cull_no_opaque"};
  static const std::vector<std::string> kCulling = {"cull_back_facing", "cull_front_facing",
                                                    "skip_triangles", "skip_aabbs"};
  std::string flags;
  const auto add = [&](const std::string& f) {
    flags += (flags.empty() ? "" : ", ") + f;
  };
  if (chance(0.3)) add(oneOf(kOpacity));
  if (chance(0.3)) add(oneOf(kCulling));
  if (chance(0.15)) add("terminate_on_first_hit");
  if (chance(0.1)) add("skip_closest_hit");
  if (!flags.empty()) features_.insert("ray-flags");
  return flags;
}

// From a point around the scene towards one inside it.
std::string CaseGenerator::wanderingRay() {
  const double ox = eighths(-6, 6), oy = eighths(-6, 6), oz = chance(0.5) ? 6.0 : -6.0;
  const double tx = eighths(-1.5, 1.5), ty = eighths(-1.5, 1.5), tz = eighths(-1, 1);
  return "{origin: [" + num(ox) + ", " + num(oy) + ", " + num(oz) + "], direction: [" +
         num(tx - ox) + ", " + num(ty - oy) + ", " + num(tz - oz) + "]";
}

// Aimed at a primitive (generate_aim.cpp: the point at t = 1) mostly, else
// wandering; an interval, flags, a cull mask and a miss index now and then.
std::string CaseGenerator::listRay() {
  std::optional<std::string> aimed;
  if (chance(0.75)) aimed = aimedRay();
  std::string ray = aimed ? *aimed : wanderingRay();
  if (chance(0.2)) {
    const double tmin = eighths(0, 0.5);
    ray += ", tmin: " + num(tmin) + ", tmax: " + num(tmin + eighths(0.25, 2));
    features_.insert("ray-interval");
  }
  const std::string flags = rayFlags();
  if (!flags.empty()) ray += ", flags: [" + flags + "]";
  if (chance(0.2)) {
    features_.insert("cull-mask");
    ray += ", cull_mask: " +
           std::to_string(chance(0.5) ? oneOf<int>({1, 2, 0x7F, 0x80}) : int(pick(256)));
  }
  if (miss_count_ > 1 && chance(0.5)) ray += ", miss: " + std::to_string(pick(miss_count_));
  return ray + "}";
}

// Now and then the form's w x h rays launched in layers (rays.launch:
// R-LAUNCH-3D), and the launch size read from a buffer (rays.command:
// indirect, R-INDIRECT).
std::string CaseGenerator::launch(uint64_t w, uint64_t h) {
  // d: the smallest factor of the rows, or of the width for one row (the
  // rays of a list).
  const uint64_t rows = h > 1 ? h : w;
  uint64_t d = 2;
  while (rows % d) ++d;
  const auto size = [](uint64_t x, uint64_t y, uint64_t z) {
    return "  launch: [" + std::to_string(x) + ", " + std::to_string(y) + ", " + std::to_string(z) +
           "]\n";
  };
  std::string out;
  const bool layers = chance(0.2);
  if (layers) {
    features_.insert("launch-3d");
    out += h > 1 ? size(w, h / d, d) : size(w / d, 1, d);
  }
  if (chance(0.12)) {
    features_.insert("indirect-launch");
    indirect_ = true;
    out += "  command: indirect\n";
    // A list in d rows: a launch of one row has no row for a wrong height
    // to lose.
    if (!layers && h == 1) out += size(w / d, d, 1);
  }
  return out;
}

void CaseGenerator::rays() {
  miss_count_ = 1 + pick(2);
  out_ += "rays:\n";
  const std::string aim = chance(0.25) ? aimForm() : "";
  if (!aim.empty()) {
    out_ += aim;
    edge_rays_ =
        aim.find("vertices") != std::string::npos || aim.find("edges") != std::string::npos;
  } else if (chance(0.7)) {
    features_.insert("ray-list");
    out_ += "  list:\n";
    const size_t count = 2 + pick(8);
    for (size_t i = 0; i < count; ++i) out_ += "    - " + listRay() + "\n";
    for (const char* f : {"aimed-edge", "aimed-vertex", "grazing-ray"})
      edge_rays_ = edge_rays_ || features_.count(f);
    out_ += launch(count, 1);
  } else {
    features_.insert("ray-grid");
    const uint64_t w = 2 + pick(4), h = 2 + pick(4);
    const double z = chance(0.5) ? 6.0 : -6.0;
    out_ += "  grid: {size: [" + std::to_string(w) + ", " + std::to_string(h) + "], origin: [" +
            num(eighths(-3, -2)) + ", " + num(eighths(-3, -2)) + ", " + num(z) + "], du: [" +
            num(5.0 / double(w)) + ", 0.0, 0.0], dv: [0.0, " + num(5.0 / double(h)) +
            ", 0.0], direction: [" + num(eighths(-0.5, 0.5)) + ", " + num(eighths(-0.5, 0.5)) +
            ", " + num(-z / 6.0) + "]}\n";
    out_ += launch(w, h);
  }
  const double tmin = chance(0.5) ? 0.001 : eighths(0, 0.5);
  out_ += "  tmin: " + num(tmin) + "\n  tmax: " + num(chance(0.7) ? 100.0 : eighths(5, 9)) + "\n";
  const std::string flags = rayFlags();
  if (!flags.empty()) out_ += "  flags: [" + flags + "]\n";
  if (chance(0.15)) {
    features_.insert("cull-mask");
    out_ += "  cull_mask: " + std::to_string(oneOf<int>({1, 2, 0xFE})) + "\n";
  }
  if (chance(0.1)) {
    features_.insert("sbt-stride-0");
    sbt_stride_zero_ = true;
    out_ += "  sbt_stride: 0\n";
  }
}

}  // namespace rayspec
