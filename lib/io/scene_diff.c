/* lib/io: what differs between two scene texts, key by key (the sentence
 * of a refused resume). A scene written with --set overrides is
 * stored re-printed (17 significant digits, other spacing), so a line diff
 * would name formatting; this compares the parsed JSON values and names the
 * dotted paths whose values differ, with both values. */
#include <jansson.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "io/io_internal.h"

typedef struct diff_out {
    char *buf;
    size_t size, len;
    int count; /* paths named */
} diff_out;

#define MAX_NAMED 3
#define VALUE_CHARS 60

static void value_text(const json_t *v, char *buf, size_t n)
{
    if (!v) {
        snprintf(buf, n, "(absent)");
        return;
    }
    char *s =
        ms_json_text(v, JSON_COMPACT | JSON_SORT_KEYS | JSON_ENCODE_ANY | JSON_REAL_PRECISION(9));
    snprintf(buf, n, "%s", s ? s : "?");
    if (s && strlen(s) >= n && n > 4)
        memcpy(buf + n - 4, "...", 4);
    ms_free(s);
}

static void name_path(diff_out *o, const char *path, const json_t *a, const json_t *b)
{
    if (o->count++ >= MAX_NAMED)
        return;
    char va[VALUE_CHARS], vb[VALUE_CHARS];
    value_text(a, va, sizeof va);
    value_text(b, vb, sizeof vb);
    int n = snprintf(o->buf + o->len, o->size - o->len, "%s%s is %s in the file, %s here",
                     o->count > 1 ? "; " : "", path[0] ? path : "(the whole scene)", va, vb);
    if (n > 0)
        o->len += (size_t)n < o->size - o->len ? (size_t)n : o->size - o->len - 1;
}

static int cmp_str(const void *x, const void *y)
{
    return strcmp(*(const char *const *)x, *(const char *const *)y);
}

static void walk(diff_out *o, const char *path, const json_t *a, const json_t *b);

static void walk_object(diff_out *o, const char *path, const json_t *a, const json_t *b)
{
    /* the union of both keys, sorted: the sentence is the same every time */
    size_t n = json_object_size(a) + json_object_size(b), k = 0;
    const char **keys = ms_alloc_array(n ? n : 1, sizeof *keys);
    if (!keys) {
        name_path(o, path, a, b);
        return;
    }
    const char *key;
    json_t *v;
    json_object_foreach((json_t *)a, key, v) keys[k++] = key;
    json_object_foreach((json_t *)b, key, v) if (!json_object_get(a, key)) keys[k++] = key;
    qsort(keys, k, sizeof *keys, cmp_str);
    for (size_t i = 0; i < k; ++i) {
        char sub[256];
        snprintf(sub, sizeof sub, "%s%s%s", path, path[0] ? "." : "", keys[i]);
        walk(o, sub, json_object_get(a, keys[i]), json_object_get(b, keys[i]));
    }
    ms_free(keys);
}

static void walk(diff_out *o, const char *path, const json_t *a, const json_t *b)
{
    if (a && b && json_is_object(a) && json_is_object(b)) {
        walk_object(o, path, a, b);
        return;
    }
    if (a && b && json_is_array(a) && json_is_array(b) &&
        json_array_size(a) == json_array_size(b)) {
        for (size_t i = 0; i < json_array_size(a); ++i) {
            char sub[256];
            snprintf(sub, sizeof sub, "%s[%zu]", path, i);
            walk(o, sub, json_array_get(a, i), json_array_get(b, i));
        }
        return;
    }
    /* numbers compare by value: 1 and 1.0 and 0.016667 re-printed are the same */
    if (a && b && json_is_number(a) && json_is_number(b) &&
        json_number_value(a) == json_number_value(b))
        return;
    if (a && b && json_equal((json_t *)a, (json_t *)b))
        return;
    name_path(o, path, a, b);
}

int ms_io_scene_diff(const char *file_text, const char *this_text, char *buf, size_t size)
{
    if (size == 0)
        return -1;
    buf[0] = '\0';
    json_t *a = json_loads(file_text, JSON_DECODE_ANY, NULL);
    json_t *b = json_loads(this_text, JSON_DECODE_ANY, NULL);
    int count = -1;
    if (a && b) {
        diff_out o = {buf, size, 0, 0};
        walk(&o, "", a, b);
        if (o.count > MAX_NAMED)
            snprintf(buf + o.len, size - o.len, "; and %d more", o.count - MAX_NAMED);
        count = o.count;
    }
    json_decref(a);
    json_decref(b);
    return count;
}
