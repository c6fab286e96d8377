// base/shell_word.h: a word sh reads back as exactly its text, whatever it
// holds; nothing in it runs.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "base/shell_word.h"
#include "test_dir.h"

namespace rayspec {
namespace {

// What /bin/sh makes of `printf %s WORD`, run in dir.
std::string readBySh(const std::string& dir, const std::string& word) {
  const std::string script = dir + "/script.sh", out = dir + "/out.txt";
  std::ofstream(script) << "cd " << shellWord(dir) << " && printf %s " << word << " > "
                        << shellWord(out) << "\n";
  if (std::system(("/bin/sh " + shellWord(script)).c_str()) != 0) return "(sh failed)";
  std::ifstream in(out, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(ShellWord, PlainWordsStayAsTheyAre) {
  EXPECT_EQ(shellWord("build/out-1_a.yaml"), "build/out-1_a.yaml");
  EXPECT_EQ(shellWord(""), "''");
  EXPECT_EQ(shellWord("a b"), "'a b'");
  EXPECT_EQ(shellWord("it's"), "'it'\\''s'");
}

TEST(ShellWord, ShReadsBackTheTextAndRunsNothing) {
  const std::string dir = testing_support::testDir();
  for (const std::string text : {"o'$(touch PWNED)x", "'; touch PWNED; '", "`touch PWNED`",
                                 "$HOME ${X:-y} *", "a\nb", "it's \"quoted\"\\", "-n", "\x1b[2J"}) {
    EXPECT_EQ(readBySh(dir, shellWord(text)), text) << shellWord(text);
    EXPECT_FALSE(std::filesystem::exists(dir + "/PWNED")) << shellWord(text);
  }
}

}  // namespace
}  // namespace rayspec
