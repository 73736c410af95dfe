/* Typed readers of scene values. Each pushes its key on the context's path
 * so that a failure can name file:line:col (found by locate.c), the full
 * key ("effects.rain.rate") and the allowed values. */
#include <float.h>
#include <limits.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "scene/reader.h"

static const char *type_name(const json_t *v)
{
    switch (json_typeof(v)) {
    case JSON_OBJECT:
        return "an object";
    case JSON_ARRAY:
        return "an array";
    case JSON_STRING:
        return "a string";
    case JSON_INTEGER:
        return "an integer";
    case JSON_REAL:
        return "a number";
    case JSON_TRUE:
    case JSON_FALSE:
        return "a boolean";
    case JSON_NULL:
        return "null";
    }
    return "a value";
}

static void path_string(const ms_scene_ctx *c, char *buf, size_t size)
{
    size_t used = 0;
    buf[0] = '\0';
    for (int d = 0; d < c->depth && used < size; ++d) {
        int w;
        if (c->path[d].key)
            w = snprintf(buf + used, size - used, "%s%s", d ? "." : "", c->path[d].key);
        else
            w = snprintf(buf + used, size - used, "[%ld]", c->path[d].index);
        if (w < 0)
            break;
        used += (size_t)w;
    }
    if (!buf[0])
        snprintf(buf, size, "(scene)");
}

ms_status ms_scene_fail(const ms_scene_ctx *c, ms_status st, const char *fmt, ...)
{
    char what[640], where[200];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(what, sizeof what, fmt, ap);
    va_end(ap);
    path_string(c, where, sizeof where);
    for (int k = 0; k < c->nset; ++k) {
        const char *set = c->set[k];
        size_t klen = strcspn(set, "=");
        size_t wlen = strlen(where);
        /* the key the --set names, a key inside its value, or a key its
         * path made (--set volume.nosuch.deeper=1 makes volume.nosuch) */
        if ((strncmp(where, set, klen) == 0 &&
             (where[klen] == '\0' || where[klen] == '.' || where[klen] == '[')) ||
            (wlen < klen && strncmp(where, set, wlen) == 0 &&
             (set[wlen] == '.' || set[wlen] == '[')))
            return ms_fail(st, "--set %s: %s %s", set, where, what);
    }
    size_t pos = 0;
    int line = 1, col = 1;
    ms_scene_locate(c->text, c->len, c->path, c->depth, &pos);
    ms_scene_line_col(c->text, c->len, pos, &line, &col);
    return ms_fail(st, "%s:%d:%d: %s %s", c->file, line, col, where, what);
}

void ms_scene_push_key(ms_scene_ctx *c, const char *key)
{
    /* the schema is at most a few levels deep; deeper paths keep the last slot */
    int d = c->depth < MS_SCENE_MAX_DEPTH ? c->depth : MS_SCENE_MAX_DEPTH - 1;
    c->path[d].key = key;
    c->path[d].index = 0;
    c->depth = d + 1;
}

void ms_scene_push_index(ms_scene_ctx *c, long index)
{
    int d = c->depth < MS_SCENE_MAX_DEPTH ? c->depth : MS_SCENE_MAX_DEPTH - 1;
    c->path[d].key = NULL;
    c->path[d].index = index;
    c->depth = d + 1;
}

void ms_scene_pop(ms_scene_ctx *c)
{
    if (c->depth > 0)
        --c->depth;
}

