/* The parameter table of a shipped shader plugin (header-only, like
 * params.h and shader.h): one row per scene key gives its components
 * (1 = float, 3 = vec3), default, range and unit; the GLSL uniform it sets
 * is "<plugin>_<key>". A plugin's create and set_uniforms are then one
 * call each, and adding a parameter is one row plus its GLSL uniform.
 *
 *     static const shader_param table[] = {
 *         {"color", 3, {0.02f, 0.28f, 0.33f}, 0.0, 1.0, ""},
 *         {"ior", 1, {1.333f}, 1.0, 3.0, ""},
 *         {NULL, 0, {0}, 0, 0, NULL},
 *     };
 */
#ifndef MS_PLUGINS_SHADER_PARAMS_H
#define MS_PLUGINS_SHADER_PARAMS_H

#include "params.h"
#include "shader.h"

typedef struct shader_param {
    const char *key; /* NULL ends the table */
    int n;           /* 1 or 3 floats */
    float def[3];
    double lo, hi;
    const char *unit;
} shader_param;

/* Enough for every shipped shader; a longer table is a programming error
 * the plugin's own test catches (create answers MS_PLUGIN_ERR_PARSE). */
#define SHADER_MAX_PARAMS 8

/* Parses json against table into the shader's self: the values packed in
 * table order as floats. Unknown keys, wrong types and values out of range
 * fail with params.h's sentence naming the key. */
static inline int shader_params_create(const shader_param *table, const char *json, void **out,
                                       char *err, size_t err_size)
{
    const char *keys[SHADER_MAX_PARAMS + 1];
    float v[3 * SHADER_MAX_PARAMS];
    int k = 0;
    for (; table[k].key; ++k) {
        if (k == SHADER_MAX_PARAMS) {
            snprintf(err, err_size, "more than %d shader parameters", SHADER_MAX_PARAMS);
            return MS_PLUGIN_ERR_PARSE;
        }
        keys[k] = table[k].key;
    }
    keys[k] = NULL;
    size_t at = 0;
    params pm;
    if (params_open(&pm, json, keys, err, err_size) == MS_PLUGIN_OK) {
        for (int i = 0; table[i].key; ++i) {
            const shader_param *p = &table[i];
            if (p->n == 3)
                params_vec(&pm, p->key, 3, v + at, p->def, p->lo, p->hi, p->unit);
            else
                v[at] = params_number(&pm, p->key, p->def[0], p->lo, p->hi, p->unit);
            at += (size_t)p->n;
        }
    }
    int rc = params_close(&pm);
    if (rc != MS_PLUGIN_OK)
        return rc;
    return shader_keep(v, at * sizeof v[0], out, err, err_size);
}

/* Sets "<prefix>_<key>" for each row from self (shader_params_create's). */
static inline void shader_params_set(const char *prefix, const shader_param *table,
                                     const void *self, const ms_shader_uniforms *u)
{
    const float *v = self;
    for (int i = 0; table[i].key; ++i) {
        char name[64];
        snprintf(name, sizeof name, "%s_%s", prefix, table[i].key);
        if (table[i].n == 3)
            u->set_vec3(u->ctx, name, v[0], v[1], v[2]);
        else
            u->set_float(u->ctx, name, v[0]);
        v += table[i].n;
    }
}

#endif
