// A results bundle on disk: a folder a run on one machine writes and another
// machine reads back (`rayspec compare`).
//   results.json   case, backend, device, status, size, counters, images,
//                  ambiguous rays, validation messages, seconds
//   records.bin    the raw per-ray words (little-endian uint32)
//   replays.bin    the model's: the record of each legal replay of each
//                  ambiguous ray, in results.json's order (RayAmbiguity::replays)
//   records.csv    the kept per-ray fields, one row per ray, for people
//                  (a run writes it where the case did not pass, see BundleFiles)
//   NAME.raw       each image's texels (little-endian 32-bit)
//   NAME.png       a viewable picture of each image (with OpenImageIO)
//   NAME.exr       float images at full precision (with OpenImageIO)
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "base/result.h"
#include "results/results.h"

namespace rayspec {

// Writes the bundle into dir (created). `kept_fields` are the record fields
// written to records.csv.
Result<void> writeResults(const Results& r, const std::string& dir,
                          const std::vector<std::string>& kept_fields);

// Which derived files a bundle gets besides results.json, records.bin and
// NAME.raw. Without image_files no NAME.png / NAME.exr (a forked child must
// not use OpenImageIO's or OpenEXR's thread pools, which its parent's threads
// own); without records_csv no records.csv (a copy of records.bin for people:
// 54 MB and seconds for a million rays; the run writes it for cases that do
// not pass, or every case with --records-csv).
struct BundleFiles {
  bool image_files = true;
  bool records_csv = true;
};
Result<void> writeResults(const Results& r, const std::string& dir,
                          const std::vector<std::string>& kept_fields, const BundleFiles& files);

// records.csv alone: x, y, the kept fields where written, the automatic ones.
Result<void> writeRecordsCsv(const Results& r, const std::string& path,
                             const std::vector<std::string>& kept_fields);

// Reads a bundle back (results.json, records.bin, the images).
Result<Results> readResults(const std::string& dir);

// The most bytes a results.json may hold (its ambiguous rays' candidates
// grow with the launch: 43 MB for accel/size-aabbs/1048576's 2^20 rays).
constexpr uint64_t kMaxResultsJsonBytes = 512ull << 20;

// One field of one record as text ("1.5", "0.25 0.5"); empty when the field
// is recordable and was not written.
std::string formatField(const std::string& field, const uint32_t* record);

// The viewable 8-bit RGBA picture of an image (ids get distinct colours,
// floats are clamped to [0, 1]), as written to NAME.png.
std::vector<uint8_t> previewPixels(const Image& image);

}  // namespace rayspec
