/* Internal helpers shared by every part of libmodesplit (never installed):
 * the error sentence, argument checks, aligned allocation, the seeded RNG
 * and a monotonic clock. Nothing here is exported from the shared library.
 */
#ifndef MS_CORE_INTERNAL_H
#define MS_CORE_INTERNAL_H

#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <sys/types.h>

#include "modesplit/core.h"

#if defined(__GNUC__) || defined(__clang__)
#define MS_PRINTF(fmt, args) __attribute__((format(printf, fmt, args)))
#else
#define MS_PRINTF(fmt, args)
#endif

/* Set this thread's error sentence and return s, so a failing path reads
 *     return ms_fail(MS_ERR_INVALID_ARGUMENT, "surface: nx %d is below 2", nx);
 */
ms_status ms_fail(ms_status s, const char *fmt, ...) MS_PRINTF(2, 3);
/* ms_fail for a refusal of one desc field: key names it ("spacing"), so
 * that a scene, which filled the desc from its keys, can name the key of
 * its file that set the field (ms_last_error_key). ms_fail clears it; the
 * checks below set it to their key. */
ms_status ms_fail_key(ms_status s, const char *key, const char *fmt, ...) MS_PRINTF(3, 4);
const char *ms_last_error_key(void);

/* Argument checks: each returns MS_OK or fails with a sentence naming the
 * part, the key, the value and the bound ("surface: dx 0 m must be > 0"). */
ms_status ms_check_finite(const char *part, const char *key, double v);
ms_status ms_check_range(const char *part, const char *key, double v, double lo, double hi,
                         const char *unit);
ms_status ms_check_positive(const char *part, const char *key, double v, const char *unit);
ms_status ms_check_int_range(const char *part, const char *key, long v, long lo, long hi);
ms_status ms_check_not_null(const char *part, const char *key, const void *p);

/* Every allocation of the library goes through these (lib/core/alloc.c),
 * and so through the engine's allocator when ms_set_allocator gave one;
 * never call malloc/free directly in lib/ (JSON text comes from
 * ms_json_text, paths from realpath into a buffer; tests/test_alloc.c
 * counts the direct calls, linked with -Wl,--wrap).
 * ms_alloc: zeroed, 64-byte aligned memory (cache line, AVX-512 vector); n
 * in bytes. ms_alloc_array checks count*size for overflow. ms_malloc is
 * not zeroed; ms_realloc keeps p valid when it fails. NULL when out of
 * memory. ms_free(NULL) does nothing; ms_strdup(NULL) is NULL (an
 * optional string stays absent). */
void *ms_alloc(size_t n);
void *ms_alloc_array(size_t count, size_t size);
void *ms_malloc(size_t n);
void *ms_realloc(void *p, size_t n);
char *ms_strdup(const char *s);
/* A jansson value as text (json_dumps' flags), in ms_malloc memory to give
 * back with ms_free; NULL when out of memory (lib/core/json_text.c). */
struct json_t;
char *ms_json_text(const struct json_t *v, size_t flags);

/* A file named by untrusted input, opened for reading only when it is a
 * regular file (lib/core/file.c): NULL with *why a phrase ("a FIFO (named
 * pipe)", "a character device", the system's reason) otherwise. Never
 * blocks on a FIFO. */
FILE *ms_fopen_regular(const char *path, const char **why);
/* "a regular file", "a directory", "a FIFO (named pipe)", ... */
const char *ms_file_kind(mode_t mode);
void ms_free(void *p);
/* Blocks allocated since the process started, and blocks live now (for
 * the tests that prove a step allocates nothing). */
long ms_alloc_count(void);
long ms_alloc_live(void);

/* xoshiro128** seeded by splitmix64: small, fast, and the same sequence on
 * every platform, carried in the handle that uses it (no global state). */
typedef struct ms_rng {
    uint32_t s[4];
} ms_rng;
void ms_rng_seed(ms_rng *r, uint64_t seed);
uint32_t ms_rng_u32(ms_rng *r);
/* Uniform in [0, 1), 24 random bits. */
float ms_rng_uniform(ms_rng *r);
/* Poisson-distributed count with the given mean (>= 0). */
long ms_rng_poisson(ms_rng *r, double mean);

/* The leading `size` of the public structs (lib/core/struct_size.c).
 * MS_STRUCT_SIZES(ms_surface_desc, max_substeps, "ms_surface_desc_default()")
 * names the struct, the last field of its version 0.1 layout, and how a
 * caller gets a valid size. When a struct grows in a release, the sizes of
 * the older layouts stay known (add a v2_end then). */
typedef struct ms_struct_sizes {
    const char *name; /* "ms_surface_desc" */
    const char *init; /* "ms_surface_desc_default()" */
    size_t current;   /* sizeof today */
    size_t v1_end;    /* end of the last field of the 0.1 layout */
} ms_struct_sizes;
#define MS_STRUCT_SIZES(type, last_v1_field, init) \
    ((ms_struct_sizes){#type, init, sizeof(type),  \
                       offsetof(type, last_v1_field) + sizeof(((type *)0)->last_v1_field)})
/* A desc the caller passes in: refuses a NULL pointer, size 0 and a size
 * the library does not know (MS_ERR_INVALID_ARGUMENT naming the struct);
 * otherwise copies the caller's .size bytes over *local (which holds the
 * defaults) and sets local's size to the current sizeof. */
ms_status ms_struct_in(const void *user, void *local, ms_struct_sizes k, const char *part);
/* A struct the library fills: the caller's .size if known, else 0 (nothing
 * may be written; ms_last_error says why; a NULL pointer gives 0 silently). */
size_t ms_struct_out(const void *user, ms_struct_sizes k, const char *part);
/* Copy the first `size` bytes of full into user, keeping user's .size. */
void ms_struct_write(void *user, const void *full, size_t size);

/* Return the status of call if it is an error: the one early-return
 * helper of the library (was TRY/CHECK in three files). */
#define MS_TRY(call)                   \
    do {                               \
        ms_status ms_try_st_ = (call); \
        if (ms_try_st_ != MS_OK)       \
            return ms_try_st_;         \
    } while (0)
/* A NUL-terminated copy of the first n bytes of s (ms_free it); NULL when
 * out of memory. ms_strdup (above) copies a whole string. */
char *ms_strndup(const char *s, size_t n);

/* The name in the NULL-terminated list closest to s by edit distance
 * (lib/core/spell.c), for a "did you mean" in the sentence of an unknown
 * key or value: at most 1 edit for s of up to 4 characters, 2 beyond;
 * NULL when none is that close (or s is in the list). */
const char *ms_closest_name(const char *s, const char *const *names);

/* Monotonic clock in seconds, for statistics only (never for results). */
double ms_now(void);

#define MS_MIN(a, b) ((a) < (b) ? (a) : (b))
#define MS_MAX(a, b) ((a) > (b) ? (a) : (b))
#define MS_CLAMP(v, lo, hi) MS_MIN(MS_MAX((v), (lo)), (hi))

#endif /* MS_CORE_INTERNAL_H */
