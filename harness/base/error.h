// The one error convention: a fallible function returns Result<T>
// (base/result.h), which holds its value or an Error: a message, its kind
// and, when the error is about a place in an input file (a case, sweep,
// baseline or saved file), where. No function of rayspec's own throws;
// exceptions are caught where a library or the standard library throws them
// (yaml-cpp, nlohmann-json, CLI11, OpenImageIO, std::filesystem ...), right at
// the call, and turned into an Error there. tools/check-exceptions.sh (ctest
// style/exceptions) keeps `throw` out of harness/.
#pragma once

#include <string>

#include "base/source_loc.h"

namespace rayspec {

// What an Error means to whoever must tell errors apart (the Vulkan engine
// turns each into a status of the case's device side).
enum class ErrorKind {
  Input,          // an input (a file, an argument, a case) is wrong; also any
                  // error no caller needs to tell apart
  NotSupported,   // the device cannot run the case: a limit or a feature it lacks
  Device,         // a Vulkan call failed (Error::call, Error::result)
  ShaderCompile,  // rayspec generated a stage that does not compile or validate
  Harness,        // the harness failed: a results bundle not written or read, a
                  // child that could not report; the case becomes a CaseError
};

struct Error {
  SourceLoc loc;  // loc.file empty: not about a place in an input file
  std::string message;
  ErrorKind kind = ErrorKind::Input;
  // ErrorKind::Device: the Vulkan function that failed ("" when the error is
  // not one call's) and the name of the VkResult it returned, as text so that
  // base/ needs no Vulkan header.
  std::string call;
  std::string result;

  // "FILE:LINE:COL: FIELD: MESSAGE" (the field when known), or MESSAGE when
  // there is no file; input quoted in it, and the file's path, made visible
  // (base/visible_text.h).
  std::string format() const;
};

// An error about no place in an input file.
inline Error errorMessage(std::string message) {
  return Error{{}, std::move(message)};
}

// An error of the given kind, about no place in an input file.
inline Error errorOf(ErrorKind kind, std::string message) {
  return Error{{}, std::move(message), kind};
}

// The same error, its message preceded by `context` ("saved results: ..."):
// the kind and the failed call stay; the file, line and column go into the
// message (format()).
Error withContext(const std::string& context, const Error& e);

}  // namespace rayspec
