#include "run/device_description.h"

namespace rayspec {
namespace {

std::string orNotReported(const std::string& s) {
  return s.empty() ? "not reported" : s;
}

std::string casesText(int n) {
  return std::to_string(n) + (n == 1 ? " case" : " cases");
}

}  // namespace

std::vector<std::string> deviceIdentityLines(const DeviceInfo& d) {
  const size_t dash = d.device_uuid.find('-');
  const std::string device_uuid = d.device_uuid.substr(0, dash);
  const std::string driver_uuid = dash == std::string::npos ? "" : d.device_uuid.substr(dash + 1);
  return {
      "conformance version " + orNotReported(d.conformance_version) + ", driver ID " +
          orNotReported(d.driver_id),
      "device UUID " + orNotReported(device_uuid) + ", driver UUID " + orNotReported(driver_uuid),
      "pipeline cache UUID " + orNotReported(d.pipeline_cache_uuid)};
}

std::string validationLayerLine(uint32_t installed, bool off) {
  if (installed == 0)
    return "Validation layer: not installed (runs check no API usage; --strict-validation "
           "refuses to run without it; no case needs it)";
  return "Validation layer: VK_LAYER_KHRONOS_validation " + vulkanVersionText(installed) +
         (off ? " (off: --no-validation)"
              : " (on in runs; a layer older than an extension a case uses makes that case "
                "NotSupported, --no-validation runs it)");
}

std::vector<std::string> librarySupportLines(const LibrarySupport& s) {
  std::vector<std::string> lines = {"library: " + std::to_string(s.not_supported) + " of " +
                                    casesText(s.cases) + " NotSupported here"};
  std::string unneeded;
  for (const FeatureSkips& f : s.missing) {
    if (f.cases == 0) {
      unneeded += (unneeded.empty() ? "" : ", ") + f.feature;
    } else if (f.validation_layer) {
      lines.push_back("  " + casesText(f.cases) + " under the validation layer " + f.feature +
                      " (older than an extension they use; --no-validation runs them)");
    } else {
      lines.push_back("  " + casesText(f.cases) + " for lack of " + f.feature);
    }
  }
  if (!unneeded.empty()) lines.push_back("  lacks also " + unneeded + ": no case needs them");
  return lines;
}

}  // namespace rayspec
