/* ms_renderer: OSMesa off-screen rendering of the combined height field
 * (paper section 3.6): cubemap reflection and refraction mixed by Fresnel,
 * a caustics light map from Snell's law, shader plugins (water, milk, oil).
 * Every call returns MS_ERR_UNSUPPORTED in a build without OSMesa.
 */
#ifndef MODESPLIT_RENDER_H
#define MODESPLIT_RENDER_H

#include "core.h"
#include "scene.h"
#include "sim.h"

#ifdef __cplusplus
extern "C" {
#endif

MS_API ms_status ms_renderer_create(const ms_scene *sc, ms_renderer **out);
MS_API void ms_renderer_destroy(ms_renderer *r);
MS_API ms_status ms_renderer_draw(ms_renderer *r, const ms_sim *sim);
/* RGBA8, top row first; view valid until the next draw. */
MS_API const unsigned char *ms_renderer_pixels(const ms_renderer *r, int *w, int *h);
MS_API ms_status ms_renderer_write_png(const ms_renderer *r, const char *path);

#ifdef __cplusplus
}
#endif

#endif /* MODESPLIT_RENDER_H */
