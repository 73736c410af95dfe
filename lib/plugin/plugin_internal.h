/* lib/plugin: the plugin loader and registry (internal).
 *
 * Owns: opening and checking one plugin file (loader.c: ELF check, dlopen,
 * entry symbol, ABI major/minor, struct sizes, vtable contents), the search
 * path (search.c: MODESPLIT_PLUGIN_PATH, the install directory found with
 * dladdr, the build tree), and the registry of loaded plugins by name
 * (registry.c: the library's only global mutable state besides the
 * thread-local error sentence, guarded by a mutex; the first scan runs
 * once, lazily, under pthread_once).
 *
 * Implements no equation of the paper: it is how collision objects (eq. 15)
 * and shaders (section 3.6) reach the library.
 */
#ifndef MS_PLUGIN_INTERNAL_H
#define MS_PLUGIN_INTERNAL_H

#include "modesplit/plugin.h"

/* A plugin that passed every check. The info and vtable are copies: the
 * fields the plugin's (smaller, older) structs lack are zero/NULL. */
typedef struct ms_plugin_rec {
    void *handle; /* from dlopen */
    char *path;   /* the file, as given */
    ms_plugin_info info;
    union {
        ms_shape_vtable shape;
        ms_shader_vtable shader;
    } vt;
} ms_plugin_rec;

/* Open and check one file. On success *out is a new record (ms_malloc'd: ms_free it);
 * on failure the library is dlclose()d and the error sentence names the
 * file (and the symbol) and what is wrong. */
ms_status ms_plugin_open(const char *path, ms_plugin_rec **out);

/* The ms_status of a plugin create's return code (MS_PLUGIN_ERR_* are the
 * ms_status values; anything else is MS_ERR_PLUGIN). */
ms_status ms_plugin_status(int rc);

/* The kind's name: "shape", "shader", "unknown". */
const char *ms_plugin_kind_name(uint32_t kind);

/* The registered plugin `name` of `kind` (scans first if needed). Fails
 * with MS_ERR_PLUGIN and a sentence listing the plugins of that kind that
 * are available, prefixed by `part` ("shape: no shape plugin named ..."). */
ms_status ms_plugin_find(const char *part, const char *name, uint32_t kind,
                         const ms_plugin_rec **out);

/* The search path as a colon-separated list (ms_malloc'd, ms_free it; NULL when out of
 * memory): the directories of `env` (MODESPLIT_PLUGIN_PATH, may be NULL),
 * then the install's plugin directory derived from `object_path` (the file
 * holding libmodesplit's code: <dir>/modesplit/plugins for a shared
 * library, a file whose name contains ".so"; <dir>/../lib/modesplit/plugins
 * for an executable; skipped if NULL), then `build_dir` (may be NULL). */
char *ms_plugin_compose_search_path(const char *env, const char *object_path,
                                    const char *build_dir);

/* The search path of this process (env, dladdr, MS_BUILD_PLUGIN_DIR). */
char *ms_plugin_default_search_path(void);

/* A shader plugin made ready for a renderer: its vtable (the sources, the
 * passes, set_uniforms) and its instance (self, for set_uniforms). */
typedef struct ms_shader_instance {
    const ms_plugin_rec *plugin;
    const ms_shader_vtable *vt;
    void *self;
} ms_shader_instance;

/* Finds the shader plugin `name` and creates an instance from its
 * parameters (JSON object text, NULL = defaults). Errors name the shader
 * and the key ("shader water: ior 0.5 is outside [1, 3]"). */
ms_status ms_shader_instance_create(const char *name, const char *params_json,
                                    ms_shader_instance *out);
void ms_shader_instance_destroy(ms_shader_instance *in);

#endif /* MS_PLUGIN_INTERNAL_H */
