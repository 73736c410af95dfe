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

#include "modesplit/plugin.h"

/* The renderer's surface mesh gives world positions and normals; every
 * shipped fragment program shades from the interpolated pair. */
#define SHADER_VERTEX_SOURCE                                                                    \
    "#version 120\n"                                                                            \
    "varying vec3 v_pos;\n"                                                                     \
    "varying vec3 v_normal;\n"                                                                  \
    "void main()\n"                                                                             \
    "{\n"                                                                                       \
    "    v_pos = gl_Vertex.xyz;\n"                                                              \
    "    v_normal = gl_Normal;\n"                                                               \
    "    gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;\n"                             \
    "}\n"

/* A heap copy of the size bytes of parsed parameters at parsed, in *out
 * (the shader's self); MS_PLUGIN_ERR_OUT_OF_MEMORY with err set if none. */
static inline int shader_keep(const void *parsed, size_t size, void **out, char *err,
                              size_t err_size)
{
    void *p = malloc(size);
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
    free(self);
}

#endif
