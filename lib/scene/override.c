/* Scene overrides: `--set KEY=VALUE` of `modesplit run|check` and the cases
 * of `modesplit accuracy` change scene keys by their dotted path
 * ("volume.spacing=0.025", "surface.cells=[512,512]",
 * "obstacles[0].position=[1,2,0.5]"). VALUE is JSON; a VALUE that is not
 * JSON is taken as a string ("volume.pressure=tait").
 *
 * The overrides are applied to the JSON tree, which is then read by the same
 * schema (sections.c) as a file, so the same type and range checks apply; a
 * failure at an overridden key names "--set KEY=VALUE" (reader.c). The
 * merged scene text lists the overrides under the top-level key
 * "overrides", so the scene stored in a run file (`modesplit info --scene`)
 * says how it was made.
 */
#include <stdlib.h>
#include <string.h>

#include <jansson.h>

#include "core/core_internal.h"
#include "scene/override.h"

#define MAX_KEY 256

/* One element of a dotted path: a key, or an index when key is NULL. */
typedef struct {
    char key[MAX_KEY];
    int is_index;
    long index;
} elem;

static int is_key_char(char ch)
{
    return (ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') || (ch >= '0' && ch <= '9') ||
           ch == '_';
}

/* Split "a.b[2].c" (klen bytes) into elements; 0 on success. */
static int split_key(const char *k, size_t klen, elem *out, int max, int *n)
{
    size_t i = 0;
    *n = 0;
    while (i < klen) {
        if (*n == max)
            return -1;
        elem *e = &out[*n];
        if (k[i] == '[') {
            char *end;
            long idx = strtol(k + i + 1, &end, 10);
            if (end == k + i + 1 || (size_t)(end - k) >= klen || *end != ']' || idx < 0)
                return -1;
            e->is_index = 1;
            e->index = idx;
            i = (size_t)(end - k) + 1;
        } else {
            if (*n > 0) {
                if (k[i] != '.')
                    return -1;
                ++i;
            }
            size_t j = i;
            while (j < klen && is_key_char(k[j]))
                ++j;
            if (j == i || j - i >= MAX_KEY)
                return -1;
            e->is_index = 0;
            memcpy(e->key, k + i, j - i);
            e->key[j - i] = '\0';
            i = j;
        }
        ++*n;
    }
    return *n > 0 && !out[0].is_index ? 0 : -1;
}

/* Put value (a new reference, stolen) at the path of `set` in root. */
static ms_status put(json_t *root, const char *set, size_t klen, json_t *value)
{
    elem path[16];
    int n;
    if (split_key(set, klen, path, 16, &n) != 0) {
        json_decref(value);
        return ms_fail(MS_ERR_INVALID_ARGUMENT,
                       "--set %s: \"%.*s\" is not a scene key; allowed: a dotted path such as "
                       "volume.spacing or obstacles[0].position",
                       set, (int)klen, set);
    }
    json_t *node = root;
    for (int d = 0; d < n; ++d) {
        const elem *e = &path[d];
        int last = d == n - 1;
        if (e->is_index) {
            if (!json_is_array(node) || (size_t)e->index >= json_array_size(node)) {
                json_decref(value);
                return ms_fail(MS_ERR_INVALID_ARGUMENT,
                               "--set %s: [%ld] is past the end; allowed: an index of an "
                               "array the scene has (%zu elements)",
                               set, e->index, json_is_array(node) ? json_array_size(node) : 0);
            }
            if (last)
                return json_array_set_new(node, (size_t)e->index, value) == 0
                           ? MS_OK
                           : ms_fail(MS_ERR_OUT_OF_MEMORY, "--set %s: out of memory", set);
            node = json_array_get(node, (size_t)e->index);
            continue;
        }
        if (!json_is_object(node)) {
            json_decref(value);
            return ms_fail(MS_ERR_INVALID_ARGUMENT,
                           "--set %s: \"%s\" is inside a value that is not an object; allowed: "
                           "keys of the scene's sections",
                           set, e->key);
        }
        if (last)
            return json_object_set_new(node, e->key, value) == 0
                       ? MS_OK
                       : ms_fail(MS_ERR_OUT_OF_MEMORY, "--set %s: out of memory", set);
        json_t *child = json_object_get(node, e->key);
        if (!child) {
            /* a section the scene does not have: created, then read (and
             * checked) as if the file had it */
            child = path[d + 1].is_index ? json_array() : json_object();
            if (!child || json_object_set_new(node, e->key, child) != 0) {
                json_decref(value);
                return ms_fail(MS_ERR_OUT_OF_MEMORY, "--set %s: out of memory", set);
            }
        }
        node = child;
    }
    json_decref(value);
    return ms_fail(MS_ERR_INVALID_ARGUMENT, "--set %s: empty key", set);
}

ms_status ms_scene_override_check(const char *set)
{
    if (!set)
        return ms_fail(MS_ERR_INVALID_ARGUMENT, "--set: the override is NULL");
    const char *eq = strchr(set, '=');
    if (!eq || eq == set)
        return ms_fail(MS_ERR_INVALID_ARGUMENT,
                       "--set %s: not KEY=VALUE; allowed: e.g. volume.spacing=0.025", set);
    return MS_OK;
}

ms_status ms_scene_apply_overrides(const char *text, size_t len, int n, const char *const *set,
                                   char **out, size_t *out_len)
{
    *out = NULL;
    *out_len = 0;
    json_error_t err;
    json_t *root = json_loadb(text, len, JSON_REJECT_DUPLICATES, &err);
    if (!root || !json_is_object(root)) {
        json_decref(root);
        return ms_fail(MS_ERR_PARSE, "--set: the scene is not a JSON object");
    }
    json_t *list = json_object_get(root, "overrides");
    if (!list) {
        list = json_array();
        if (!list || json_object_set_new(root, "overrides", list) != 0) {
            json_decref(root);
            return ms_fail(MS_ERR_OUT_OF_MEMORY, "--set: out of memory");
        }
    } else if (!json_is_array(list)) {
        json_decref(root);
        return ms_fail(MS_ERR_PARSE,
                       "--set: the scene's \"overrides\" is not an array; allowed: the list of "
                       "KEY=VALUE strings a run was made with");
    }
    for (int i = 0; i < n; ++i) {
        ms_status st = ms_scene_override_check(set[i]);
        if (st != MS_OK) {
            json_decref(root);
            return st;
        }
        const char *eq = strchr(set[i], '=');
        /* "overrides" is the record of the --set a run was made with: a
         * --set that replaced it would free the list appended to below */
        const size_t klen = (size_t)(eq - set[i]), olen = strlen("overrides");
        if (klen >= olen && strncmp(set[i], "overrides", olen) == 0 &&
            (klen == olen || set[i][olen] == '.' || set[i][olen] == '[')) {
            json_decref(root);
            return ms_fail(MS_ERR_INVALID_ARGUMENT,
                           "--set %s: \"overrides\" is the list of KEY=VALUE strings a run was "
                           "made with, written by the tool; allowed: keys of the scene's sections",
                           set[i]);
        }
        json_t *value = json_loads(eq + 1, JSON_DECODE_ANY | JSON_REJECT_DUPLICATES, &err);
        if (!value)
            value = json_string(eq + 1);
        if (!value) {
            json_decref(root);
            return ms_fail(MS_ERR_INVALID_ARGUMENT,
                           "--set %s: the value is neither JSON nor UTF-8 text", set[i]);
        }
        st = put(root, set[i], (size_t)(eq - set[i]), value);
        if (st == MS_OK && json_array_append_new(list, json_string(set[i])) != 0)
            st = ms_fail(MS_ERR_INVALID_ARGUMENT, "--set %s: not UTF-8 text", set[i]);
        if (st != MS_OK) {
            json_decref(root);
            return st;
        }
    }
    /* 17 significant digits: every number reads back as the same double */
    *out = ms_json_text(root, JSON_INDENT(2) | JSON_PRESERVE_ORDER | JSON_REAL_PRECISION(17));
    json_decref(root);
    if (!*out)
        return ms_fail(MS_ERR_OUT_OF_MEMORY, "--set: out of memory writing the merged scene");
    *out_len = strlen(*out);
    return MS_OK;
}
