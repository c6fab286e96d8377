#include "bundle/results_io.h"

#include <algorithm>
#include <bit>
#include <charconv>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>

#include <nlohmann/json.hpp>

#include "base/visible_text.h"
#include "base/whole_file.h"
#include "bundle/image_files.h"
#include "bundle/step_cost_json.h"
#include "results/content_hash.h"
#include "results/file_name.h"
#include "results/record_layout.h"

namespace rayspec {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

template <typename Words>  // std::vector<uint32_t> or BulkWords
Result<void> writeWords(const fs::path& path, const Words& words) {
  return writeWholeFile(path.string(), words.data(), words.size() * 4);
}

// Reads path as whole words after checking that it holds `expected` words
// (or none, when empty_ok); the error names the file, its size and the size
// results.json implies.
Result<void> readSizedWords(const fs::path& path, uint64_t expected, bool empty_ok,
                            const std::string& implied, BulkWords& words) {
  std::error_code ec;
  if (expected > std::numeric_limits<uint64_t>::max() / 4)
    return errorMessage("results.json says " + implied + ": more words than a file can hold");
  if (!fs::is_regular_file(fs::symlink_status(path, ec)))
    return errorMessage("cannot read " + path.string() + ": not a regular file");
  const uint64_t bytes = fs::file_size(path, ec);
  if (ec) return errorMessage("cannot read " + path.string());
  if (bytes != expected * 4 && !(empty_ok && bytes == 0))
    return errorMessage(path.string() + " holds " + std::to_string(bytes) +
                        " bytes; results.json says " + implied + " = " + std::to_string(expected) +
                        " words (" + std::to_string(expected * 4) + " bytes)");
  std::ifstream in(path, std::ios::binary);
  words.resize(bytes / 4);
  in.read(reinterpret_cast<char*>(words.data()), static_cast<std::streamsize>(bytes));
  if (!in) return errorMessage("cannot read " + path.string());
  return {};
}

// An error about a value in dir/results.json: "DIR/results.json: MESSAGE".
Error badValue(const fs::path& dir, const std::string& message) {
  return errorMessage((dir / "results.json").string() + ": " + message);
}

// A count from results.json that sizes a file: at most 2^30 (a 4 GiB file).
constexpr uint64_t kMaxSize = 1u << 30;

// An unsigned integer of results.json (a counter, a size, a ray, an id) of
// at most `max`; the error names the field where it is anything else: 64.9,
// -1, 1e3 and 2^64 are none (nlohmann-json would read them as 64, 2^64 - 1,
// 1000 and 0).
template <typename T>
Result<T> unsignedValue(const fs::path& dir, const json& value, const std::string& key,
                        uint64_t max = std::numeric_limits<T>::max()) {
  if (!value.is_number_unsigned())
    return badValue(dir, key + ": " + visibleText(value.dump(), 40) + " is no unsigned integer");
  const uint64_t v = value.get<uint64_t>();
  if (v > max)
    return badValue(dir, key + ": " + std::to_string(v) + " is too large (at most " +
                             std::to_string(max) + ")");
  return static_cast<T>(v);
}

// One field's words as text, %.9g for floats ("1.5", "0.25 0.5"), appended.
void appendField(std::string& out, const RecordField& f, const uint32_t* rec) {
  char buf[32];
  for (uint32_t i = 0; i < f.words; ++i) {
    if (i) out += ' ';
    const uint32_t w = rec[f.offset + i];
    const std::to_chars_result end =
        f.type == FieldType::Float ? std::to_chars(buf, buf + sizeof buf, std::bit_cast<float>(w),
                                                   std::chars_format::general, 9)
                                   : std::to_chars(buf, buf + sizeof buf, w);
    out.append(buf, end.ptr);
  }
}

// A recordable field is shown only where the ray wrote it.
bool fieldWritten(const RecordField& f, int index, const uint32_t* rec) {
  return f.automatic || written(rec, index);
}

}  // namespace

