/* plugin.h: the plugin ABI of libmodesplit (collision shapes and shaders),
 * and the calls a program uses to list and load plugins.
 *
 * WRITING A PLUGIN
 *
 * A plugin is a self-contained shared object that exports one symbol,
 *
 *     const ms_plugin_info *ms_plugin_entry(void);     (MS_PLUGIN_ENTRY_SYMBOL)
 *
 * returning a pointer to static, constant data:
 *
 *     #include <modesplit/plugin.h>
 *
 *     static float ball_distance(const void *self, const float p[3], float n[3]) {
 *         float r = *(const float *)self, l = sqrtf(p[0]*p[0] + p[1]*p[1] + p[2]*p[2]);
 *         if (n) { ... outward unit normal ... }
 *         return l - r;                            // m, negative inside
 *     }
 *     ... ball_create, ball_destroy, ball_bounds ...
 *     static const ms_shape_vtable ball_vt = {
 *         .size = sizeof(ms_shape_vtable), .create = ball_create,
 *         .destroy = ball_destroy, .distance = ball_distance, .bounds = ball_bounds};
 *     static const ms_plugin_info ball_info = {
 *         .abi = MS_PLUGIN_ABI, .size = sizeof(ms_plugin_info), .name = "ball",
 *         .version = "1.0", .kind = MS_PLUGIN_SHAPE,
 *         .description = "a ball", .vtable = &ball_vt};
 *     const ms_plugin_info *ms_plugin_entry(void) { return &ball_info; }
 *
 * and is built with
 *
 *     cc -shared -fPIC $(pkg-config --cflags modesplit) ball.c -o ball.so -lm
 *
 * It must not call libmodesplit (the plugins shipped with the library are
 * linked with -Wl,--no-undefined against libc, libm, jansson and libpng
 * only), so it loads into any host: the tool, an engine, a statically
 * linked program. Its memory comes from the host (ABI 1.1): the loader
 * calls its set_host with the host's allocator before any create, and it
 * allocates its instances with host->alloc_fn, so an engine's allocator
 * (ms_set_allocator) sees them:
 *
 *     static const ms_plugin_host *host;
 *     static void ball_set_host(const ms_plugin_host *h) { host = h; }
 *     ... in ball_create:  float *r = host->alloc_fn(sizeof *r);
 *     ... in ball_destroy: host->free_fn(self);
 *     ... and in ball_info: .set_host = ball_set_host Drop it into a directory of MODESPLIT_PLUGIN_PATH or the
 * install's lib/modesplit/plugins, or load it with ms_plugin_load().
 *
 * THE ABI RULES
 *
 * - ms_plugin_info starts with `abi` (MS_PLUGIN_ABI = major << 16 | minor)
 *   and `size` (sizeof the struct the plugin was built with); every vtable
 *   starts with its own `size`. The loader reads abi and size first and
 *   refuses the plugin before reading any other field when the major
 *   differs, the minor is newer than the host's, or a size is smaller than
 *   the struct of ABI 1.0 (a truncated or zero-size struct).
 * - Structs only grow at the end (a new field bumps the minor; the loader
 *   treats a field past the plugin's `size` as absent/NULL). Removing or
 *   reordering a field bumps the major.
 * - ABI 1.1 added ms_plugin_info.set_host (the host's allocator); a plugin
 *   of 1.0 (without it) still loads and allocates on its own.
 * - Enums are 32-bit (uint32_t fields).
 * - Names are [a-z0-9_-], 1..31 characters, unique across loaded plugins of
 *   all kinds.
 *
 * HOW THE LIBRARY FINDS PLUGINS
 *
 * Lazily, on the first ms_shape_create() or listing call (a program that
 * uses no plugin pays nothing), every *.so file of these directories is
 * loaded with dlopen(RTLD_NOW | RTLD_LOCAL), in this order:
 *   1. the directories of MODESPLIT_PLUGIN_PATH (colon-separated);
 *   2. the install's plugin directory: <libdir>/modesplit/plugins, where
 *      <libdir> holds the loaded libmodesplit.so (found with dladdr); for a
 *      program linked with the static library, <exe dir>/../lib/modesplit/plugins;
 *   3. the build tree's plugins/ directory (compiled into the library).
 * Files of one directory load in name order. A name found earlier wins:
 * a plugin in MODESPLIT_PLUGIN_PATH overrides an installed one of the same
 * name, which overrides the build tree's. A file that fails to load during
 * the scan is closed and skipped; ms_plugin_problem() reports why.
 * The registry is guarded by a mutex: every call here is thread-safe.
 * Plugins stay loaded until the process ends.
 */