ms_status ms_scene_check_keys(ms_scene_ctx *c, json_t *obj, const char *const *allowed)
{
    const char *key;
    json_t *v;
    json_object_foreach(obj, key, v)
    {
        int ok = 0;
        for (const char *const *a = allowed; *a; ++a)
            if (strcmp(key, *a) == 0)
                ok = 1;
        if (strcmp(key, "comment") == 0) {
            if (!json_is_string(v)) {
                ms_scene_push_key(c, key);
                ms_status st =
                    ms_scene_fail(c, MS_ERR_PARSE, "is %s; allowed: a string", type_name(v));
                ms_scene_pop(c);
                return st;
            }
            ok = 1;
        }
        if (!ok) {
            char list[400];
            size_t used = 0;
            list[0] = '\0';
            for (const char *const *a = allowed; *a && used < sizeof list; ++a) {
                int w = snprintf(list + used, sizeof list - used, "%s, ", *a);
                if (w < 0)
                    break;
                used += (size_t)w;
            }
            if (used < sizeof list)
                snprintf(list + used, sizeof list - used, "comment");
            /* the key may hold anything (even a NUL via \u0000 is refused by
             * jansson, so it is a C string); quote at most 60 bytes of it */
            static const char *const comment[] = {"comment", NULL};
            const char *near = ms_closest_name(key, allowed);
            near = near ? near : ms_closest_name(key, comment);
            char hint[96] = "";
            if (near)
                snprintf(hint, sizeof hint, " (did you mean \"%s\"?)", near);
            ms_scene_push_key(c, key);
            ms_status st = ms_scene_fail(
                c, MS_ERR_PARSE, "is an unknown key \"%.60s\"%s; allowed: %s", key, hint, list);
            ms_scene_pop(c);
            return st;
        }
    }
    return MS_OK;
}

/* "a number in (lo, hi] unit", or, for a desc field whose range its part
 * checks (lo, hi the float's own), "a number (unit) of float's range". */
static void allowed_text(char *buf, size_t size, double lo, double hi, int lo_open,
                         const char *unit)
{
    if (lo <= -FLT_MAX && hi >= FLT_MAX)
        snprintf(buf, size, "a number%s%s%s within float's range", *unit ? " (" : "", unit,
                 *unit ? ")" : "");
    else
        snprintf(buf, size, "a number in %s%g, %g]%s%s", lo_open ? "(" : "[", lo, hi,
                 *unit ? " " : "", unit);
}

ms_status ms_scene_get_number(ms_scene_ctx *c, json_t *obj, const char *key, double def, double lo,
                              double hi, int lo_open, const char *unit, double *out)
{
    json_t *v = json_object_get(obj, key);
    if (!v) {
        *out = def;
        return MS_OK;
    }
    char allowed[160];
    allowed_text(allowed, sizeof allowed, lo, hi, lo_open, unit);
    ms_scene_push_key(c, key);
    ms_status st = MS_OK;
    if (!json_is_number(v)) {
        st = ms_scene_fail(c, MS_ERR_PARSE, "is %s; allowed: %s", type_name(v), allowed);
    } else {
        double x = json_number_value(v);
        if (!isfinite(x) || x < lo || x > hi || (lo_open && x <= lo))
            st = ms_scene_fail(c, MS_ERR_INVALID_ARGUMENT, "%g%s%s is out of range; allowed: %s", x,
                               *unit ? " " : "", unit, allowed);
        else
            *out = x;
    }
    ms_scene_pop(c);
    return st;
}

ms_status ms_scene_get_float(ms_scene_ctx *c, json_t *obj, const char *key, double def, double lo,
                             double hi, int lo_open, const char *unit, float *out)
{
    double d;
    ms_status st = ms_scene_get_number(c, obj, key, def, lo, hi, lo_open, unit, &d);
    if (st == MS_OK)
        *out = (float)d;
    return st;
}

/* "an integer in [lo, hi]", or "a 32-bit integer" for a desc field whose
 * range its part checks (lo, hi the int's own). */
static void int_text(char *buf, size_t size, long lo, long hi)
{
    if (lo <= INT_MIN && hi >= INT_MAX)
        snprintf(buf, size, "a 32-bit integer");
    else
        snprintf(buf, size, "an integer in [%ld, %ld]", lo, hi);
}

ms_status ms_scene_get_int(ms_scene_ctx *c, json_t *obj, const char *key, long def, long lo,
                           long hi, long *out)
{
    char allowed[80];
    int_text(allowed, sizeof allowed, lo, hi);
    json_t *v = json_object_get(obj, key);
    if (!v) {
        *out = def;
        return MS_OK;
    }
    ms_scene_push_key(c, key);
    ms_status st = MS_OK;
    if (!json_is_integer(v)) {
        st = ms_scene_fail(c, MS_ERR_PARSE, "is %s; allowed: %s", type_name(v), allowed);
    } else {
        json_int_t x = json_integer_value(v);
        if (x < lo || x > hi)
            st = ms_scene_fail(c, MS_ERR_INVALID_ARGUMENT, "%lld is out of range; allowed: %s",
                               (long long)x, allowed);
        else
            *out = (long)x;
    }
    ms_scene_pop(c);
    return st;
}