Result<void> writeRecordsCsv(const Results& r, const std::string& path,
                             const std::vector<std::string>& kept) {
  struct Column {
    const RecordField* field;
    int index;
  };
  std::vector<Column> columns;
  for (const auto& name : kept)
    if (const RecordField* f = findRecordField(name))
      columns.push_back({f, recordFieldIndex(name)});
  for (const RecordField& f : recordFields())
    if (f.automatic) columns.push_back({&f, -1});
  std::ofstream out(path, std::ios::binary);
  std::string text = "x,y";
  for (const Column& c : columns) text += std::string(",") + c.field->name;
  text += '\n';
  const uint32_t words = recordWords();
  const size_t rays = r.records.size() / words;
  char buf[24];
  for (size_t i = 0; i < rays; ++i) {
    const uint32_t* rec = &r.records[i * words];
    text.append(buf, std::to_chars(buf, buf + sizeof buf, r.width ? i % r.width : i).ptr);
    text += ',';
    text.append(buf, std::to_chars(buf, buf + sizeof buf, r.width ? i / r.width : 0).ptr);
    for (const Column& c : columns) {
      text += ',';
      if (fieldWritten(*c.field, c.index, rec)) appendField(text, *c.field, rec);
    }
    text += '\n';
    if (text.size() > (1u << 20)) {
      out.write(text.data(), static_cast<std::streamsize>(text.size()));
      text.clear();
    }
  }
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
  out.close();  // the last of it reaches the file here (or fails to, on a full disk)
  if (!out) return errorMessage("cannot write " + path);
  return {};
}

namespace {

json candidatesJson(const std::vector<Candidate>& candidates) {
  json out = json::array();
  for (const Candidate& c : candidates) {
    json j = {{"hit", c.hit},
              {"instance", c.instance},
              {"geometry", c.geometry},
              {"primitive", c.primitive}};
    if (std::isfinite(c.t)) j["t"] = c.t;
    out.push_back(std::move(j));
  }
  return out;
}

// An ambiguous ray's replays (RayAmbiguity::replays) in results.json: each
// one's counter moves; their records go to replays.bin (writeReplayRecords).
json replaysJson(const std::vector<LegalReplay>& replays) {
  json out = json::array();
  for (const LegalReplay& r : replays) out.push_back({{"counter_moves", r.counter_moves}});
  return out;
}

// The records of every ambiguous ray's replays, then its leak replays and
// double-hit replays, ray after ray, into replays.bin (none where the case
// keeps no records).
Result<void> writeReplayRecords(const Results& r, const fs::path& dir) {
  std::vector<uint32_t> words;
  for (const RayAmbiguity& a : r.ambiguous)
    for (const auto* list : {&a.replays, &a.leak_replays, &a.double_replays})
      for (const LegalReplay& k : *list)
        words.insert(words.end(), k.record.begin(), k.record.end());
  return writeWords(dir / "replays.bin", words);
}

// The rays the model found ambiguous, bounded, undefined or dependent on
// any-hit repetition, into results.json (readRayNotes reads them back).
void writeRayNotes(const Results& r, json& j) {
  j["ambiguous"] = json::array();
  for (const RayAmbiguity& a : r.ambiguous)
    j["ambiguous"].push_back({{"ray", a.ray},
                              {"reason", ambiguityReasonName(a.reason)},
                              {"candidates", candidatesJson(a.candidates)},
                              {"shared_triangles", candidatesJson(a.shared_triangles)},
                              {"leak_answers", candidatesJson(a.leak_answers)},
                              {"replays", replaysJson(a.replays)},
                              {"leak_replays", replaysJson(a.leak_replays)},
                              {"double_replays", replaysJson(a.double_replays)}});
  for (size_t k = 0; k < r.ambiguous.size(); ++k)  // written only where not 1
    if (r.ambiguous[k].traces != 1) j["ambiguous"][k]["traces"] = r.ambiguous[k].traces;
  for (size_t k = 0; k < r.ambiguous.size(); ++k)  // written only where a ray query's
    if (r.ambiguous[k].from_query) j["ambiguous"][k]["from"] = "ray_query";
  j["t_bounds"] = json::array();
  for (const TBound& b : r.t_bounds) j["t_bounds"].push_back({{"ray", b.ray}, {"bound", b.bound}});
  j["object_origin_bounds"] = json::array();
  for (const TBound& b : r.object_origin_bounds)
    j["object_origin_bounds"].push_back({{"ray", b.ray}, {"bound", b.bound}});
  j["position_bounds"] = json::array();
  for (const TBound& b : r.position_bounds)
    j["position_bounds"].push_back({{"ray", b.ray}, {"bound", b.bound}});
  j["undefined"] = json::array();
  for (const UndefinedRay& u : r.undefined)
    j["undefined"].push_back(
        {{"ray", u.ray}, {"reason", undefinedReasonName(u.reason)}, {"what", u.what}});
  j["repeat_dependent"] = json::array();
  for (const RepeatDependentRay& d : r.repeat_dependent) {
    json names = json::array();
    for (const RecordField& f : recordFields())
      if (d.fields & fieldBit(f.index)) names.push_back(f.name);
    j["repeat_dependent"].push_back({{"ray", d.ray}, {"fields", names}});
  }
  j["repeat_counters"] = r.repeat_counters;
  if (!r.order_dependent.empty()) j["order_dependent"] = r.order_dependent;
  if (!r.endless_restarts.empty()) j["endless_restarts"] = r.endless_restarts;
  if (!r.counter_floors.empty()) j["counter_floors"] = r.counter_floors;
}

}  // namespace

