// How a generated scene is built and changed: build flags, input layouts
// (instances as pointers, data offsets, first vertex, vertex and box
// strides, one build at a time), vertex formats, copies (clone, compact,
// serialize), and updates of vertices, boxes and instances in random order
// with the copy (scene.build and scene.update, cases/README.md).
#include <cmath>

#include "fuzz/case_generator.h"

namespace rayspec {

// Drawn before the BLASes (scene.build comes first in the file): how many
// updates there will be and the copy, so the order can name them.
void CaseGenerator::buildLayout() {
  updates_ = chance(0.35) ? 1 + pick(3) : 0;
  if (chance(0.3)) copy_ = oneOf<std::string>({"clone", "compact", "serialize"});
  std::string b;
  // feature nullptr: one the text shows (fuzz/content_features.h).
  const auto add = [&](const std::string& key, const std::string& value, const char* feature) {
    b += "    " + key + ": " + value + "\n";
    if (feature) features_.insert(feature);
  };
  if (chance(0.3)) {
    std::string flags =
        oneOf<std::string>({"prefer_fast_trace", "prefer_fast_build", "low_memory"});
    if (chance(0.4)) flags += ", allow_compaction";
    if (chance(0.3)) flags += ", allow_update";
    add("flags", "[" + flags + "]", "build-flags");
  }
  if (copy_ != "none") add("copy", copy_, ("copy-" + copy_).c_str());
  if (updates_ && copy_ != "none") {
    // A deserialized structure is never updated
    // (VUID-vkCmdBuildAccelerationStructuresKHR-pInfos-03667).
    const size_t at = copy_ == "serialize" ? updates_ : pick(updates_ + 1);
    std::string order;
    for (size_t i = 0; i <= updates_; ++i)
      order += std::string(i ? ", " : "") + (i == at ? "copy" : "update");
    add("order", "[" + order + "]", at < updates_ ? "copy-before-update" : "copy-after-updates");
  }
  if (chance(0.15)) add("instances_as_pointers", "true", "instances-as-pointers");
  if (chance(0.15)) add("data_offsets", "true", "data-offsets");
  if (chance(0.06)) add("first_vertex", std::to_string(1 + pick(16)), nullptr);
  // Multiples of 4 of at least 16: a whole vertex of every format, a
  // multiple of every component (VUID-...-vertexStride-03735).
  if (chance(0.15))
    add("vertex_stride", std::to_string(oneOf<int>({16, 20, 24, 32})), "vertex-stride");
  if (chance(0.1)) add("aabb_stride", std::to_string(oneOf<int>({32, 40, 48})), "aabb-stride");
  if (chance(0.1)) add("one_by_one", "true", "one-by-one");
  if (updates_ && copy_ == "none" && chance(0.3)) add("update_into", "other", "update-into-other");
  if (updates_ && chance(0.3)) add("tlas_update", "rebuild", "tlas-rebuild");
  if (!b.empty()) out_ += "  build:\n" + b;
}

// A vertex format other than float3 now and then (snorm16x3 aside: few
// devices build from it).
std::string CaseGenerator::drawFormat(Geometry& g) {
  if (!chance(0.2)) return "";
  static const std::vector<VertexFormat> kFormats = {
      VertexFormat::Float2,    VertexFormat::Half4,     VertexFormat::Half2,
      VertexFormat::Snorm16x4, VertexFormat::Snorm16x2, VertexFormat::Float4,
      VertexFormat::Half3,     VertexFormat::Unorm16x4, VertexFormat::Unorm16x2,
      VertexFormat::Snorm8x4,  VertexFormat::Snorm8x2,  VertexFormat::Unorm8x4,
      VertexFormat::Unorm8x2,  VertexFormat::Unorm10x3};
  g.vertex_format = oneOf(kFormats);
  features_.insert("vertex-format");
  return "          vertex_format: " + std::string(vertexFormatName(g.vertex_format)) + "\n";
}

// A vertex the format holds: snorm in -1..1, unorm in 0..1, z 0 where the
// format has two components.
Vec3 CaseGenerator::drawVertex(VertexFormat f) {
  const VertexEncoding e = vertexEncoding(f);
  const bool unorm = e == VertexEncoding::Unorm || e == VertexEncoding::Packed10;
  const double lo = unorm ? 0 : e == VertexEncoding::Snorm ? -1 : -2, hi = unorm ? 1 : -lo;
  const double x = eighths(lo, hi), y = eighths(lo, hi);
  const double z = vertexComponents(f) == 2 ? 0 : eighths(unorm ? 0 : -1, 1);
  return {float(x), float(y), float(z)};
}

namespace {

std::string boxText(const std::array<float, 6>& box) {
  std::string s;
  for (float v : box) s += (s.empty() ? "" : ", ") + CaseGenerator::num(v);
  return "[" + s + "]";
}

}  // namespace

// One update: new vertices or boxes for some geometries (inactive ones stay
// inactive: a NaN stays where it was; mesh shapes keep theirs), new
// transforms, masks, custom indices and SBT offsets (another range of the
// same BLAS) for some instances. Counts, indices and flags stay.
std::string CaseGenerator::updateStep() {
  std::string blas;
  for (Blas& b : blas_) {
    if (!chance(0.6)) continue;
    std::string list;
    for (size_t k = 0; k < b.data.size(); ++k) {
      Geometry& g = b.data[k];
      std::string entry = "{}";
      if (g.kind == Geometry::Kind::Aabbs && chance(0.7)) {
        features_.insert("update-boxes");
        entry.clear();
        for (auto& box : g.aabbs) {
          const bool nan = std::isnan(box[0]);
          box = drawBox();
          if (nan) box[0] = NAN;
          entry += (entry.empty() ? "" : ", ") + boxText(box);
        }
        entry = "{aabbs: [" + entry + "]}";
      } else if (g.kind == Geometry::Kind::Triangles && !b.shaped[k] && chance(0.7)) {
        features_.insert("update-vertices");
        entry.clear();
        for (Vec3& v : g.vertices) {
          const bool nan = std::isnan(v[0]);
          v = drawVertex(g.vertex_format);
          if (nan) v[0] = NAN;
          entry +=
              (entry.empty() ? "[" : ", [") + num(v[0]) + ", " + num(v[1]) + ", " + num(v[2]) + "]";
        }
        entry = "{vertices: [" + entry + "]}";
      }
      list += (k ? ", " : "") + entry;
    }
    blas += "        " + b.name + ": [" + list + "]\n";
  }
  std::string instances;
  for (size_t i = 0; i < instances_.size(); ++i) {
    if (!instances_[i] || !chance(0.4)) continue;
    features_.insert("update-instances");
    std::string fields = "instance: " + std::to_string(i);
    if (chance(0.6)) fields += ", transform: " + transform(instances_[i]->transform);
    if (chance(0.3)) fields += ", mask: " + std::to_string(1 + pick(255));
    if (chance(0.3)) fields += ", custom_index: " + std::to_string(pick(1u << 24));
    std::vector<size_t> same;
    for (const GroupRange& r : ranges_)
      if (r.blas == instances_[i]->blas) same.push_back(r.first);
    if (chance(0.3)) fields += ", sbt_offset: " + std::to_string(oneOf(same));
    instances += "        - {" + fields + "}\n";
  }
  if (blas.empty() && instances.empty()) {  // keep every geometry as it is
    std::string keep;
    for (size_t k = 0; k < blas_[0].data.size(); ++k) keep += k ? ", {}" : "{}";
    blas = "        " + blas_[0].name + ": [" + keep + "]\n";
  }
  std::string step;
  if (!blas.empty()) step += "      blas:\n" + blas;
  if (!instances.empty()) step += "      instances:\n" + instances;
  return "    - " + step.substr(6);
}

void CaseGenerator::updates() {
  if (!updates_) return;
  if (updates_ > 1) features_.insert("several-updates");
  out_ += "  update:\n";
  for (size_t u = 0; u < updates_; ++u) out_ += updateStep();
}

}  // namespace rayspec
