// Acceleration structure operations broken. R-AS-COPY: a copy of a top level (scene.build.copy:
// clone or compact) that loses an instance, as a device whose copy drops the last instance record:
// the scene as that device traces it.
#include <cmath>

#include "case/vertex_format_misread.h"
#include "fault/fault_impl.h"
#include "fault/program_edit.h"

namespace rayspec {

std::string copyDropsInstance(Case& c, ModelOptions&) {
  if (c.scene.build.copy == AsCopy::None) return "";
  for (size_t i = c.scene.instances.size(); i-- > 0;) {
    Instance& inst = c.scene.instances[i];
    if (!inst.blas) continue;
    inst.blas.reset();
    return "the " + std::string(asCopyName(c.scene.build.copy)) + " copy lost instance " +
           std::to_string(i);
  }
  return "";
}

// R-AS-UPDATE broken: an update (scene.update) that changes nothing, as a
// device whose refit keeps the old vertices, boxes and instances.
std::string updateIgnored(Case& c, ModelOptions&) {
  if (!c.scene.updates()) return "";
  const std::shared_ptr<const Scene> built = c.scene.earlier.front();
  c.scene = *built;
  return "the update was ignored: the scene as first built";
}

// R-AS-UPDATE broken for a structure updated before: the first update takes
// effect, every later one changes nothing (a refit that works only from a
// fresh build).
std::string laterUpdatesIgnored(Case& c, ModelOptions&) {
  if (c.scene.updates() < 2) return "";
  const size_t updates = c.scene.updates();
  const std::shared_ptr<const Scene> first = c.scene.earlier[1];
  c.scene = *first;
  return "updates 2 to " + std::to_string(updates) + " were ignored: the scene after the first";
}

// R-AS-UPDATE broken on copies (scene.build.order with an update after the
// copy): updating a cloned, compacted or deserialized structure changes
// nothing, as a device whose copy loses what a refit needs.
std::string copyUpdateIgnored(Case& c, ModelOptions&) {
  const size_t before = c.scene.updatesBeforeCopy(), updates = c.scene.updates();
  if (c.scene.build.copy == AsCopy::None || before == updates) return "";
  const std::shared_ptr<const Scene> at_copy = c.scene.earlier[before];
  c.scene = *at_copy;
  return "the " + std::to_string(updates - before) + " update(s) of the copies were ignored";
}

// R-AS-UPDATE broken for primitives degenerate when first built (R-DEGEN: a
// triangle of no area, a box that is a point): a device whose build leaves
// them out of the structure (legal there: they give no intersection) and
// whose update then cannot refit them, so those the updates make whole are
// never hit, as if inactive.
namespace {

bool boxIsPoint(const std::array<float, 6>& a) {
  return a[0] == a[3] && a[1] == a[4] && a[2] == a[5];
}

// Primitive p of g, degenerate in `built` and whole in g, made inactive.
bool loseIfMadeWhole(const Geometry& built, Geometry& g, uint32_t p) {
  if (g.kind == Geometry::Kind::Aabbs) {
    if (!boxIsPoint(built.aabbs[p]) || boxIsPoint(g.aabbs[p]) || std::isnan(g.aabbs[p][0]))
      return false;
    g.aabbs[p][0] = std::nanf("");
    return true;
  }
  if (!degenerateTriangle(built, p) || degenerateTriangle(g, p)) return false;
  std::array<Vec3, 3> t;
  for (uint32_t k = 0; k < 3; ++k) {
    const uint32_t i = g.indices.empty() ? p * 3 + k : g.indices[p * 3 + k];
    if (i >= g.vertices.size() || std::isnan(g.vertices[i][0])) return false;
    t[k] = g.vertices[i];
  }
  t[0][0] = std::nanf("");
  setTriangle(g, p, t);
  return true;
}

}  // namespace

std::string updateDegenerateLost(Case& c, ModelOptions&) {
  if (!c.scene.updates()) return "";
  const Scene& built = *c.scene.earlier.front();
  size_t n = 0;
  for (size_t b = 0; b < c.scene.blases.size() && b < built.blases.size(); ++b) {
    std::vector<Geometry>& now = c.scene.blases[b].geometries;
    for (size_t k = 0; k < now.size() && k < built.blases[b].geometries.size(); ++k) {
      const Geometry& then = built.blases[b].geometries[k];
      for (uint32_t p = 0; p < now[k].primitiveCount() && p < then.primitiveCount(); ++p)
        n += loseIfMadeWhole(then, now[k], p);
    }
  }
  return describeCount(n,
                       "primitives degenerate as first built and made whole by the updates "
                       "left out");
}

// R-AS-CREATE broken (scene.build.storage reused): a device whose
// vkCreateAccelerationStructureKHR writes the memory it is given, so the
// structure created over the built top level leaves it empty, as the model
// sees a cleared structure (creation-clears-memory does it on a live device).
std::string creationEmptiesStructure(Case& c, ModelOptions&) {
  if (c.scene.build.storage != StructureStorage::Reused) return "";
  size_t n = 0;
  for (Instance& inst : c.scene.instances) {
    n += inst.blas.has_value();
    inst.blas.reset();
  }
  return describeCount(n, "instances of the top level a structure was created over lost");
}

// R-VERTEX-FORMAT broken: a device that does not round positions to their
// vertex format (triangles.vertex_format): the positions as the case wrote them.
std::string vertexFormatIgnored(Case& c, ModelOptions&) {
  size_t n = 0;
  for (Blas& b : c.scene.blases)
    for (Geometry& g : b.geometries)
      if (!g.written.empty() && g.written != g.vertices) {
        g.vertices = g.written;
        ++n;
      }
  return n ? std::to_string(n) + " geometries traced at their unrounded positions" : "";
}

// R-VERTEX-FORMAT broken another way: a device that reads each geometry's
// vertex bytes in a format it confuses with the real one
// (case/vertex_format_misread.h): the positions such a build traces. On a
// device, the layout fault vertex-format-misread does the same.
std::string vertexFormatConfused(Case& c, ModelOptions&) {
  size_t n = 0;
  for (Blas& b : c.scene.blases)
    for (Geometry& g : b.geometries)
      if (g.kind == Geometry::Kind::Triangles && vertexFormatMisread(g.vertex_format)) {
        g.vertices = misreadVertices(g.vertex_format, g.vertices);
        ++n;
      }
  return n ? std::to_string(n) +
                 " geometries traced as a build that confuses their format reads them"
           : "";
}

// Empty geometries and acceleration structures broken: a device that leaves
// geometries without primitives, and instances of BLASes without any, out
// when it numbers the rest (gl_GeometryIndexEXT, gl_InstanceID and the SBT
// index that follows from them).
std::string emptyGeometryRenumbered(Case& c, ModelOptions&) {
  if (c.scene.updates()) return "";
  size_t geometries = 0, instances = 0;
  for (Blas& b : c.scene.blases) {
    const size_t before = b.geometries.size();
    std::erase_if(b.geometries, [](const Geometry& g) { return g.primitiveCount() == 0; });
    geometries += before - b.geometries.size();
  }
  const size_t before = c.scene.instances.size();
  std::erase_if(c.scene.instances, [&](const Instance& i) {
    return i.blas && c.scene.blases[*i.blas].geometries.empty();
  });
  instances = before - c.scene.instances.size();
  if (geometries + instances == 0) return "";
  return std::to_string(geometries) + " empty geometries and " + std::to_string(instances) +
         " instances of empty BLASes left out of the numbering";
}

// Large builds broken (R-AS-SIZE): a device that keeps a build's primitive
// count of each geometry and its instance count in 16 bits, so that 2^16
// primitives or instances become none and 2^16 + k become the first k.
std::string buildCounts16Bit(Case& c, ModelOptions&) {
  if (c.scene.updates()) return "";
  constexpr uint32_t kWrap = 1u << 16;
  size_t geometries = 0;
  for (Blas& b : c.scene.blases)
    for (Geometry& g : b.geometries) {
      const uint32_t n = g.primitiveCount();
      if (n < kWrap) continue;
      const size_t keep = n % kWrap;
      if (g.kind == Geometry::Kind::Aabbs) {
        g.aabbs.resize(keep);
      } else if (!g.indices.empty()) {
        g.indices.resize(3 * keep);
      } else {
        g.vertices.resize(3 * keep);
        if (!g.written.empty()) g.written.resize(3 * keep);
      }
      ++geometries;
    }
  const bool instances = c.scene.instances.size() >= kWrap;
  if (instances) c.scene.instances.resize(c.scene.instances.size() % kWrap);
  if (!geometries && !instances) return "";
  return std::to_string(geometries) + " geometries" + (instances ? " and the instance list" : "") +
         " cut to their count modulo 2^16";
}

// R-AS-BUILD broken: builds one after another in the same scratch memory
// (scene.build.one_by_one) where each after the first finds the one before's
// state in it and builds that: every BLAS but the first traced as the BLAS
// before it in the scene's list.
std::string sharedScratchKeepsPrevious(Case& c, ModelOptions&) {
  if (!c.scene.build.one_by_one || c.scene.blases.size() < 2 || c.scene.updates()) return "";
  for (size_t b = c.scene.blases.size(); b-- > 1;)
    c.scene.blases[b].geometries = c.scene.blases[b - 1].geometries;
  return std::to_string(c.scene.blases.size() - 1) +
         " BLASes built as the one before them in the shared scratch";
}

}  // namespace rayspec
