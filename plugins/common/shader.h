/* What the shader plugins shipped with libmodesplit share (header-only, so
 * each stays one self-contained shared object that links no libmodesplit
 * or GL symbol): the vertex program of the surface mesh, and keeping or
 * freeing a plugin's parsed parameters.
 */
#ifndef MS_PLUGINS_SHADER_H
#define MS_PLUGINS_SHADER_H

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "host.h"
#include "modesplit/plugin.h"

/* The renderer's surface mesh gives world positions and normals; every
 * shipped fragment program shades from the interpolated pair. The world
 * position as gl_ClipVertex lets the renderer cut the mesh where the
 * liquid is dry (plugin.h), so a dry floor is seen directly. */
#define SHADER_VERTEX_SOURCE                                        \
    "#version 120\n"                                                \
    "varying vec3 v_pos;\n"                                         \
    "varying vec3 v_normal;\n"                                      \
    "void main()\n"                                                 \
    "{\n"                                                           \
    "    v_pos = gl_Vertex.xyz;\n"                                  \
    "    v_normal = gl_Normal;\n"                                   \
    "    gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;\n" \
    "    gl_ClipVertex = gl_Vertex;\n"                              \
    "}\n"

/* The display transform every shipped fragment program ends with: the
 * program shades in linear light, ms_tonemap compresses what lies above
 * MS_TONEMAP_KNEE (0.6) smoothly towards 1 (a per-channel exponential
 * shoulder, value and slope continuous at the knee), so bright liquid such
 * as milk keeps its shading instead of clipping at white; the renderer's
 * sRGB framebuffer then applies the sRGB curve. Below the knee it is the
 * identity, so water and the pool keep their physical (linear) values.
 * Put it after "#version" in a fragment source. */
#define SHADER_TONEMAP_SOURCE                                                       \
    "vec3 ms_tonemap(vec3 c)\n"                                                     \
    "{\n"                                                                           \
    "    const float knee = 0.6;\n"                                                 \
    "    vec3 x = max(c, vec3(0.0));\n"                                             \
    "    vec3 s = knee + (1.0 - knee) * (1.0 - exp(-(x - knee) / (1.0 - knee)));\n" \
    "    return mix(x, s, step(vec3(knee), x));\n"                                  \
    "}\n"

/* The surface normal at a fragment: the renderer hands every liquid program
 * the full field's gradient (dh/dx, dh/dy) as the texture ms_normal_map
 * (unit 2, bilinear between cell centres) and the field's rectangle as
 * ms_field (origin x, y; 1 / width, 1 / height), so the normal keeps
 * every cell's ripple while the mesh may have a vertex only every few
 * cells (render.h, mesh_step). The side of the liquid in a glass, a
 * vertical wall the renderer draws with ms_side = 1 (else 0), takes the
 * normals it gives with its vertices (gl_glass.c). Put it after "#version";
 * it reads v_pos and v_normal. */
#define SHADER_NORMAL_SOURCE                                                              \
    "uniform sampler2D ms_normal_map;\n"                                                  \
    "uniform vec4 ms_field;\n"                                                            \
    "uniform float ms_side;\n"                                                            \
    "varying vec3 v_pos;\n"                                                               \
    "varying vec3 v_normal;\n"                                                            \
    "vec3 ms_surface_normal()\n"                                                          \
    "{\n"                                                                                 \
    "    vec2 g = texture2D(ms_normal_map, (v_pos.xy - ms_field.xy) * ms_field.zw).rg;\n" \
    "    return ms_side > 0.5 ? normalize(v_normal) : normalize(vec3(-g, 1.0));\n"        \
    "}\n"

/* A heap copy of the size bytes of parsed parameters at parsed, in *out
 * (the shader's self); MS_PLUGIN_ERR_OUT_OF_MEMORY with err set if none. */
static inline int shader_keep(const void *parsed, size_t size, void **out, char *err,
                              size_t err_size)
{
    void *p = plugin_alloc(size);
    if (!p) {
        snprintf(err, err_size, "out of memory");
        return MS_PLUGIN_ERR_OUT_OF_MEMORY;
    }
    memcpy(p, parsed, size);
    *out = p;
    return MS_PLUGIN_OK;
}

/* The vtable's destroy for a shader whose self is one shader_keep copy. */
static inline void shader_free(void *self)
{
    plugin_free(self);
}

#endif
