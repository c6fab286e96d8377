// `rayspec faults --doc`: docs/wrong-devices.md lists every planted fault of
// the fault table (its one definition), as the table makes the list.
#include <gtest/gtest.h>

#include "base/whole_file.h"
#include "fault/planted_fault.h"
#include "mutate/fault_listing.h"

namespace rayspec {
namespace {

const std::string kWrongDevicesDoc = RAYSPEC_SOURCE_DIR "/docs/wrong-devices.md";

TEST(FaultListing, TheDocsListIsTheOneTheFaultTableMakes) {
  const Result<std::string> doc = readWholeFile(kWrongDevicesDoc, 1u << 20);
  ASSERT_TRUE(doc.ok()) << doc.error().format();
  const Result<std::string> made = faultsDocument(*doc);
  ASSERT_TRUE(made.ok()) << made.error().format();
  EXPECT_TRUE(*made == *doc) << "docs/wrong-devices.md does not list the planted faults the "
                                "fault table holds: build/rayspec faults --doc > /tmp/wd.md && "
                                "mv /tmp/wd.md docs/wrong-devices.md";
}

// Every fault has its own line, with what it breaks, under its kind.
TEST(FaultListing, TheListNamesEveryFault) {
  const std::string part = faultsDocPart();
  for (const FaultInfo& f : faultTable())
    EXPECT_NE(part.find("- `" + f.name + "` ("), std::string::npos) << f.name;
  EXPECT_NE(part.find("**" + std::string(faultKindText(FaultKind::Vulkan)) + ":**"),
            std::string::npos);
}

// A fault added to the table (here: one left out of the page) is caught.
TEST(FaultListing, APageThatLacksAFaultDiffers) {
  const Result<std::string> doc = readWholeFile(kWrongDevicesDoc, 1u << 20);
  ASSERT_TRUE(doc.ok()) << doc.error().format();
  const std::string line = "- `" + faultTable().back().name + "` (";
  std::string behind = *doc;
  const size_t at = behind.find(line);
  ASSERT_NE(at, std::string::npos);
  behind.erase(at, behind.find('\n', at) + 1 - at);
  const Result<std::string> made = faultsDocument(behind);
  ASSERT_TRUE(made.ok());
  EXPECT_NE(*made, behind);
  EXPECT_EQ(*made, *doc);
}

TEST(FaultListing, APageWithoutTheMarkersIsAnError) {
  const Result<std::string> made = faultsDocument("# A page\n");
  ASSERT_FALSE(made.ok());
  EXPECT_NE(made.error().message.find(kFaultsDocBegin), std::string::npos);
}

}  // namespace
}  // namespace rayspec