Result<void> writeResults(const Results& r, const std::string& dir_name,
                          const std::vector<std::string>& kept_fields) {
  return writeResults(r, dir_name, kept_fields, BundleFiles{});
}

Result<void> writeResults(const Results& r, const std::string& dir_name,
                          const std::vector<std::string>& kept_fields, const BundleFiles& files) {
  const auto start = std::chrono::steady_clock::now();
  const fs::path dir(dir_name);
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) return errorMessage("cannot create " + dir.string() + ": " + ec.message());

  json j;
  j["case"] = r.case_name;
  j["backend"] = r.backend;
  j["device"] = r.device;
  if (!r.driver.empty()) j["driver"] = r.driver;
  j["status"] = sideStatusName(r.status);
  j["status_detail"] = r.status_detail;
  j["case_file"] = r.case_file;
  j["case_hash"] = contentHashText(r.case_hash);
  j["width"] = r.width;
  j["height"] = r.height;
  j["seconds"] = r.seconds;
  j["record_words"] = recordWords();
  j["counters"] = r.counters;
  j["validation_messages"] = r.validation_messages;
  j["device_findings"] = json::array();
  for (const DeviceFinding& f : r.device_findings)
    j["device_findings"].push_back({{"rule", f.rule}, {"message", f.message}});
  j["rejected"] = r.rejected;
  j["library_handles_compared"] = r.library_handles_compared;
  j["images"] = json::array();
  for (const Image& im : r.images) {
    j["images"].push_back({{"name", im.name},
                           {"field", im.field},
                           {"width", im.width},
                           {"height", im.height},
                           {"channels", im.channels},
                           {"float", im.is_float}});
    RAYSPEC_TRY_VOID(writeWords(dir / (im.name + ".raw"), im.texels));
    if (files.image_files) RAYSPEC_TRY_VOID(writeImageFiles(im, dir.string()));
  }
  writeRayNotes(r, j);
  RAYSPEC_TRY_VOID(writeWords(dir / "records.bin", r.records));
  RAYSPEC_TRY_VOID(writeReplayRecords(r, dir));
  if (files.records_csv)
    RAYSPEC_TRY_VOID(writeRecordsCsv(r, (dir / "records.csv").string(), kept_fields));
  // results.json last, with the time of writing the rest of the bundle.
  StepCosts cost = r.cost;
  cost.add(CostStep::WriteBundle,
           std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  j["cost"] = costJson(cost);
  return writeWholeFile((dir / "results.json").string(), j.dump(1) + '\n');
}