#ifndef MODESPLIT_PLUGIN_H
#define MODESPLIT_PLUGIN_H

#include <stddef.h>
#include <stdint.h>

#include "core.h"

#ifdef __cplusplus
extern "C" {
#endif

#define MS_PLUGIN_ABI_MAJOR 1u
#define MS_PLUGIN_ABI_MINOR 1u
#define MS_PLUGIN_ABI ((MS_PLUGIN_ABI_MAJOR << 16) | MS_PLUGIN_ABI_MINOR)
#define MS_PLUGIN_ENTRY_SYMBOL "ms_plugin_entry"
/* Longest plugin name, without the terminating NUL. */
#define MS_PLUGIN_NAME_MAX 31

/* Put in front of the plugin's ms_plugin_entry definition. */
#if defined(__GNUC__) || defined(__clang__)
#define MS_PLUGIN_EXPORT __attribute__((visibility("default")))
#else
#define MS_PLUGIN_EXPORT
#endif

/* ms_plugin_info.kind */
enum {
    MS_PLUGIN_SHAPE = 1u, /* vtable is a const ms_shape_vtable * */
    MS_PLUGIN_SHADER = 2u /* vtable is a const ms_shader_vtable * */
};

/* The host's side of the ABI (1.1): its allocator, handed to a plugin by
 * ms_plugin_info.set_host. Valid while the plugin is loaded; both
 * functions are thread-safe. */
typedef struct ms_plugin_host {
    uint32_t size; /* sizeof(ms_plugin_host) of the host; only grows */
    /* size bytes aligned for any type (64 bytes), or NULL when out of
     * memory; the engine's allocator when it set one (ms_set_allocator) */
    void *(*alloc_fn)(size_t size);
    void (*free_fn)(void *p); /* a block of alloc_fn, or NULL */
} ms_plugin_host;

/* What ms_plugin_entry returns. Static, constant, valid while loaded. */
typedef struct ms_plugin_info {
    uint32_t abi;            /* MS_PLUGIN_ABI of the headers it was built with */
    uint32_t size;           /* sizeof(ms_plugin_info) it was built with */
    const char *name;        /* "sphere": the kind name users ask for */
    const char *version;     /* the plugin's own version, free text ("1.0") */
    uint32_t kind;           /* MS_PLUGIN_SHAPE or MS_PLUGIN_SHADER */
    const char *description; /* one line, for listings */
    const void *vtable;      /* the kind's vtable; starts with uint32_t size */
    /* --- ABI 1.1 (past a 1.0 plugin's size: absent) --- */
    /* Optional (NULL: the plugin allocates nothing, or on its own). Called
     * once by the loader, after the checks and before any create, with
     * the host's allocator. */
    void (*set_host)(const ms_plugin_host *host);
} ms_plugin_info;

typedef const ms_plugin_info *(*ms_plugin_entry_fn)(void);
/* The one symbol a plugin defines (and the host never does). */
MS_PLUGIN_EXPORT const ms_plugin_info *ms_plugin_entry(void);

/* Status codes a plugin's create returns (the values of ms_status). */
#define MS_PLUGIN_OK 0
#define MS_PLUGIN_ERR_INVALID_ARGUMENT (-1) /* a parameter is out of range */
#define MS_PLUGIN_ERR_OUT_OF_MEMORY (-2)
#define MS_PLUGIN_ERR_IO (-4)    /* a file named in the parameters */
#define MS_PLUGIN_ERR_PARSE (-5) /* the JSON text or a key's type */

/* ---- collision shapes ------------------------------------------------ */

/* A shape works in its LOCAL frame (metres); the library applies the pose
 * (a translation and a velocity, ms_shape_set_pose). All functions but
 * create/destroy must be thread-safe for concurrent calls on one instance
 * (they only read it). */
typedef struct ms_shape_vtable {
    uint32_t size; /* sizeof(ms_shape_vtable) */
    /* params_json: a JSON object text (NULL: all defaults). Unknown keys,
     * wrong types and out-of-range values fail with a sentence naming the
     * key, written to err (err_size bytes, NUL-terminated), e.g.
     * "radius -1 m must be > 0". Returns MS_PLUGIN_OK and *out, or an error. */
    int (*create)(const char *params_json, void **out, char *err, size_t err_size);
    void (*destroy)(void *self);
    /* Signed distance (m, negative inside) from local point p to the
     * surface; if normal != NULL, the outward unit normal there, smoothed
     * around hard edges so that it is continuous (paper Fig. 5, eq. 15). */
    float (*distance)(const void *self, const float p[3], float normal[3]);
    /* Local bounding box (m). Use +-1e30f for unbounded directions. */
    void (*bounds)(const void *self, float lo[3], float hi[3]);
    /* Optional (NULL: the library marches down the distance field): the
     * height (m, local) of the shape's topmost surface above local column
     * (x, y); returns 1 and sets *top, or 0 if the column holds no
     * material. Terrain gives its exact height here. */
    int (*height_at)(const void *self, float x, float y, float *top);
} ms_shape_vtable;

/* ---- shaders --------------------------------------------------------- */

/* The passes a shader needs; the renderer runs only those (flags). */
enum {
    /* the environment cubemap ms_env, for reflected rays */
    MS_SHADER_NEEDS_REFLECTION = 1u << 0,
    /* the liquid is see-through: refracted rays look up ms_env too (the
     * paper's cubemap refraction, section 3.6) and meet the pool floor at
     * ms_floor_z */
    MS_SHADER_NEEDS_REFRACTION = 1u << 1,
    /* the caustics light map ms_caustics (light traced through the surface
     * by Snell's law onto the floor), computed each frame */
    MS_SHADER_NEEDS_CAUSTICS = 1u << 2
};

/* How a shader sets its uniforms without linking GL: the renderer passes
 * this table; each call sets the uniform of that name in the bound program
 * (a name the program lacks is ignored). */
typedef struct ms_shader_uniforms {
    uint32_t size; /* sizeof(ms_shader_uniforms) */
    void *ctx;     /* the renderer's, passed back to each call */
    void (*set_float)(void *ctx, const char *name, float v);
    void (*set_vec3)(void *ctx, const char *name, float x, float y, float z);
    void (*set_int)(void *ctx, const char *name, int v);
    void (*set_vec4)(void *ctx, const char *name, float x, float y, float z, float w);
} ms_shader_uniforms;

/* The contract between the renderer and a shader's source, GLSL 1.20
 * (what Mesa's llvmpipe/OSMesa compiles; the legacy built-ins exist):
 *   attributes: gl_Vertex (world position, m), gl_Normal (world unit
 *     normal of the liquid surface); gl_ModelViewProjectionMatrix maps
 *     world to clip space;
 *   uniforms the renderer sets (a shader declares those it uses):
 *     vec3  ms_eye          eye position, world (m)
 *     vec3  ms_light_dir    unit vector towards the light, world
 *     vec3  ms_light_color  linear RGB
 *     float ms_time         s since the start
 *     vec4  ms_viewport     width, height, 1/width, 1/height (pixels)
 *     samplerCube ms_env    environment cubemap, texture unit 0 (with
 *                           MS_SHADER_NEEDS_REFLECTION or _REFRACTION);
 *                           alpha 1, but 0 on an object under the water
 *                           already lit through ms_caustics (with
 *                           _CAUSTICS): the floor's light map is not for it
 *     vec3  ms_env_refracted_eye  where ms_env's downward half is drawn
 *                           from (world, m): the direction from it to the
 *                           point a refracted ray meets looks that point up
 *     float ms_floor_z      height of the pool floor (m)
 *     vec4  ms_pool         x0, y0, size x, size y of the pool (m)
 *     sampler2D ms_caustics caustics light map over ms_pool, texture unit 1,
 *                           1 = unfocused light (with _CAUSTICS)
 *     sampler2D ms_normal_map the full height field's gradient (dh/dx,
 *                           dh/dy) in .rg, texel (i, j) at cell (i, j)'s
 *                           centre, bilinear, texture unit 2: per-pixel
 *                           normals normalize(vec3(-g, 1)) while the mesh
 *                           (gl_Normal) may be coarser than the field
 *     vec4  ms_field        x0, y0, 1/size x, 1/size y of the field (m):
 *                           ms_normal_map's coordinate is
 *                           (pos.xy - ms_field.xy) * ms_field.zw
 *     sampler2D ms_caustics_walls  the caustics on the pool's four walls
 *                           under the still water, texture unit 3: strips
 *                           -x, +x, -y, +y stacked along t (strip k in
 *                           [k/4, (k+1)/4], from the floor up); along s
 *                           the x-walls run with y, the y-walls with x;
 *                           in ms_caustics' unit (with _CAUSTICS)
 *     float ms_pool_depth   still water depth over the floor the strips
 *                           span (m); 0 when the walls were not traced
 *     float ms_caustics_wall_rows  texel rows of one strip
 *     sampler2D ms_foam     foam cover in [0, 1] in .r (the sim's spray,
 *                           ms_renderer_set_foam), texture unit 4; its
 *                           coordinate is (pos.xy - ms_foam_field.xy) *
 *                           ms_foam_field.zw (vec4 ms_foam_field, as
 *                           ms_field); float ms_foam_on 1 when there is
 *                           foam, else 0 (a shader may ignore all three)
 *     float ms_side         1 while the side of the liquid in a glass is
 *                           drawn (a vertical wall: shade with gl_Normal,
 *                           which the renderer sets for it), else 0
 *   the shader's own uniforms (colours, ...) it sets in set_uniforms.
 * The fragment shader writes gl_FragColor (linear RGB, alpha 1).
 * A vertex shader that writes gl_ClipVertex = gl_Vertex (the world
 * position, as the shipped ones do) has the surface cut where the liquid
 * is dry (less than 1 mm deep): nothing of it is
 * drawn there and the floor is seen directly. One that does not is drawn
 * everywhere, a zero-depth sheet over dry floor included. */
typedef struct ms_shader_vtable {
    uint32_t size;               /* sizeof(ms_shader_vtable) */
    uint32_t passes;             /* MS_SHADER_NEEDS_* bits */
    const char *vertex_source;   /* GLSL 1.20 vertex shader */
    const char *fragment_source; /* GLSL 1.20 fragment shader */
    /* Optional (NULL: no parameters, self is NULL; then destroy is NULL
     * too). params_json as for shapes (colours, ...; NULL: defaults). */
    int (*create)(const char *params_json, void **out, char *err, size_t err_size);
    void (*destroy)(void *self);
    /* Called with the program bound, once per draw. */
    void (*set_uniforms)(const void *self, const ms_shader_uniforms *u);
} ms_shader_vtable;

/* ---- host side: listing and loading (programs, not plugins) ----------- */

/* One registered plugin, as listed by `modesplit plugins`. The strings
 * stay valid until the process ends. */
typedef struct ms_plugin_description {
    uint32_t size;       /* sizeof, set by ms_plugin_description_init() (core.h: struct sizes) */
    const char *name;    /* "sphere" */
    const char *kind;    /* "shape" or "shader" */
    const char *version; /* the plugin's version */
    const char *description; /* one line */
    const char *path;        /* the file it was loaded from */
    uint32_t abi;            /* the ABI it was built with */
} ms_plugin_description;
static inline ms_plugin_description ms_plugin_description_init(void)
{
    ms_plugin_description x = MS_ZERO_INIT;
    x.size = (uint32_t)sizeof x;
    return x;
}

/* Number of registered plugins (scans the search path on first use). */
MS_API int ms_plugin_count(void);
/* The i-th plugin, 0 <= i < ms_plugin_count(), sorted by kind then name. */
MS_API ms_status ms_plugin_describe(int i, ms_plugin_description *out);
/* Load one plugin file explicitly (after the search path scan). Fails with
 * MS_ERR_PLUGIN and a sentence naming the file (and symbol) when the file is
 * not a shared object, lacks ms_plugin_entry, has a wrong ABI, a truncated
 * info or vtable, or a name already registered; the file is closed and the
 * registry is unchanged. MS_ERR_IO when the file cannot be read. */
MS_API ms_status ms_plugin_load(const char *path);
/* Problems met while scanning the search path (files skipped, names
 * shadowed by an earlier directory): count, then one sentence each. */
MS_API int ms_plugin_problem_count(void);
MS_API const char *ms_plugin_problem(int i);
/* The directories searched, in order, as one colon-separated string
 * (for listings and error messages). */
MS_API const char *ms_plugin_search_path(void);

#ifdef __cplusplus
}
#endif

#endif /* MODESPLIT_PLUGIN_H */