ms_status ms_scene_get_bool(ms_scene_ctx *c, json_t *obj, const char *key, int def, int *out)
{
    json_t *v = json_object_get(obj, key);
    if (!v) {
        *out = def;
        return MS_OK;
    }
    if (!json_is_boolean(v)) {
        ms_scene_push_key(c, key);
        ms_status st =
            ms_scene_fail(c, MS_ERR_PARSE, "is %s; allowed: true or false", type_name(v));
        ms_scene_pop(c);
        return st;
    }
    *out = json_is_true(v);
    return MS_OK;
}

ms_status ms_scene_get_string(ms_scene_ctx *c, json_t *obj, const char *key, const char *def,
                              const char **out)
{
    json_t *v = json_object_get(obj, key);
    if (!v) {
        *out = def;
        return MS_OK;
    }
    if (!json_is_string(v)) {
        ms_scene_push_key(c, key);
        ms_status st = ms_scene_fail(c, MS_ERR_PARSE, "is %s; allowed: a string", type_name(v));
        ms_scene_pop(c);
        return st;
    }
    *out = json_string_value(v);
    return MS_OK;
}

ms_status ms_scene_get_enum(ms_scene_ctx *c, json_t *obj, const char *key, const char *const *names,
                            int def, int *out)
{
    char list[300];
    size_t used = 0;
    list[0] = '\0';
    for (const char *const *a = names; *a && used < sizeof list; ++a) {
        int w = snprintf(list + used, sizeof list - used, "%s\"%s\"", a == names ? "" : ", ", *a);
        if (w < 0)
            break;
        used += (size_t)w;
    }
    json_t *v = json_object_get(obj, key);
    if (!v) {
        *out = def;
        return MS_OK;
    }
    ms_scene_push_key(c, key);
    ms_status st = MS_OK;
    if (!json_is_string(v)) {
        st = ms_scene_fail(c, MS_ERR_PARSE, "is %s; allowed: one of %s", type_name(v), list);
    } else {
        const char *s = json_string_value(v);
        int found = -1;
        for (int i = 0; names[i]; ++i)
            if (strcmp(s, names[i]) == 0)
                found = i;
        if (found < 0) {
            const char *near = ms_closest_name(s, names);
            char hint[96] = "";
            if (near)
                snprintf(hint, sizeof hint, " (did you mean \"%s\"?)", near);
            st = ms_scene_fail(c, MS_ERR_INVALID_ARGUMENT,
                               "\"%.60s\" is unknown%s; allowed: one of %s", s, hint, list);
        } else
            *out = found;
    }
    ms_scene_pop(c);
    return st;
}

ms_status ms_scene_read_vec(ms_scene_ctx *c, json_t *v, int n, double lo, double hi,
                            const char *unit, float *out)
{
    char allowed[160];
    allowed_text(allowed, sizeof allowed, lo, hi, 0, unit);
    if (!json_is_array(v) || json_array_size(v) != (size_t)n)
        return ms_scene_fail(c, MS_ERR_PARSE, "is %s%s; allowed: an array of %d, each %s",
                             type_name(v), json_is_array(v) ? " of another length" : "", n,
                             allowed);
    for (int i = 0; i < n; ++i) {
        json_t *e = json_array_get(v, (size_t)i);
        ms_scene_push_index(c, i);
        ms_status st = MS_OK;
        if (!json_is_number(e)) {
            st = ms_scene_fail(c, MS_ERR_PARSE, "is %s; allowed: %s", type_name(e), allowed);
        } else {
            double x = json_number_value(e);
            if (!isfinite(x) || x < lo || x > hi)
                st =
                    ms_scene_fail(c, MS_ERR_INVALID_ARGUMENT, "%g%s%s is out of range; allowed: %s",
                                  x, *unit ? " " : "", unit, allowed);
            else
                out[i] = (float)x;
        }
        ms_scene_pop(c);
        if (st != MS_OK)
            return st;
    }
    return MS_OK;
}

