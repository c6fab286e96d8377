// Internal to the parse module: the readers of each section of a case file and its checks.
// Each records its problems in the YamlReader and fills what it could read.
#pragma once

#include <optional>
#include <string>

#include "case/case.h"
#include "parse/yaml_reader.h"

namespace rayspec {

void parseScene(YamlReader& r, const YAML::Node& n, Scene& scene);
// A yes/no field: true or false (parse_scene.cpp).
std::optional<bool> parseSwitch(YamlReader& r, const YAML::Node& n, const std::string& field);
// scene.update (parse_update.cpp): `scene` as parsed becomes Scene::built,
// and `scene` the scene after the update.
void parseSceneUpdate(YamlReader& r, const YAML::Node& n, Scene& scene);
// scene.build.queries and query_command (parse_structure_queries.cpp).
void parseStructureQueries(YamlReader& r, const YAML::Node& n, AsBuild& build);
// scene.build.order, once scene.update and scene.build.copy are known.
void parseBuildOrder(YamlReader& r, const YAML::Node& n, Scene& scene);
// One instance of scene.instances (its blas named among scene.blases).
void parseInstance(YamlReader& r, const YAML::Node& n, const std::string& field, const Scene& scene,
                   Instance& inst);
// scene.split (parse_split.cpp), once the rays are aimed: a mesh's
// triangles each in a geometry or an instance of its own (case/split_mesh.h).
void parseSceneSplit(YamlReader& r, const YAML::Node& n, Scene& scene);
// The scene first: the `aim` form aims at one of its meshes.
void parseRays(YamlReader& r, const YAML::Node& n, const Scene& scene, Rays& rays);
void parsePipeline(YamlReader& r, const YAML::Node& n, Pipeline& pipeline);
// pipeline.libraries (parse_libraries.cpp), after the groups are parsed.
void parseLibraries(YamlReader& r, const YAML::Node& n, Pipeline& pipeline);
// pipeline.payloads (parse_payloads.cpp), before the shaders that name a location.
void parsePayloadTypes(YamlReader& r, const YAML::Node& n, Pipeline& pipeline);
// A location of pipeline.payloads (a constant); nullopt, with an error, when none.
std::optional<uint32_t> parsePayloadLocation(YamlReader& r, const YAML::Node& n,
                                             const std::string& field, const Pipeline& pipeline);
// pipeline.miss: programs, or {program, payload: location}.
void parseMissShaders(YamlReader& r, const YAML::Node& n, Pipeline& pipeline);
// Types by location with `words` more uint words: pipeline.payloads and
// pipeline.callable_data.
struct WordTypes {
  const char* field;  // "pipeline.payloads"
  const char* what;   // "payload"
  uint32_t max_locations, max_words;
};
// Each location's words into `out`, its sized members (`sized: [int8,
// f16vec4]`, program/payload_words.h) into `sized`.
void parseWordTypes(YamlReader& r, const YAML::Node& n, const WordTypes& types,
                    std::vector<uint32_t>& out, std::vector<SizedMembers>& sized);
// A list of sized types, each once (an error at the entry otherwise).
std::optional<SizedMembers> parseSizedMembers(YamlReader& r, const YAML::Node& n,
                                              const std::string& field);
// A location among `declared` (a constant); nullopt, with an error, when none.
std::optional<uint32_t> parseWordLocation(YamlReader& r, const YAML::Node& n,
                                          const std::string& field, const WordTypes& types,
                                          size_t declared);
// pipeline.sbt.record_layout (parse_record_layout.cpp), after record_data.
void parseRecordLayout(YamlReader& r, const YAML::Node& n, Pipeline& pipeline);
// pipeline.callable_data (parse_call_data.cpp), before the callables; then
// pipeline.callables: programs, or {program, call_data: location}.
void parseCallDataTypes(YamlReader& r, const YAML::Node& n, Pipeline& pipeline);
void parseCallables(YamlReader& r, const YAML::Node& n, Pipeline& pipeline);
void parseOutputs(YamlReader& r, const YAML::Node& n, Outputs& outputs);

// A generated mesh (`grid`, `fan` or `triangulation` in a `triangles` map):
// nullopt when n names none, else whether it parsed (then g holds the mesh).
// `aabbs: {grid: {cells, size, center, height}}` (case/box_grid.h).
bool parseBoxGrid(YamlReader& r, const YAML::Node& n, const std::string& field, Geometry& g);
// A `scene.instances` entry `{grid: {cells, spacing, origin, instance}}`
// (case/box_grid.h): its instances appended to scene.instances.
void parseInstanceGrid(YamlReader& r, const YAML::Node& n, const std::string& field, Scene& scene);
std::optional<bool> parseGeneratedMesh(YamlReader& r, const YAML::Node& n, const std::string& field,
                                       Geometry& g);

// A yes/no field: true or false (an error naming the field otherwise).
std::optional<bool> parseTrueFalse(YamlReader& r, const YAML::Node& n, const std::string& field);

// identity | 12 numbers | {translate, scale, rotate: {axis, degrees}}
std::optional<Transform> parseTransform(YamlReader& r, const YAML::Node& n,
                                        const std::string& field);

// {uints: [..]} | {floats: [..]}, at most 8 words.
std::optional<std::vector<uint32_t>> parseRecordData(YamlReader& r, const YAML::Node& n,
                                                     const std::string& field);

// A stage program (a list of statements); false when something failed.
bool parseProgram(YamlReader& r, const YAML::Node& n, const std::string& field, Program& out);
// pipeline.functions, and the body of every `invoke` copied into its call site
// (parse_functions.cpp); an invoke of no such function is an error at its line.
void expandFunctions(YamlReader& r, const YAML::Node& functions, Pipeline& p);
// pipeline.constants and pipeline.specialize (parse_constants.cpp); the
// latter names shaders, so it is read after the programs.
void parseConstants(YamlReader& r, const YAML::Node& n, Pipeline& p);
void parseSpecialize(YamlReader& r, const YAML::Node& n, Pipeline& p);
// Hit attribute words (check_attribute_words.cpp): a report's word<i> and an
// attribute.word<i> read within pipeline.hit_attribute.words, and read only
// in a hit group with an intersection shader (a triangle's attribute is its
// barycentrics).
void checkAttributeWords(YamlReader& r, const Pipeline& p);
bool parseExpr(YamlReader& r, const YAML::Node& n, const std::string& field, Expr& out);

// Checks every program of the pipeline for its stage (program/ops.h checkProgram).
void checkPrograms(YamlReader& r, Case& c, const YAML::Node& pipeline_node);

// Errors for shader record reads (shader_record_uint / _float, the lights)
// past the record's data bytes (pipeline.sbt.record_data).
void checkRecordReads(YamlReader& r, const Case& c);
// record_hit: a vec2 hit attribute and one top level (check_record_hit.cpp).
void checkRecordHits(YamlReader& r, const Case& c);

// Notes the undefined behaviour (R-UB) of traces and calls whose values are
// constants: SBT indices beyond their regions, a trace's bad tmin / tmax.
// Needs the types checkPrograms fills in.
void checkTraceConstants(YamlReader& r, const Case& c);

// Every payload location a trace names and callable data location a call
// names, and every word a program reads or writes, within the type it has
// (pipeline.payloads, pipeline.callable_data; check_data_words.cpp).
void checkDataWords(YamlReader& r, const Case& c);
// A rays.same launch above kMaxTracedLaunchIds ids: no program may read
// gl_LaunchIDEXT (launch_id_x, _y, _z), so that the model may trace one id
// for all (model/uniform_launch.h); an error at rays.launch otherwise.
void checkWideLaunch(YamlReader& r, const Case& c);

// pipeline.layout: empty with what needs set 0 itself: an image (a storage
// image has no address), several top levels, pipeline libraries or
// pipeline.tlas_function: an error at pipeline.layout each
// (check_empty_layout.cpp; the ray query forms refuse it themselves).
void checkEmptyLayout(YamlReader& r, const Case& c, const YAML::Node& pipeline);

// Parts of the stage programs' statements (parse_program.cpp), shared with
// the hit-object statements (parse_hit_objects.cpp).
// A payload's fields: color, value and the words of its type, into s.assigns.
bool parsePayloadAssigns(YamlReader& r, const YAML::Node& n, const std::string& field, Stmt& s);
// A trace's constant index `key` (tlas, location) up to max, and where it is
// written; false when it is there but not such a number.
bool constantIndex(YamlReader& r, const YAML::Node& v, const std::string& f, const char* key,
                   uint32_t max, uint32_t& out, SourceLoc& loc);
// The trace fields a trace or ray_query gives (origin .. miss), each an expression.
bool parseTraceSlots(YamlReader& r, const YAML::Node& v, const std::string& f, TraceArgs& t);
// The hit-object statements (parse_hit_objects.cpp): execute, record_miss,
// record_hit and reorder, each from its map.
bool parseExecute(YamlReader& r, const YAML::Node& v, const std::string& f, Stmt& s);
bool parseRecordMiss(YamlReader& r, const YAML::Node& v, const std::string& f, Stmt& s);
bool parseRecordHit(YamlReader& r, const YAML::Node& v, const std::string& f, Stmt& s);
bool parseReorder(YamlReader& r, const YAML::Node& v, const std::string& f, Stmt& s);

}  // namespace rayspec
