// A results bundle on disk: a folder a run on one machine writes and another
// machine reads back (`rayspec compare`).
//   results.json   case, backend, device, status, size, counters, images,
//                  ambiguous rays, validation messages, seconds
//   records.bin    the raw per-ray words (little-endian uint32)
//   records.csv    the kept per-ray fields, one row per ray, for people
//   NAME.raw       each image's texels (little-endian 32-bit)
//   NAME.png       a viewable picture of each image (with OpenImageIO)
//   NAME.exr       float images at full precision (with OpenImageIO)
#pragma once

#include <string>
#include <vector>

#include "results/results.h"

namespace rayspec {

// Writes the bundle into dir (created). `kept_fields` are the record fields
// written to records.csv. Returns an error message, empty on success.
std::string writeResults(const Results& r, const std::string& dir,
                         const std::vector<std::string>& kept_fields);

// The same; without image_files only NAME.raw is written per image (no
// NAME.png / NAME.exr: a forked child must not use OpenImageIO's or
// OpenEXR's thread pools, which its parent's threads own).
std::string writeResults(const Results& r, const std::string& dir, const std::vector<std::string>& kept_fields,
                         bool image_files);

// Reads a bundle back; error set on failure.
Results readResults(const std::string& dir, std::string* error);

// One field of one record as text ("1.5", "0.25 0.5"); empty when the field
// is recordable and was not written.
std::string formatField(const std::string& field, const uint32_t* record);

// The viewable 8-bit RGBA picture of an image (ids get distinct colours,
// floats are clamped to [0, 1]), as written to NAME.png.
std::vector<uint8_t> previewPixels(const Image& image);

}  // namespace rayspec
