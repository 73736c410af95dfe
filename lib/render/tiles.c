/* The pool's tile texture: one square tile with a rounded bevel and its
 * grout line, repeated over the floor, the walls and the deck. Luminance,
 * multiplied by the tile colour in the pool's shader. */
#include <math.h>

#include "core/core_internal.h"
#include "render/render_internal.h"

void ms_tile_texture(int size, unsigned char *texels)
{
    const float grout = 0.06f; /* half-width of the grout line, in tiles */
    const float bevel = 0.05f; /* width of the darkening bevel inside it */
    for (int j = 0; j < size; ++j) {
        float v = ((float)j + 0.5f) / (float)size;
        float dv = MS_MIN(v, 1.0f - v); /* distance to the nearest edge */
        for (int i = 0; i < size; ++i) {
            float u = ((float)i + 0.5f) / (float)size;
            float d = MS_MIN(dv, MS_MIN(u, 1.0f - u));
            float lum;
            if (d < grout)
                lum = 0.50f;
            else if (d < grout + bevel)
                lum = 0.78f + 0.2f * (d - grout) / bevel;
            else
                lum = 0.98f;
            texels[(size_t)j * (size_t)size + (size_t)i] = (unsigned char)lrintf(255.0f * lum);
        }
    }
}
