/* ---- The comparison ----------------------------------------------------- */

static float rs_float(uint32_t w) {
  float f;
  memcpy(&f, &w, 4);
  return f;
}

static double rs_abs(double v) {
  return v < 0 ? -v : v;
}
static int rs_nan(float v) {
  return v != v;
}

static int rs_written(const uint32_t* rec, const rs_field* f) {
  return f->automatic || ((rec[f->bit / 32] >> (f->bit % 32)) & 1u);
}

/* What a ray's fields are compared under: the fields left out (bit
   rs_field.bit) and the ray's bounds (rs_bound.by). */
typedef struct {
  uint64_t skip;
  const float* widen;
} rs_ray_rules;

/* One field of a record as the expected one has it (the judge's sameField):
   floats within the field's tolerance, its abs widened to the ray's bound. */
static int rs_same(const rs_field* f, const uint32_t* d, const uint32_t* m, const float* widen) {
  const double abs = f->abs > widen[f->bound] ? f->abs : (double)widen[f->bound];
  uint32_t k;
  if (rs_written(d, f) != rs_written(m, f)) return 0;
  if (!rs_written(d, f)) return 1;
  for (k = 0; k < f->words; ++k) {
    uint32_t dw = d[f->offset + k], mw = m[f->offset + k];
    if (!f->is_float) {
      if (dw != mw) return 0;
    } else {
      float df = rs_float(dw), mf = rs_float(mw);
      double diff = rs_abs((double)df - (double)mf), scale = rs_abs((double)mf);
      if (rs_nan(df) || rs_nan(mf)) {
        if (!(rs_nan(df) && rs_nan(mf))) return 0;
      } else if (df != mf && diff > abs + f->rel * (scale > 1.0 ? scale : 1.0)) {
        return 0;
      }
    }
  }
  return 1;
}

static void rs_print_value(const rs_field* f, const uint32_t* rec) {
  uint32_t k;
  if (!rs_written(rec, f)) {
    printf("(not written)");
    return;
  }
  for (k = 0; k < f->words; ++k) {
    if (f->is_float)
      printf(k ? " %.9g" : "%.9g", (double)rs_float(rec[f->offset + k]));
    else
      printf(k ? " %u" : "%u", rec[f->offset + k]);
  }
}

/* The counts as variables: a loop up to a count of 0 draws no warning. */
static const uint32_t rs_ambiguous_count = RS_AMBIGUOUS_COUNT;
static const uint32_t rs_counter_count = RS_COUNTER_COUNT;
static const uint32_t rs_ray_count = RS_RECORDS_JUDGED ? RS_RAY_COUNT : 0; /* rays judged */
static const uint32_t rs_repeat_count = RS_REPEAT_COUNT;
static const uint32_t rs_bound_count = RS_BOUND_COUNT;

static const rs_ambiguous* rs_ambiguity(uint32_t ray) {
  uint32_t i;
  for (i = 0; i < rs_ambiguous_count; ++i)
    if (rs_ambiguous_rays[i].ray == ray) return &rs_ambiguous_rays[i];
  return NULL;
}

/* The ray's rules: the fields a repeated any-hit may change (R-AHIT-DUP),
   not judged, and the model's wider bounds of its t, origin and position. */
static rs_ray_rules rs_rules_of(uint32_t ray) {
  static const float none[5] = {0, 0, 0, 0, 0};
  rs_ray_rules r;
  uint32_t i;
  r.skip = 0;
  r.widen = none;
  for (i = 0; i < rs_repeat_count; ++i)
    if (rs_repeat_rays[i].ray == ray) r.skip = rs_repeat_rays[i].fields;
  for (i = 0; i < rs_bound_count; ++i)
    if (rs_bounds[i].ray == ray) r.widen = rs_bounds[i].by;
  return r;
}

/* The first field of `d` that differs from `m` under `r`, or NULL. */
static const rs_field* rs_differs(const uint32_t* d, const uint32_t* m, rs_ray_rules r) {
  uint32_t i;
  for (i = 0; i < RS_FIELD_COUNT; ++i)
    if (!((r.skip >> rs_fields[i].bit) & 1u) && !rs_same(&rs_fields[i], d, m, r.widen))
      return &rs_fields[i];
  return NULL;
}

