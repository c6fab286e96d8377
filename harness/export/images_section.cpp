#include <algorithm>
#include <cstdio>

#include "export/c_text.h"
#include "export/export_sections.h"
#include "export/export_support.h"
#include "glsl/bindings.h"
#include "results/record_layout.h"
#include "results/tolerances.h"

namespace rayspec {
namespace {

// The index of plan.images' image `name`, as C ("RS_NONE" for none).
std::string imageIndex(const Plan& plan, const std::string& name) {
  for (size_t i = 0; i < plan.images.size(); ++i)
    if (!name.empty() && plan.images[i].name == name) return std::to_string(i) + "u";
  return "RS_NONE";
}

// One image's rs_image initialiser: its field's tolerance (scaled as the
// case says), the failing pixels allowed, the image it must equal, the
// field's place in a record, and the model's texels (array `texels`).
std::string imageEntry(const Plan& plan, const ImageOutput& out, const std::string& texels) {
  const RecordField* f = findRecordField(out.field);
  const Tolerance tol = toleranceFor(out.field);
  char numbers[128];
  std::snprintf(numbers, sizeof numbers, "%.17g, %.17g, %.17g", tol.abs, tol.rel, out.tolerance);
  const bool is_float = f && f->type == FieldType::Float;
  return "  {" + cString(out.name) + ", " + cString(out.field) + ", " + (is_float ? "1" : "0") +
         ", " + numbers + ", " + std::to_string(out.max_failing_pixels) + "u, " +
         imageIndex(plan, out.equal_to) + ", " + (f ? "1" : "0") + ", " +
         std::to_string(f ? f->offset : 0) + "u, " + std::to_string(f ? f->words : 0) + "u, " +
         std::to_string(f ? f->index : 0) + "u, " + (f && f->automatic ? "1" : "0") + ", " +
         texels + "},\n";
}

}  // namespace

std::string imagesSection(const Case& c, const Plan& plan, const Results& model) {
  std::string arrays, table;
  for (size_t i = 0; i < plan.images.size(); ++i) {
    const Image* im = imageNamed(model, plan.images[i].name);
    const std::string name = "rs_image" + std::to_string(i) + "_expected";
    arrays += cWordArray(name, im ? std::vector<uint32_t>(im->texels.begin(), im->texels.end())
                                  : std::vector<uint32_t>{});
    table += imageEntry(plan, plan.images[i], name);
  }
  if (table.empty()) {
    arrays = cWordArray("rs_image_none", {});
    table = "  {\"\", \"\", 0, 0, 0, 0, 0u, RS_NONE, 0, 0u, 0u, 0u, 0, rs_image_none},\n";
  }
  return "/* The storage images (outputs.images), one texel a ray (r32ui, or rgba32f for a float\n"
         "   field), at bindings from RS_FIRST_IMAGE_BINDING: each compared with the model's\n"
         "   texels within the field's tolerance times the image's scale, the pixels of\n"
         "   ambiguous and undefined rays left out, at most max_failing pixels differing. */\n"
         "#define RS_IMAGE_WIDTH " +
         std::to_string(c.rays.width) + "u\n#define RS_IMAGE_HEIGHT " +
         std::to_string(c.rays.height) + "u\n#define RS_FIRST_IMAGE_BINDING " +
         std::to_string(kBindingFirstImage) + "u\n#define RS_IMAGE_COUNT " +
         std::to_string(plan.images.size()) + "u\n#define RS_IMAGE_SLOTS " +
         std::to_string(std::max<size_t>(1, plan.images.size())) + "\n" + arrays +
         "static const rs_image rs_images[] = {\n" + table + "};\n\n";
}

}  // namespace rayspec
