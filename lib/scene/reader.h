/* Typed readers of scene values that name file:line:col, the key and what
 * is allowed when a value is wrong (see reader.c). Internal. */
#ifndef MS_SCENE_READER_H
#define MS_SCENE_READER_H

#include <jansson.h>

#include "core/core_internal.h"
#include "scene/locate.h"

#define MS_SCENE_MAX_DEPTH 16

typedef struct ms_scene_ctx {
    const char *file; /* for messages: the path, or "<scene>" */
    const char *text;
    size_t len;
    ms_scene_pathelem path[MS_SCENE_MAX_DEPTH];
    int depth;
    const char *dir; /* the scene file's folder with its '/', "" when parsed */
    /* --set overrides (override.c): a failure whose key is one of these (or
     * inside one) names "--set KEY=VALUE" instead of file:line:col. */
    const char *const *set;
    int nset;
} ms_scene_ctx;

/* Fail with "file:line:col: a.b[2].c: <message>", at the place the current
 * path names. Returns st. */
ms_status ms_scene_fail(const ms_scene_ctx *c, ms_status st, const char *fmt, ...) MS_PRINTF(3, 4);

void ms_scene_push_key(ms_scene_ctx *c, const char *key);
void ms_scene_push_index(ms_scene_ctx *c, long index);
void ms_scene_pop(ms_scene_ctx *c);

/* Every key of obj must be in the NULL-terminated list `allowed` (or be
 * "comment", a string, which every object may carry). MS_ERR_PARSE names
 * the first unknown key and lists the allowed ones. */
ms_status ms_scene_check_keys(ms_scene_ctx *c, json_t *obj, const char *const *allowed);

/* Each reader below: an absent key gives the default; a value of the
 * wrong type is MS_ERR_PARSE, one out of range MS_ERR_INVALID_ARGUMENT. */

/* A number in [lo, hi], or (lo, hi] when lo_open. */
ms_status ms_scene_get_number(ms_scene_ctx *c, json_t *obj, const char *key, double def, double lo,
                              double hi, int lo_open, const char *unit, double *out);
ms_status ms_scene_get_float(ms_scene_ctx *c, json_t *obj, const char *key, double def, double lo,
                             double hi, int lo_open, const char *unit, float *out);
ms_status ms_scene_get_int(ms_scene_ctx *c, json_t *obj, const char *key, long def, long lo,
                           long hi, long *out);
ms_status ms_scene_get_bool(ms_scene_ctx *c, json_t *obj, const char *key, int def, int *out);
/* A string (view into obj, valid while obj lives); def may be NULL. */
ms_status ms_scene_get_string(ms_scene_ctx *c, json_t *obj, const char *key, const char *def,
                              const char **out);
/* A string that must be one of names (NULL-terminated); *out its index. */
ms_status ms_scene_get_enum(ms_scene_ctx *c, json_t *obj, const char *key, const char *const *names,
                            int def, int *out);
/* An array of exactly n numbers, each in [lo, hi]; def (n values) may be NULL
 * only when the key is required. */
ms_status ms_scene_get_vec(ms_scene_ctx *c, json_t *obj, const char *key, int n, const float *def,
                           double lo, double hi, const char *unit, float *out);
/* The n numbers of an array value v already pushed as the current path. */
ms_status ms_scene_read_vec(ms_scene_ctx *c, json_t *v, int n, double lo, double hi,
                            const char *unit, float *out);
/* An array of exactly n integers, each in [lo, hi]. */
ms_status ms_scene_get_ivec(ms_scene_ctx *c, json_t *obj, const char *key, int n, const int *def,
                            long lo, long hi, int *out);
/* A member that must be an object (NULL when absent). */
ms_status ms_scene_get_object(ms_scene_ctx *c, json_t *obj, const char *key, json_t **out);
/* A member that must be an array of at most max elements (NULL when absent). */
ms_status ms_scene_get_array(ms_scene_ctx *c, json_t *obj, const char *key, size_t min, size_t max,
                             json_t **out);
/* A required member: MS_ERR_INVALID_ARGUMENT naming it when absent. */
ms_status ms_scene_require(ms_scene_ctx *c, json_t *obj, const char *key, const char *what);

#endif