ms_status ms_scene_get_vec(ms_scene_ctx *c, json_t *obj, const char *key, int n, const float *def,
                           double lo, double hi, const char *unit, float *out)
{
    json_t *v = json_object_get(obj, key);
    if (!v) {
        if (def)
            memcpy(out, def, sizeof *out * (size_t)n);
        return MS_OK;
    }
    ms_scene_push_key(c, key);
    ms_status st = ms_scene_read_vec(c, v, n, lo, hi, unit, out);
    ms_scene_pop(c);
    return st;
}

ms_status ms_scene_get_ivec(ms_scene_ctx *c, json_t *obj, const char *key, int n, const int *def,
                            long lo, long hi, int *out)
{
    char allowed[80];
    int_text(allowed, sizeof allowed, lo, hi);
    json_t *v = json_object_get(obj, key);
    if (!v) {
        if (def)
            memcpy(out, def, sizeof *out * (size_t)n);
        return MS_OK;
    }
    ms_scene_push_key(c, key);
    ms_status st = MS_OK;
    if (!json_is_array(v) || json_array_size(v) != (size_t)n) {
        st = ms_scene_fail(c, MS_ERR_PARSE, "is %s%s; allowed: an array of %d, each %s",
                           type_name(v), json_is_array(v) ? " of another length" : "", n, allowed);
    }
    for (int i = 0; st == MS_OK && i < n; ++i) {
        json_t *e = json_array_get(v, (size_t)i);
        ms_scene_push_index(c, i);
        if (!json_is_integer(e))
            st = ms_scene_fail(c, MS_ERR_PARSE, "is %s; allowed: %s", type_name(e), allowed);
        else if (json_integer_value(e) < lo || json_integer_value(e) > hi)
            st = ms_scene_fail(c, MS_ERR_INVALID_ARGUMENT, "%lld is out of range; allowed: %s",
                               (long long)json_integer_value(e), allowed);
        else
            out[i] = (int)json_integer_value(e);
        ms_scene_pop(c);
    }
    ms_scene_pop(c);
    return st;
}

ms_status ms_scene_get_object(ms_scene_ctx *c, json_t *obj, const char *key, json_t **out)
{
    json_t *v = json_object_get(obj, key);
    *out = NULL;
    if (!v)
        return MS_OK;
    if (!json_is_object(v)) {
        ms_scene_push_key(c, key);
        ms_status st =
            ms_scene_fail(c, MS_ERR_PARSE, "is %s; allowed: an object {...}", type_name(v));
        ms_scene_pop(c);
        return st;
    }
    *out = v;
    return MS_OK;
}

ms_status ms_scene_get_array(ms_scene_ctx *c, json_t *obj, const char *key, size_t min, size_t max,
                             json_t **out)
{
    json_t *v = json_object_get(obj, key);
    *out = NULL;
    if (!v)
        return MS_OK;
    ms_status st = MS_OK;
    ms_scene_push_key(c, key);
    if (!json_is_array(v))
        st = ms_scene_fail(c, MS_ERR_PARSE, "is %s; allowed: an array [...] of %zu to %zu elements",
                           type_name(v), min, max);
    else if (json_array_size(v) < min || json_array_size(v) > max)
        st = ms_scene_fail(c, MS_ERR_INVALID_ARGUMENT,
                           "has %zu elements; allowed: %zu to %zu elements", json_array_size(v),
                           min, max);
    else
        *out = v;
    ms_scene_pop(c);
    return st;
}

ms_status ms_scene_require(ms_scene_ctx *c, json_t *obj, const char *key, const char *what)
{
    if (json_object_get(obj, key))
        return MS_OK;
    return ms_scene_fail(c, MS_ERR_INVALID_ARGUMENT, "lacks the required key \"%s\" (%s)", key,
                         what);
}
