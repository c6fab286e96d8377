// The interface a pipeline linked from libraries declares
// (maxPipelineRayPayloadSize, vulkan/pipeline.h interfacePayloadBytes): the
// case's largest payload or callable data type, never less than the plain
// RsCallData, and the same for every part of the pipeline.
#include <gtest/gtest.h>

#include "vulkan/pipeline.h"

namespace rayspec {
namespace {

TEST(LibraryInterface, TheLargestPayloadOrCallableDataTypeOfTheCase) {
  Pipeline p;
  EXPECT_EQ(interfacePayloadBytes(p), 48u);  // RsCallData; RsPayload is 24
  p.payload_words = {0, 10, 2};
  EXPECT_EQ(interfacePayloadBytes(p), 64u);  // 24 + 4 x 10
  p.call_data_words = {0, 52};
  EXPECT_EQ(interfacePayloadBytes(p), 256u);  // 48 + 4 x 52
  p.payload_words = {58};
  p.call_data_words = {0};
  EXPECT_EQ(interfacePayloadBytes(p), 256u);  // 24 + 4 x 58
}

}  // namespace
}  // namespace rayspec
