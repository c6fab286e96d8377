// Viewable image files (PNG, and EXR for float images) written through
// OpenImageIO. A run-only build without OpenImageIO writes none (the raw
// texels in the bundle stay the reference).
#pragma once

#include <string>

#include "base/result.h"
#include "results/results.h"

namespace rayspec {

// Writes dir/NAME.png (and dir/NAME.exr for float images), or the error
// (ErrorKind::Harness: a file OpenImageIO could not write); built without
// OpenImageIO, writes nothing and succeeds.
Result<void> writeImageFiles(const Image& image, const std::string& dir);

// Writes dir/NAME.png showing where two images of the same size differ: red
// where texels differ (brighter for larger float differences), grey where
// equal; images of different sizes get none. The error as writeImageFiles's.
Result<void> writeDiffImage(const Image& device, const Image& model, const std::string& dir);

bool imageFilesSupported();

}  // namespace rayspec
