/* The fixed part of a `rayspec export --format c` reproducer: a generic
 * player of one case, the case's data spliced in by rayspec (export_c.cpp)
 * where the marker line below stands. It creates an instance and a device,
 * builds the bottom levels and the top level from the embedded inputs,
 * creates the ray tracing pipeline from the embedded SPIR-V, writes the
 * shader binding table with the device's handles, binds the buffers, traces,
 * reads the per-ray records and counters back and compares them with the
 * reference model's expectations, embedded. Exit status: 0 PASS, or a
 * QualityWarning (a last line "QualityWarning: ...": R-WATERTIGHT broken, a
 * "should", as rayspec exits 0 on it), 1 FAIL (each wrong value: rule, ray,
 * field, expected, observed), 77 NotSupported (the missing feature named),
 * 2 a Vulkan error.
 * The player is the files of harness/export/player/ joined, in the order
 * parts.cmake lists them, by tools/embed_player.cmake: this one (the types
 * of the case's data, and the marker), then one file a step; they are
 * compiled only as that one file, an exported reproducer (C99, the Vulkan
 * loader and libc). */
#include <math.h> /* NAN, INFINITY in the data (macros: no -lm) */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <vulkan/vulkan.h>

#define RS_NONE 0xFFFFFFFFu

typedef struct {
  VkShaderStageFlagBits stage;
  const uint32_t* code;
  size_t bytes;
} rs_shader;
typedef struct {
  VkRayTracingShaderGroupTypeKHR type;
  uint32_t general, closest_hit, any_hit, intersection; /* shader indices or RS_NONE */
} rs_group;
typedef struct {
  /* Triangles, or AABBs: then `vertices` holds the boxes (VkAabbPositionsKHR,
     `stride` apart) and the format and index fields are unused. */
  VkGeometryTypeKHR type;
  VkFormat format;
  const char* format_name; /* the case's name of it (triangles.vertex_format) */
  uint32_t stride, max_vertex;
  VkIndexType index_type;
  VkGeometryFlagsKHR flags;
  const uint8_t *vertices, *indices, *transform;
  size_t vertex_bytes, index_bytes, transform_bytes;
  VkAccelerationStructureBuildRangeInfoKHR range;
} rs_geometry;
typedef struct {
  uint32_t first_geometry, geometry_count;
  uint32_t reached; /* some instance of the scene as first built references it: built */
} rs_blas;
typedef struct {
  float transform[12];
  uint32_t custom_index, mask, sbt_offset, flags, blas; /* blas: RS_NONE for none */
  uint32_t tlas;                                        /* the top level it belongs to */
} rs_instance;
/* scene.build.copy: the structures the traces use are copies (R-AS-COPY). */
enum rs_copy { RS_COPY_NONE, RS_COPY_CLONE, RS_COPY_COMPACT, RS_COPY_SERIALIZE };
typedef struct {
  uint32_t group; /* RS_NONE: an all-zero record */
  uint32_t data_words;
  uint32_t data[8];
} rs_record;
/* RS_BIND_WORDS: a read-only buffer of fixed words (the scene data of
   intersection programs, the SBT as tables). RS_BIND_IMAGE: a storage image
   (outputs.images), image binding - RS_FIRST_IMAGE_BINDING. */
enum rs_binding_kind {
  RS_BIND_TLAS,
  RS_BIND_RAYS,
  RS_BIND_RECORDS,
  RS_BIND_COUNTERS,
  RS_BIND_WORDS,
  RS_BIND_IMAGE
};
typedef struct {
  uint32_t binding;
  enum rs_binding_kind kind;
  const uint32_t* words; /* RS_BIND_WORDS: the buffer's contents */
  size_t bytes;
} rs_binding;
typedef struct {
  const char *name, *rule;
  uint32_t offset, words, is_float, automatic, bit;
  uint32_t bound; /* the rs_bound.by a ray's bound widens its abs with (0: none) */
  double abs, rel;
} rs_field;
/* An ambiguous ray's answers in rs_replays from first_replay: `replays` legal
   ones, then `warnings` the judge accepts with a QualityWarning (R-WATERTIGHT),
   their words in rs_warning_notes from first_warning. ahit_limit: the most
   any-hit runs of a device that hits one triangle of the shared edge or
   vertex (more: a double hit, R-WATERTIGHT), RS_NONE where not judged so. */
typedef struct {
  uint32_t ray, first_replay, replays, warnings, first_warning, ahit_limit;
  const char *reason, *rule;
} rs_ambiguous;
typedef struct {
  const char *name, *rule;
  uint64_t lo, hi;
} rs_counter;
typedef struct {
  uint32_t ray;
  uint64_t fields; /* bit rs_field.bit: a field a repeated any-hit may change */
} rs_repeat;
typedef struct {
  uint32_t ray;
  /* 0, then the ray's t, object-origin, hit-position and carried bounds (R-PREC; the
     carried one: the widest, where the case carries them into a free field) */
  float by[5];
} rs_bound;

typedef struct {
  const char *name, *field;
  uint32_t is_float;      /* rgba32f (4 channels), else r32ui (1) */
  double abs, rel, scale; /* the field's tolerance, times the image's scale */
  uint32_t max_failing;   /* pixels allowed to differ */
  uint32_t equal_to;      /* an image it must equal texel for texel, or RS_NONE */
  uint32_t has_field;     /* the field's place in a record: */
  uint32_t offset, words, bit, automatic;
  const uint32_t* expected; /* the model's texels */
} rs_image;

/* RAYSPEC_CASE_DATA */