namespace {

// Reads the fields of results.json by dotted path, remembering the last one
// for the message when its value has the wrong type (nlohmann-json throws
// then: readResultsJson catches it).
struct FieldReader {
  fs::path dir;  // the bundle's
  std::string where;
  const json& operator()(const json& object, const std::string& path) {
    where = path;
    return object.at(path.substr(path.rfind('.') + 1));
  }
  // The field as an unsigned integer (unsignedValue).
  template <typename T>
  Result<T> count(const json& object, const std::string& path,
                  uint64_t max = std::numeric_limits<T>::max()) {
    return unsignedValue<T>(dir, (*this)(object, path), path, max);
  }
};

// The counters, each an unsigned integer (counters.NAME in the error).
Result<void> readCounters(const json& j, FieldReader& field, Results& r) {
  const json& counters = field(j, "counters");
  if (!counters.is_object()) return badValue(field.dir, "counters: not an object");
  for (const auto& [name, value] : counters.items()) {
    RAYSPEC_TRY(r.counters[name],
                unsignedValue<uint64_t>(field.dir, value, "counters." + visibleText(name, 80)));
  }
  return {};
}

// The bundle's own fields: case, backend, device, status, size, costs,
// counters and validation messages; or the error of a bad value.
Result<void> readHeader(const json& j, FieldReader& field, Results& r) {
  r.case_name = field(j, "case");
  if (const std::string problem = caseNameProblem(r.case_name); !problem.empty())
    return badValue(field.dir,
                    "case: '" + r.case_name.substr(0, 120) + "' is no case name: " + problem);
  r.backend = field(j, "backend");
  r.device = field(j, "device");
  if (j.contains("driver") && j.at("driver").is_string())
    r.driver = j.at("driver").get<std::string>();
  if (!parseSideStatus(field(j, "status").get<std::string>(), &r.status))
    return badValue(field.dir,
                    "status: unknown value '" + field(j, "status").get<std::string>() + "'");
  r.status_detail = j.value("status_detail", std::string());
  RAYSPEC_TRY(r.width, field.count<uint32_t>(j, "width", kMaxSize));
  RAYSPEC_TRY(r.height, field.count<uint32_t>(j, "height", kMaxSize));
  r.seconds = field(j, "seconds");
  if (j.contains("cost")) {
    const Result<StepCosts> cost = costFromJson(field(j, "cost"));
    if (!cost) return badValue(field.dir, cost.error().message);
    r.cost = *cost;
  }
  r.case_file = j.value("case_file", std::string());
  if (j.contains("case_hash")) {
    const std::string hash = field(j, "case_hash").get<std::string>();
    const std::optional<uint64_t> parsed = contentHashFromText(hash);
    if (!parsed)
      return badValue(field.dir, "case_hash: '" + visibleText(hash, 40) +
                                     "' is no case hash (16 lower-case hex digits)");
    r.case_hash = *parsed;
  }
  RAYSPEC_TRY_VOID(readCounters(j, field, r));
  r.validation_messages = field(j, "validation_messages").get<std::vector<std::string>>();
  if (j.contains("device_findings"))  // bundles saved before it was kept have none
    for (const json& f : field(j, "device_findings")) {
      if (f.is_string())  // saved before findings named their rule: all were R-LIBRARY's
        r.device_findings.push_back({"R-LIBRARY", f.get<std::string>()});
      else
        r.device_findings.push_back(
            {f.at("rule").get<std::string>(), f.at("message").get<std::string>()});
    }
  if (j.contains("rejected"))  // nor rejections
    r.rejected = field(j, "rejected").get<std::vector<std::string>>();
  if (j.contains("library_handles_compared")) {
    RAYSPEC_TRY(r.library_handles_compared, field.count<uint32_t>(j, "library_handles_compared"));
  }
  return {};
}

// The images and their NAME.raw texels; or the error of a bad value or of
// the first file that does not read.
Result<void> readImages(const json& j, FieldReader& field, Results& r) {
  const fs::path& dir = field.dir;
  for (const json& ji : field(j, "images")) {
    Image im;
    im.name = field(ji, "images.name");
    if (const std::string problem = fileNameProblem(im.name); !problem.empty())
      return badValue(dir, "images: name '" + im.name.substr(0, 120) + "' " + problem);
    im.field = field(ji, "images.field");
    RAYSPEC_TRY(im.width, field.count<uint32_t>(ji, "images.width", kMaxSize));
    RAYSPEC_TRY(im.height, field.count<uint32_t>(ji, "images.height", kMaxSize));
    RAYSPEC_TRY(im.channels, field.count<uint32_t>(ji, "images.channels", kMaxSize));
    im.is_float = field(ji, "images.float");
    const std::string implied = "image " + im.name + ": width x height x channels " +
                                std::to_string(im.width) + " x " + std::to_string(im.height) +
                                " x " + std::to_string(im.channels);
    if (im.channels < 1 || im.channels > 4)
      return badValue(dir, "images.channels: " + std::to_string(im.channels) +
                               " (an image has 1 to 4 channels)");
    // Each factor is at most 2^30 (kMaxSize): the product fits 64 bits only
    // with 4 channels at most and is checked before it is used.
    const uint64_t texels = uint64_t(im.width) * im.height;
    if (im.width && texels / im.width != im.height)
      return badValue(dir, "images: width x height overflows");
    const uint64_t words = texels * im.channels;
    RAYSPEC_TRY_VOID(readSizedWords(dir / (im.name + ".raw"), words, false, implied, im.texels));
    r.images.push_back(std::move(im));
  }
  return {};
}

// One list of an ambiguous ray's answers (ambiguous.<key>); absent and not
// `required` (older bundles): none. A hit's t where written.
Result<std::vector<Candidate>> readCandidates(FieldReader& field, const json& ja,
                                              const std::string& key, bool required) {
  std::vector<Candidate> out;
  if (!required && !ja.contains(key)) return out;
  const std::string path = "ambiguous." + key;
  for (const json& jc : field(ja, path)) {
    Candidate k;
    k.hit = jc.contains("hit") || required ? field(jc, path + ".hit").get<bool>() : true;
    RAYSPEC_TRY(k.instance, field.count<uint32_t>(jc, path + ".instance"));
    RAYSPEC_TRY(k.geometry, field.count<uint32_t>(jc, path + ".geometry"));
    RAYSPEC_TRY(k.primitive, field.count<uint32_t>(jc, path + ".primitive"));
    if (jc.contains("t")) k.t = field(jc, path + ".t");
    out.push_back(k);
  }
  return out;
}

// An ambiguous ray's replays, leak or double-hit replays (ambiguous.replays,
// ambiguous.leak_replays, ambiguous.double_replays: `key`; absent in older
// bundles: none), each one's
// counter moves: a counter of the bundle's, by a signed 64-bit integer.
// Their records come from replays.bin (readReplayRecords).
Result<std::vector<LegalReplay>> readReplays(FieldReader& field, const json& ja, const Results& r,
                                             const std::string& key) {
  std::vector<LegalReplay> out;
  if (!ja.contains(key)) return out;
  const std::string at = "ambiguous." + key + ".counter_moves";
  for (const json& jr : field(ja, "ambiguous." + key)) {
    LegalReplay k;
    const json& moves = field(jr, at);
    if (!moves.is_object()) return badValue(field.dir, at + ": not an object");
    for (const auto& [name, value] : moves.items()) {
      const std::string where = at + "." + visibleText(name, 80);
      if (!r.counters.count(name)) return badValue(field.dir, where + ": no such counter");
      if (!value.is_number_integer() ||
          (value.is_number_unsigned() &&
           value.get<uint64_t>() > uint64_t{std::numeric_limits<int64_t>::max()}))
        return badValue(field.dir, where + ": not a signed 64-bit integer");
      k.counter_moves[name] = value.get<int64_t>();
    }
    out.push_back(std::move(k));
  }
  return out;
}

// t_bounds, object_origin_bounds or position_bounds (absent in older
// bundles: none).
Result<void> readBounds(const json& j, FieldReader& field, const std::string& key,
                        std::vector<TBound>& out) {
  if (!j.contains(key)) return {};
  for (const json& jb : field(j, key)) {
    TBound b;
    RAYSPEC_TRY(b.ray, field.count<uint32_t>(jb, key + ".ray"));
    b.bound = field(jb, key + ".bound");
    out.push_back(b);
  }
  return {};
}

// The rays the model bounded, found undefined, or found ambiguous; or the
// error of a bad value.
Result<void> readRayNotes(const json& j, FieldReader& field, Results& r) {
  RAYSPEC_TRY_VOID(readBounds(j, field, "t_bounds", r.t_bounds));
  RAYSPEC_TRY_VOID(readBounds(j, field, "object_origin_bounds", r.object_origin_bounds));
  RAYSPEC_TRY_VOID(readBounds(j, field, "position_bounds", r.position_bounds));
  if (j.contains("undefined"))
    for (const json& ju : field(j, "undefined")) {
      UndefinedRay u;
      RAYSPEC_TRY(u.ray, field.count<uint32_t>(ju, "undefined.ray"));
      if (!parseUndefinedReason(field(ju, "undefined.reason").get<std::string>(), &u.reason))
        return badValue(field.dir, "undefined.reason: unknown value '" +
                                       field(ju, "undefined.reason").get<std::string>() + "'");
      u.what = field(ju, "undefined.what");
      r.undefined.push_back(std::move(u));
    }
  if (j.contains("repeat_dependent"))
    for (const json& jd : field(j, "repeat_dependent")) {
      RepeatDependentRay d;
      RAYSPEC_TRY(d.ray, field.count<uint32_t>(jd, "repeat_dependent.ray"));
      if (uint64_t{d.ray} >= uint64_t{r.width} * r.height)
        return badValue(
            field.dir, "repeat_dependent.ray: " + std::to_string(d.ray) + " is outside the launch");
      for (const json& jn : field(jd, "repeat_dependent.fields")) {
        const int index = recordFieldIndex(jn.get<std::string>());
        if (index < 0)
          return badValue(field.dir,
                          "repeat_dependent.fields: unknown field '" + jn.get<std::string>() + "'");
        d.fields |= fieldBit(index);
      }
      r.repeat_dependent.push_back(d);
    }
  if (j.contains("repeat_counters"))
    r.repeat_counters = field(j, "repeat_counters").get<std::vector<std::string>>();
  if (j.contains("counter_floors"))
    r.counter_floors = field(j, "counter_floors").get<std::map<std::string, uint64_t>>();
  if (j.contains("order_dependent"))
    r.order_dependent = field(j, "order_dependent").get<std::vector<std::string>>();
  if (j.contains("endless_restarts"))
    r.endless_restarts = field(j, "endless_restarts").get<std::vector<std::string>>();
  for (const json& ja : field(j, "ambiguous")) {
    RayAmbiguity a;
    RAYSPEC_TRY(a.ray, field.count<uint32_t>(ja, "ambiguous.ray"));
    if (!parseAmbiguityReason(field(ja, "ambiguous.reason").get<std::string>(), &a.reason))
      return badValue(field.dir, "ambiguous.reason: unknown value '" +
                                     field(ja, "ambiguous.reason").get<std::string>() + "'");
    RAYSPEC_TRY(a.candidates, readCandidates(field, ja, "candidates", true));
    RAYSPEC_TRY(a.shared_triangles, readCandidates(field, ja, "shared_triangles", false));
    RAYSPEC_TRY(a.leak_answers, readCandidates(field, ja, "leak_answers", false));
    RAYSPEC_TRY(a.replays, readReplays(field, ja, r, "replays"));
    RAYSPEC_TRY(a.leak_replays, readReplays(field, ja, r, "leak_replays"));
    RAYSPEC_TRY(a.double_replays, readReplays(field, ja, r, "double_replays"));
    if (ja.contains("traces")) {  // absent: 1
      RAYSPEC_TRY(a.traces, field.count<uint32_t>(ja, "ambiguous.traces"));
    }
    if (ja.contains("from")) {  // absent: a trace's
      const std::string from = field(ja, "ambiguous.from").get<std::string>();
      if (from != "ray_query")
        return badValue(field.dir, "ambiguous.from: unknown value '" + from + "'");
      a.from_query = true;
    }
    r.ambiguous.push_back(std::move(a));
  }
  return {};
}

// results.json into r; or the error, naming the file and field.
Result<void> readResultsJsonFields(const std::string& text, FieldReader& field, Results& r) {
  const json j = json::parse(text);
  RAYSPEC_TRY_VOID(readHeader(j, field, r));
  RAYSPEC_TRY(const uint32_t record_words, field.count<uint32_t>(j, "record_words"));
  if (record_words != recordWords())
    return errorMessage(field.dir.string() + ": record layout differs from this build");
  RAYSPEC_TRY_VOID(readImages(j, field, r));
  return readRayNotes(j, field, r);
}

// readResultsJsonFields, with what nlohmann-json throws (a value of the
// wrong type, a missing field, text that is no JSON) made an Error.
Result<void> readResultsJson(const std::string& text, const fs::path& dir, Results& r) {
  FieldReader field{dir, {}};
  try {
    return readResultsJsonFields(text, field, r);
  } catch (const nlohmann::json::exception& e) {
    return errorMessage((dir / "results.json").string() +
                        (field.where.empty() ? "" : ": field '" + field.where + "'") + ": " +
                        e.what());
  } catch (const std::exception& e) {
    return badValue(dir, e.what());
  }
}

// The records of the replays, leak and double-hit replays results.json lists, from
// replays.bin: one each where the bundle has records, none where it has not.
Result<void> readReplayRecords(const fs::path& dir, Results& r) {
  uint64_t replays = 0;
  for (const RayAmbiguity& a : r.ambiguous)
    replays += a.replays.size() + a.leak_replays.size() + a.double_replays.size();
  const uint64_t words = r.records.empty() ? 0 : replays * recordWords();
  if (words == 0) return {};
  BulkWords all;
  RAYSPEC_TRY_VOID(readSizedWords(
      dir / "replays.bin", words, false,
      "replays x record words " + std::to_string(replays) + " x " + std::to_string(recordWords()),
      all));
  const uint32_t* w = all.data();
  for (RayAmbiguity& a : r.ambiguous)
    for (auto* list : {&a.replays, &a.leak_replays, &a.double_replays})
      for (LegalReplay& k : *list) {
        k.record.assign(w, w + recordWords());
        w += recordWords();
      }
  return {};
}

}  // namespace

