// scene.split: {blas: NAME, into: geometries | instances, translate: [x, y, z],
// cycle_axes: false} (case/split_mesh.h), applied once the rays are aimed at
// the whole mesh.
#include "case/split_mesh.h"
#include "parse/parse_parts.h"

namespace rayspec {
namespace {

bool readInto(YamlReader& r, const YAML::Node& m, const std::string& f, SplitSpec& spec) {
  const auto into = r.string(YamlReader::get(m, "into"), f + ".into");
  if (!into) return false;
  if (*into == "geometries" || *into == "instances") {
    spec.into = *into == "geometries" ? SplitSpec::Into::Geometries : SplitSpec::Into::Instances;
    return true;
  }
  r.error(YamlReader::get(m, "into"), f + ".into",
          "unknown split '" + *into + "' (geometries, instances)");
  return false;
}

bool readBlas(YamlReader& r, const YAML::Node& m, const std::string& f, const Scene& scene,
              SplitSpec& spec) {
  const auto name = r.string(YamlReader::get(m, "blas"), f + ".blas");
  if (!name) return false;
  for (size_t i = 0; i < scene.blases.size(); ++i)
    if (scene.blases[i].name == *name) {
      spec.blas = static_cast<uint32_t>(i);
      return true;
    }
  r.error(YamlReader::get(m, "blas"), f + ".blas", "unknown BLAS '" + *name + "'");
  return false;
}

// The moves of the pieces: only where they are instances.
bool readMoves(YamlReader& r, const YAML::Node& m, const std::string& f, SplitSpec& spec) {
  const bool moved = YamlReader::has(m, "translate") || YamlReader::has(m, "cycle_axes");
  if (moved && spec.into != SplitSpec::Into::Instances) {
    r.error(m, f, "translate and cycle_axes move instances: only with into: instances");
    return false;
  }
  if (YamlReader::has(m, "translate")) {
    const auto t = r.numbers<3>(YamlReader::get(m, "translate"), f + ".translate");
    if (!t) return false;
    for (int k = 0; k < 3; ++k) spec.translate[k] = static_cast<float>((*t)[k]);
  }
  if (YamlReader::has(m, "cycle_axes")) {
    const auto c = parseTrueFalse(r, YamlReader::get(m, "cycle_axes"), f + ".cycle_axes");
    if (!c) return false;
    spec.cycle_axes = *c;
  }
  return true;
}

}  // namespace

void parseSceneSplit(YamlReader& r, const YAML::Node& m, Scene& scene) {
  const std::string f = "scene.split";
  if (!r.expectMap(m, f, {"blas", "into", "translate", "cycle_axes"}) ||
      !(r.require(m, f, "blas") & r.require(m, f, "into")))
    return;
  SplitSpec spec;
  if (!readBlas(r, m, f, scene, spec) || !readInto(r, m, f, spec) || !readMoves(r, m, f, spec))
    return;
  if (Result<void> split = splitMesh(scene, spec); !split) r.error(m, f, split.error().message);
}

}  // namespace rayspec
