/* Parameter parsing shared by the plugins shipped with libmodesplit
 * (header-only, so each plugin stays one self-contained shared object).
 * A plugin's parameters are a JSON object text (the scene file syntax),
 * parsed with jansson. Unknown keys, wrong types and out-of-range values
 * fail with a sentence naming the key; the first failure wins.
 *
 *     params pm;
 *     static const char *const keys[] = {"radius", NULL};
 *     if (params_open(&pm, json, keys, err, err_size) == 0) {
 *         float r = params_number(&pm, "radius", 0.5f, 1e-6f, 1e6f, "m");
 *     }
 *     return params_close(&pm);   // MS_PLUGIN_OK or the first error
 */
#ifndef MS_PLUGINS_PARAMS_H
#define MS_PLUGINS_PARAMS_H

#include <jansson.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "modesplit/plugin.h"

typedef struct params {
    json_t *root;
    char *err;
    size_t err_size;
    int rc; /* MS_PLUGIN_OK or the first error */
} params;

#if defined(__GNUC__) || defined(__clang__)
__attribute__((format(printf, 3, 4)))
#endif
static inline void
params_fail(params *p, int rc, const char *fmt, ...)
{
    if (p->rc != MS_PLUGIN_OK)
        return;
    p->rc = rc;
    if (p->err && p->err_size) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(p->err, p->err_size, fmt, ap);
        va_end(ap);
    }
}

/* keys: the known keys, NULL-terminated. Returns p->rc. */
static inline int params_open(params *p, const char *json, const char *const *keys, char *err,
                              size_t err_size)
{
    p->root = NULL;
    p->err = err;
    p->err_size = err_size;
    p->rc = MS_PLUGIN_OK;
    if (err && err_size)
        err[0] = '\0';
    if (!json || !*json) {
        p->root = json_object();
        if (!p->root)
            params_fail(p, MS_PLUGIN_ERR_OUT_OF_MEMORY, "out of memory");
        return p->rc;
    }
    json_error_t je;
    p->root = json_loads(json, JSON_REJECT_DUPLICATES, &je);
    if (!p->root) {
        params_fail(p, MS_PLUGIN_ERR_PARSE, "parameters line %d column %d: %s", je.line, je.column,
                    je.text);
        return p->rc;
    }
    if (!json_is_object(p->root)) {
        params_fail(p, MS_PLUGIN_ERR_PARSE, "parameters must be a JSON object");
        return p->rc;
    }
    const char *key;
    json_t *value;
    json_object_foreach(p->root, key, value)
    {
        int known = 0;
        for (int i = 0; keys[i]; ++i)
            known |= strcmp(keys[i], key) == 0;
        if (!known) {
            char list[256] = "";
            size_t len = 0;
            for (int i = 0; keys[i] && len + 32 < sizeof list; ++i)
                len +=
                    (size_t)snprintf(list + len, sizeof list - len, "%s%s", i ? ", " : "", keys[i]);
            params_fail(p, MS_PLUGIN_ERR_INVALID_ARGUMENT, "unknown key \"%s\"; known keys: %s",
                        key, list);
            return p->rc;
        }
    }
    return p->rc;
}

static inline int params_has(const params *p, const char *key)
{
    return p->root && json_object_get(p->root, key) != NULL;
}

static inline float params_check(params *p, const char *key, double v, double lo, double hi,
                                 const char *unit)
{
    if (!isfinite(v) || v < lo || v > hi)
        params_fail(p, MS_PLUGIN_ERR_INVALID_ARGUMENT, "%s %g%s%s is outside [%g, %g]", key, v,
                    *unit ? " " : "", unit, lo, hi);
    return (float)v;
}

/* A number in [lo, hi] (def when absent). */
static inline float params_number(params *p, const char *key, float def, double lo, double hi,
                                  const char *unit)
{
    json_t *v = p->root ? json_object_get(p->root, key) : NULL;
    if (!v)
        return def;
    if (!json_is_number(v)) {
        params_fail(p, MS_PLUGIN_ERR_PARSE, "%s must be a number (%s)", key, unit);
        return def;
    }
    return params_check(p, key, json_number_value(v), lo, hi, unit);
}

/* An array of exactly n numbers, each in [lo, hi] (def when absent). */
static inline void params_vec(params *p, const char *key, int n, float *out, const float *def,
                              double lo, double hi, const char *unit)
{
    for (int i = 0; i < n; ++i)
        out[i] = def[i];
    json_t *v = p->root ? json_object_get(p->root, key) : NULL;
    if (!v)
        return;
    if (!json_is_array(v) || json_array_size(v) != (size_t)n) {
        params_fail(p, MS_PLUGIN_ERR_PARSE, "%s must be an array of %d numbers (%s)", key, n, unit);
        return;
    }
    for (int i = 0; i < n; ++i) {
        json_t *e = json_array_get(v, (size_t)i);
        char name[64];
        snprintf(name, sizeof name, "%s[%d]", key, i);
        if (!json_is_number(e)) {
            params_fail(p, MS_PLUGIN_ERR_PARSE, "%s must be a number (%s)", name, unit);
            return;
        }
        out[i] = params_check(p, name, json_number_value(e), lo, hi, unit);
    }
}

/* A string (def when absent); valid until params_close. */
static inline const char *params_string(params *p, const char *key, const char *def)
{
    json_t *v = p->root ? json_object_get(p->root, key) : NULL;
    if (!v)
        return def;
    if (!json_is_string(v)) {
        params_fail(p, MS_PLUGIN_ERR_PARSE, "%s must be a string", key);
        return def;
    }
    return json_string_value(v);
}

/* The JSON value of key (NULL when absent), borrowed until params_close. */
static inline json_t *params_get(const params *p, const char *key)
{
    return p->root ? json_object_get(p->root, key) : NULL;
}

static inline int params_close(params *p)
{
    json_decref(p->root);
    p->root = NULL;
    return p->rc;
}

#endif /* MS_PLUGINS_PARAMS_H */