Result<Results> readResults(const std::string& dir_name) {
  Results r;
  const fs::path dir(dir_name);
  std::error_code ec;
  if (!fs::exists(dir / "results.json", ec))
    return errorMessage("no results.json in " + dir.string());
  const Result<std::string> text =
      readWholeFile((dir / "results.json").string(), kMaxResultsJsonBytes);
  if (!text) return inOneMessage(text.error());
  RAYSPEC_TRY_VOID(readResultsJson(*text, dir, r));
  // No records at all when the case records nothing per ray (or its side died).
  const std::string implied = "width x height x record words " + std::to_string(r.width) + " x " +
                              std::to_string(r.height) + " x " + std::to_string(recordWords());
  RAYSPEC_TRY_VOID(readSizedWords(dir / "records.bin", uint64_t(r.width) * r.height * recordWords(),
                                  true, implied, r.records));
  RAYSPEC_TRY_VOID(readReplayRecords(dir, r));
  return r;
}

std::string formatField(const std::string& name, const uint32_t* rec) {
  const RecordField* f = findRecordField(name);
  std::string text;
  if (f && fieldWritten(*f, recordFieldIndex(name), rec)) appendField(text, *f, rec);
  return text;
}

std::vector<uint8_t> previewPixels(const Image& im) {
  std::vector<uint8_t> px(static_cast<size_t>(im.width) * im.height * 4);
  for (size_t i = 0; i < static_cast<size_t>(im.width) * im.height; ++i) {
    uint8_t* p = &px[i * 4];
    if (im.is_float) {
      for (uint32_t c = 0; c < 4; ++c) {
        float v = 0.0f;
        if (c < im.channels) v = std::bit_cast<float>(im.texels[i * im.channels + c]);
        if (c == 3 && im.channels < 4) v = 1.0f;
        v = v != v ? 0.0f : std::min(std::max(v, 0.0f), 1.0f);
        p[c] = static_cast<uint8_t>(v * 255.0f + 0.5f);
      }
    } else {
      // Distinct colours for small ids (hash), black for 0.
      const uint32_t v = im.texels[i * im.channels];
      uint32_t h = v * 2654435761u;
      p[0] = v ? static_cast<uint8_t>(64 + (h >> 24) % 192) : 0;
      p[1] = v ? static_cast<uint8_t>(64 + (h >> 16) % 192) : 0;
      p[2] = v ? static_cast<uint8_t>(64 + (h >> 8) % 192) : 0;
      p[3] = 255;
    }
  }
  return px;
}

}  // namespace rayspec
