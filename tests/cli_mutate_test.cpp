// `rayspec mutate` on a run of case files kept outside the library (issue
// 61): without --cases it finds none of them under cases/ and says so, and
// what to pass; with --cases naming their folder it judges them.
#include <gtest/gtest.h>

#include <string>

#include "cli_helpers.h"

namespace {
using cli::fresh;
using cli::kBin;
using cli::sh;
using cli::slurp;

const std::string kFolder = RAYSPEC_SOURCE_DIR "/tests/data/portable";

TEST(MutateOutside, WithoutCasesItSaysWhyAndWhatToPass) {
  const std::string out = fresh("mutate-outside");
  ASSERT_EQ(sh(kBin + " run --no-validation --case " + kFolder +
                   "/candidates-at-least.yaml --out " + out + "/run",
               out + "/run.txt"),
            0)
      << slurp(out + "/run.txt");
  EXPECT_EQ(sh(kBin + " mutate " + out + "/run --out " + out + "/without", out + "/without.txt"),
            1);
  const std::string without = slurp(out + "/without.txt");
  EXPECT_NE(without.find("rayspec mutate: no case of " + out +
                         "/run could be judged: none of the 1 case(s) " + out +
                         "/run ran (candidates-at-least) is a case file under " RAYSPEC_SOURCE_DIR
                         "/cases, the folder mutate reads the cases from"),
            std::string::npos)
      << without;
  EXPECT_NE(without.find("pass --cases FOLDER, the folder that holds the run's case files"),
            std::string::npos)
      << without;

  EXPECT_EQ(sh(kBin + " mutate " + out + "/run --cases " + kFolder + " --out " + out + "/with",
               out + "/with.txt"),
            0)
      << slurp(out + "/with.txt");
  const std::string with = slurp(out + "/with.txt");
  EXPECT_EQ(with.find("could be judged"), std::string::npos) << with;
  EXPECT_NE(with.find("\n1 of 1 cases judged\n"), std::string::npos) << with;
}

// A run of library cases that --filter leaves none of is told apart.
TEST(MutateOutside, AFilterThatLeavesNoneIsNamed) {
  const std::string out = fresh("mutate-filter");
  ASSERT_EQ(sh(kBin + " run --no-validation" + cli::caseArg("results/miss-xor-closest-hit") +
                   " --out " + out + "/run",
               out + "/run.txt"),
            0)
      << slurp(out + "/run.txt");
  EXPECT_EQ(
      sh(kBin + " mutate " + out + "/run --filter 'culling/*' --out " + out + "/m", out + "/m.txt"),
      1);
  EXPECT_NE(slurp(out + "/m.txt").find("matches --filter 'culling/*' and has a device bundle"),
            std::string::npos)
      << slurp(out + "/m.txt");
}

}  // namespace
