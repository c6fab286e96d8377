// outputs: counters, per-ray fields, images.
#include <algorithm>
#include <cctype>
#include <map>
#include <optional>

#include "parse/parse_parts.h"
#include "results/file_name.h"
#include "results/record_layout.h"

namespace rayspec {
namespace {

bool isIdentifier(const std::string& s) {
  if (s.empty() || !(std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_')) return false;
  return std::all_of(s.begin(), s.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
  });
}

bool contains(const std::vector<std::string>& v, const std::string& s) {
  return std::find(v.begin(), v.end(), s) != v.end();
}

const char* const kCounterModes[] = {"exact", "at_least", "at_most", "informational"};

// A counter written as {name: mode}: returns the name, records the mode.
std::optional<std::string> counterWithMode(YamlReader& r, const YAML::Node& n, const std::string& f,
                                           Outputs* modes) {
  if (!modes || !n.IsMap()) return r.string(n, f);
  if (n.size() != 1) {
    r.error(n, f, "a counter with a mode is one `name: mode` pair");
    return std::nullopt;
  }
  const auto kv = n.begin();
  const auto key = r.string(kv->first, f);
  if (!key) return std::nullopt;
  const std::string& name = *key;
  auto mode = r.string(kv->second, f + "." + name);
  if (!mode) return std::nullopt;
  if (std::find(std::begin(kCounterModes), std::end(kCounterModes), *mode) ==
      std::end(kCounterModes)) {
    r.error(kv->second, f + "." + name,
            "unknown counter mode '" + *mode + "' (exact, at_least, at_most, informational)");
    return std::nullopt;
  }
  modes->counter_modes[name] = *mode;
  modes->counter_mode_locs[name] = r.loc(kv->second, f + "." + name);
  return name;
}

void parseNames(YamlReader& r, const YAML::Node& n, const std::string& field, bool record_fields,
                std::vector<std::string>& out, Outputs* modes = nullptr) {
  if (!r.expectSeq(n, field)) return;
  for (size_t i = 0; i < n.size(); ++i) {
    const std::string f = field + "[" + std::to_string(i) + "]";
    auto name = counterWithMode(r, n[i], f, modes);
    if (!name) continue;
    if (!isIdentifier(*name)) {
      r.error(n[i], f, "'" + *name + "' is not a valid name");
      continue;
    }
    if (contains(out, *name)) {
      r.error(n[i], f, "'" + *name + "' is declared twice");
      continue;
    }
    if (record_fields) {
      const RecordField* rf = findRecordField(*name);
      if (!rf) {
        std::string list;
        for (const RecordField& x : recordFields())
          if (!x.automatic) list += std::string(list.empty() ? "" : ", ") + x.name;
        r.error(n[i], f, "unknown per-ray field '" + *name + "' (recordable: " + list + ")");
        continue;
      }
      if (rf->automatic) {
        r.error(n[i], f, "per-ray field '" + *name + "' is kept automatically; do not declare it");
        continue;
      }
    }
    out.push_back(*name);
  }
}

}  // namespace

void parseOutputs(YamlReader& r, const YAML::Node& n, Outputs& o) {
  if (!r.expectMap(n, "outputs", {"counters", "per_ray", "images"})) return;
  if (auto v = YamlReader::get(n, "counters"); v.IsDefined())
    parseNames(r, v, "outputs.counters", false, o.counters, &o);
  if (auto v = YamlReader::get(n, "per_ray"); v.IsDefined())
    parseNames(r, v, "outputs.per_ray", true, o.per_ray);
  const YAML::Node images = YamlReader::get(n, "images");
  if (!images.IsDefined() || !r.expectSeq(images, "outputs.images")) return;
  std::vector<std::pair<YAML::Node, std::string>> equal_to;  // checked once every image is known
  for (size_t i = 0; i < images.size(); ++i) {
    const std::string f = "outputs.images[" + std::to_string(i) + "]";
    const YAML::Node img = images[i];
    if (!r.expectMap(img, f, {"name", "from", "tolerance", "max_failing_pixels", "equal_to"}) ||
        !(r.require(img, f, "name") & r.require(img, f, "from")))
      continue;
    ImageOutput out;
    out.loc = r.loc(img, f);
    auto name = r.string(YamlReader::get(img, "name"), f + ".name");
    auto from = r.string(YamlReader::get(img, "from"), f + ".from");
    if (!name || !from) continue;
    // It becomes a file name: NAME.raw, NAME.png, diff/NAME.png.
    if (const std::string problem = fileNameProblem(*name); !problem.empty()) {
      r.error(YamlReader::get(img, "name"), f + ".name", "image name '" + *name + "' " + problem);
      continue;
    }
    for (const ImageOutput& other : o.images)
      if (other.name == *name)
        r.error(YamlReader::get(img, "name"), f + ".name", "duplicate image name");
    if (!contains(o.per_ray, *from)) {
      r.error(YamlReader::get(img, "from"), f + ".from",
              "field '" + *from + "' is not declared in outputs.per_ray");
      continue;
    }
    if (const YAML::Node t = YamlReader::get(img, "tolerance"); t.IsDefined()) {
      const auto scale = r.number(t, f + ".tolerance");
      if (!scale) continue;
      if (!(*scale > 0)) {
        r.error(t, f + ".tolerance", "the tolerance scale must be above 0");
        continue;
      }
      out.tolerance = *scale;
    }
    if (const YAML::Node m = YamlReader::get(img, "max_failing_pixels"); m.IsDefined()) {
      const auto count = r.uint(m, f + ".max_failing_pixels");
      if (!count) continue;
      out.max_failing_pixels = *count;
    }
    if (const YAML::Node e = YamlReader::get(img, "equal_to"); e.IsDefined()) {
      const auto other = r.string(e, f + ".equal_to");
      if (!other) continue;
      out.equal_to = *other;
      equal_to.push_back({e, f + ".equal_to"});
    }
    out.name = *name;
    out.field = *from;
    o.images.push_back(out);
  }
  // equal_to: another image of the case, of the same texel format.
  size_t k = 0;
  for (const ImageOutput& img : o.images) {
    if (img.equal_to.empty()) continue;
    const auto& [node, f] = equal_to[k++];
    const ImageOutput* other = nullptr;
    for (const ImageOutput& x : o.images)
      if (x.name == img.equal_to && x.name != img.name) other = &x;
    if (!other) {
      r.error(node, f, "'" + img.equal_to + "' is not another image of this case");
      continue;
    }
    const RecordField* a = findRecordField(img.field);
    const RecordField* b = findRecordField(other->field);
    if (a && b && a->type != b->type)
      r.error(node, f,
              "image '" + img.name + "' (from " + img.field + ") and '" + other->name + "' (from " +
                  other->field + ") have different texel formats");
  }
}

}  // namespace rayspec
