/* ---- The images against the model's ------------------------------------- */

static const uint32_t rs_image_rays = RS_RAY_COUNT; /* a texel a ray */

/* Whether a ray's pixel is left out of image `im`, as the judge leaves it out:
   an ambiguous ray (its legal answers differ by design), a ray with undefined
   behaviour (R-UB), or one whose field a repeated any-hit may change (R-AHIT-DUP). */
static int rs_pixel_left_out(const rs_image* im, uint32_t ray) {
  return rs_undefined[ray] || rs_ambiguity(ray) ||
         (im->has_field && ((rs_rules_of(ray).skip >> im->bit) & 1u));
}

/* How far an observed texel is from the expected one, in allowances (the
   judge's prepareImagePair; above 1 fails): ids 2 where they differ; floats
   |observed - expected| over the field's tolerance times the image's scale, NaN
   equal only to NaN. */
static float rs_texel_error(const rs_image* im, uint32_t d, uint32_t m) {
  float df = rs_float(d), mf = rs_float(m);
  double allowance, error;
  if (d == m) return 0.0f;
  if (!im->is_float) return 2.0f;
  if (rs_nan(df) || rs_nan(mf)) return rs_nan(df) && rs_nan(mf) ? 0.0f : 1e30f;
  if (df == mf) return 0.0f;
  allowance =
      (im->abs + im->rel * (rs_abs((double)mf) > 1.0 ? rs_abs((double)mf) : 1.0)) * im->scale;
  error = rs_abs((double)df - (double)mf) / allowance;
  return (float)(error < 1e30 ? error : 1e30);
}

static void rs_print_texel(const rs_image* im, uint32_t t) {
  if (im->is_float)
    printf("%.9g", (double)rs_float(t));
  else
    printf("%u", t);
}

/* The pixels of image i that differ from the model's beyond the tolerance
   (the left-out ones aside); FAIL printed when more than the case allows. */
static int rs_check_image(uint32_t i, const uint32_t* texels) {
  const rs_image* im = &rs_images[i];
  const uint32_t channels = im->is_float ? 4 : 1;
  uint32_t ray, k, failing = 0, first = 0, first_channel = 0;
  for (ray = 0; ray < rs_image_rays; ++ray) {
    int fails = 0;
    if (rs_pixel_left_out(im, ray)) continue;
    for (k = 0; k < channels && !fails; ++k) {
      const size_t at = (size_t)ray * channels + k;
      fails = rs_texel_error(im, texels[at], im->expected[at]) > 1.0f;
      if (fails && !failing) first = ray, first_channel = k;
    }
    failing += fails ? 1u : 0u;
  }
  if (failing <= im->max_failing) return 1;
  printf(
      "FAIL: image: image '%s' differs from the model in %u pixels (%u allowed); first: "
      "pixel %u, channel %u: expected ",
      im->name, failing, im->max_failing, first, first_channel);
  rs_print_texel(im, im->expected[(size_t)first * channels + first_channel]);
  printf(", observed ");
  rs_print_texel(im, texels[(size_t)first * channels + first_channel]);
  printf(" ('%s')\n", im->field);
  return 0;
}

/* On the ambiguous rays, image i shows the device's own record of its field
   (the judge's compareImagesToRecords): the first ray where it does not, or RS_NONE. */
static uint32_t rs_image_unlike_records(uint32_t i, const uint32_t* texels,
                                        const uint32_t* records) {
  const rs_image* im = &rs_images[i];
  const uint32_t channels = im->is_float ? 4 : 1;
  const uint32_t shown = im->words < channels ? im->words : channels;
  uint32_t a, k;
  if (!RS_RECORDS_JUDGED || !im->has_field) return RS_NONE;
  for (a = 0; a < rs_ambiguous_count; ++a) {
    const uint32_t ray = rs_ambiguous_rays[a].ray;
    const uint32_t* rec = records + (size_t)ray * RS_RECORD_WORDS;
    if (!im->automatic && !((rec[im->bit / 32] >> (im->bit % 32)) & 1u)) continue;
    for (k = 0; k < shown; ++k)
      if (texels[(size_t)ray * channels + k] != rec[im->offset + k]) return ray;
  }
  return RS_NONE;
}

/* Images the case declares equal (equal_to) are equal texel for texel. */
static int rs_check_equal_images(uint32_t i, const rs_image_target* targets) {
  const rs_image* im = &rs_images[i];
  const size_t words = (size_t)rs_image_rays * (im->is_float ? 4 : 1);
  if (im->equal_to == RS_NONE) return 1;
  if (!memcmp(targets[i].readback.mapped, targets[im->equal_to].readback.mapped, words * 4))
    return 1;
  printf("FAIL: image: images '%s' and '%s' differ on the device (equal_to: texel for texel)\n",
         im->name, rs_images[im->equal_to].name);
  return 0;
}

static int rs_compare_images(const rs_image_target* targets, const uint32_t* records) {
  uint32_t i, ray;
  int failures = 0;
  for (i = 0; i < rs_image_count; ++i) {
    const uint32_t* texels = (const uint32_t*)targets[i].readback.mapped;
    failures += !rs_check_image(i, texels);
    failures += !rs_check_equal_images(i, targets);
    ray = rs_image_unlike_records(i, texels, records);
    if (ray == RS_NONE) continue;
    printf(
        "FAIL: image: ray %u (numerically ambiguous): image '%s' shows another value than "
        "the device's own record of '%s'\n",
        ray, rs_images[i].name, rs_images[i].field);
    ++failures;
  }
  return failures;
}
