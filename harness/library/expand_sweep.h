// A sweep file (cases/<family>/<stem>.sweep.yaml) is a case file with a
// `sweep:` block that names parameters; every combination of their values is
// one case, named <family>/<stem>/<variant>. Each `${parameter}` in the rest
// of the file is replaced by the value's YAML text (a list or map in flow
// style, a scalar as written); values may hold ${...} too, and names nest
// (${prog_${stage}}), innermost first. The sweep block is blanked, not removed, so a
// variant's lines are the file's lines and every error names the sweep file.
//
//   sweep:
//     name: "offset-${offset}-stride-${stride}"   # each variant's name (required)
//     rows:                                     # optional: values bound together
//       - {geometry: triangles, shape: "{triangles: {vertices: [...]}}"}
//     product:                                  # every combination, last key fastest
//       offset: [0, 1, 0x11]
//       stride: [1, 0x12]
//
// Variants: each row (or one empty row) times every product combination.
#pragma once

#include <set>
#include <string>
#include <vector>

#include "parse/parse_case.h"

namespace rayspec {

struct SweepVariant {
  std::string name;  // <family>/<stem>/<variant>
  std::string text;  // the case file's text with the parameters substituted
  std::vector<std::pair<std::string, std::string>>
      params;  // each parameter's value text, rows' first
};

struct SweepExpansion {
  std::vector<SweepVariant> variants;
  std::vector<Error> errors;   // problems of the sweep block or of a ${...}; then no variants
  std::set<std::string> used;  // the parameters some variant brings in
};

bool isSweepFile(const std::string& path);  // the name ends in .sweep.yaml

// text: the file's contents; file: its path (for messages); name: the sweep's
// case name (<family>/<stem>, without .sweep).
SweepExpansion expandSweep(const std::string& text, const std::string& file,
                           const std::string& name);

}  // namespace rayspec