static void rs_print_difference(const rs_field* f, const uint32_t* expected, const uint32_t* d) {
  printf("field '%s': expected ", f->name);
  rs_print_value(f, expected);
  printf(", observed ");
  rs_print_value(f, d);
  printf("\n");
}

/* The rays the judge warns of (R-WATERTIGHT, a "should": a double hit or a
   leak at a shared edge or vertex): the first few printed, every one counted. */
#define RS_WARNINGS_PRINTED 8u
static uint32_t rs_warned_rays = 0;

static void rs_warn(uint32_t ray, const rs_ambiguous* a, const char* what) {
  if (rs_warned_rays++ < RS_WARNINGS_PRINTED)
    printf("WARNING: ray %u (numerically ambiguous: %s): %s\n", ray, a->reason, what);
}

/* The one of the ray's answers the judge accepts with a warning that `d` is,
   its words; NULL for none. */
static const char* rs_warned_answer(const uint32_t* d, const rs_ambiguous* a, rs_ray_rules r) {
  uint32_t i;
  for (i = 0; i < a->warnings; ++i)
    if (!rs_differs(d, rs_replays + (size_t)(a->first_replay + a->replays + i) * RS_RECORD_WORDS,
                    r))
      return rs_warning_notes[a->first_warning + i];
  return NULL;
}

/* Whether `d` is one of the ray's legal answers; else, one the judge accepts
   with a warning (given in *warning). */
static int rs_legal_answer(const uint32_t* d, const rs_ambiguous* a, rs_ray_rules r,
                           const char** warning) {
  uint32_t i;
  for (i = 0; i < a->replays; ++i)
    if (!rs_differs(d, rs_replays + (size_t)(a->first_replay + i) * RS_RECORD_WORDS, r)) return 1;
  *warning = rs_warned_answer(d, a, r);
  return *warning != NULL;
}

/* An ambiguous ray whose record is none of its answers: FAIL, 0. */
static int rs_none_of(uint32_t ray, const uint32_t* d, const rs_ambiguous* a, rs_ray_rules r) {
  const uint32_t* m = rs_replays + (size_t)a->first_replay * RS_RECORD_WORDS;
  printf(
      "FAIL: %s: ray %u (numerically ambiguous: %s): the record is none of its %u legal answers "
      "(nor of the %u accepted with a warning); of the first: ",
      a->rule, ray, a->reason, a->replays, a->warnings);
  rs_print_difference(rs_differs(d, m, r), m, d);
  return 0;
}

static int rs_check_ray(uint32_t ray, const uint32_t* d) {
  const rs_ambiguous* a = rs_ambiguity(ray);
  rs_ray_rules r = rs_rules_of(ray);
  const uint32_t* m = rs_expected + (size_t)ray * RS_RECORD_WORDS;
  const rs_field* f;
  const char* warning = NULL;
  int doubled;
  if (!a) {
    f = rs_differs(d, m, r);
    if (!f) return 1;
    printf("FAIL: %s: ray %u: ", f->rule, ray);
    rs_print_difference(f, m, d);
    return 0;
  }
  /* A double hit by any-hit runs: a warning whatever the record. */
  doubled = a->ahit_limit != RS_NONE && d[RS_ANY_HIT_RUNS_WORD] > a->ahit_limit;
  if (doubled) rs_warn(ray, a, RS_ANY_HIT_DOUBLE_HIT);
  if (r.skip) return 1; /* its legal answers and what repetition changes: not judged */
  if (!rs_legal_answer(d, a, r, &warning)) return rs_none_of(ray, d, a, r);
  if (warning && !doubled) rs_warn(ray, a, warning);
  return 1;
}

static int rs_compare(const uint32_t* records, const uint32_t* counters) {
  uint32_t ray, i;
  int failures = 0;
  for (ray = 0; ray < rs_ray_count; ++ray)
    if (!rs_undefined[ray] && !rs_check_ray(ray, records + (size_t)ray * RS_RECORD_WORDS))
      ++failures;
  for (i = 0; i < rs_counter_count; ++i) {
    const rs_counter* c = &rs_counters[i];
    if (counters[i] >= c->lo && counters[i] <= c->hi) continue;
    printf("FAIL: %s: counter '%s': expected %llu..%llu, observed %u\n", c->rule, c->name,
           (unsigned long long)c->lo, (unsigned long long)c->hi, counters[i]);
    ++failures;
  }
  return failures;
}
