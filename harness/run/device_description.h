// What `rayspec devices` prints of a device beyond its heading and limits,
// as text (pure functions, each line without its indent): its identity
// (conformance version, driver ID, UUIDs), the validation layer runs would
// load, and the library cases it cannot run (run/library_support.h).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "run/library_support.h"
#include "vulkan/vulkan_engine.h"

namespace rayspec {

// "conformance version 1.3.1.1, driver ID MesaLlvmpipe (13)", then the
// device, driver and pipeline cache UUIDs; "not reported" for what a device
// below Vulkan 1.2 (1.1 for the UUIDs) does not tell.
std::vector<std::string> deviceIdentityLines(const DeviceInfo& d);

// The Khronos validation layer a run would load: its version (installed: its
// specVersion, 0 when none is), whether runs load it (`off`: --no-validation),
// and what it changes.
std::string validationLayerLine(uint32_t installed, bool off);

// "library: N of M cases NotSupported here", then one line per missing
// feature that skips cases, with how many ("none" when nothing is missing).
std::vector<std::string> librarySupportLines(const LibrarySupport& s);

}  // namespace rayspec
