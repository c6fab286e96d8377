// Acceleration structure operations broken. R-AS-COPY: a copy of a top level (scene.build.copy:
// clone or compact) that loses an instance, as a device whose copy drops the last instance record:
// the scene as that device traces it.
#include "fault/fault_impl.h"

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
  if (!c.scene.built) return "";
  const std::shared_ptr<const Scene> built = c.scene.built;
  c.scene = *built;
  return "the update was ignored: the scene as first built";
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

}  // namespace rayspec
