// cases/README.md names exactly the built-ins that have a record field of
// their own (recordFields(): neither free nor automatic); every other
// built-in is recorded through a free field (issue 62).
#include <gtest/gtest.h>

#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include "results/record_layout.h"

namespace rayspec {
namespace {

// The README's list: the text between its lead-in and the table's path,
// the comment marks and spaces taken out, split at commas.
std::set<std::string> readmeBuiltinFields() {
  std::ifstream in(RAYSPEC_SOURCE_DIR "/cases/README.md");
  std::stringstream whole;
  whole << in.rdbuf();
  const std::string text = whole.str();
  const std::string lead = "built-ins with a field of their own:";
  const size_t from = text.find(lead);
  const size_t to = text.find("(harness/results/record_field_table.h)", from);
  EXPECT_NE(from, std::string::npos);
  EXPECT_NE(to, std::string::npos);
  if (from == std::string::npos || to == std::string::npos) return {};
  std::set<std::string> names;
  std::string name;
  for (char ch : text.substr(from + lead.size(), to - from - lead.size())) {
    if (ch == ',') {
      names.insert(name);
      name.clear();
    } else if (ch != '#' && ch != ' ' && ch != '\n') {
      name += ch;
    }
  }
  names.insert(name);
  return names;
}

TEST(RecordFieldsReadme, ListsExactlyTheBuiltinsWithAFieldOfTheirOwn) {
  std::set<std::string> table;
  for (const RecordField& f : recordFields())
    if (!f.automatic && !isFreeField(f.name)) table.insert(f.name);
  EXPECT_EQ(readmeBuiltinFields(), table);
}

}  // namespace
}  // namespace rayspec
