/* ms_scene: a scene file (JSON, see data/scenes/README.md) turned into the
 * descs of the parts it calls for. A section that is absent is an effect
 * that is not simulated and costs nothing. Errors name file:line:col, the
 * key and what is allowed.
 */
#ifndef MODESPLIT_SCENE_H
#define MODESPLIT_SCENE_H

#include "core.h"
#include "surface.h"
#include "volume.h"

#ifdef __cplusplus
extern "C" {
#endif

MS_API ms_status ms_scene_load(const char *path, ms_scene **out);
MS_API ms_status ms_scene_parse(const char *json, size_t len, ms_scene **out);
MS_API void ms_scene_destroy(ms_scene *sc);

MS_API const char *ms_scene_name(const ms_scene *sc);
MS_API const char *ms_scene_text(const ms_scene *sc);       /* the JSON text as loaded */
MS_API const char *ms_scene_path(const ms_scene *sc);       /* file it came from; "" when parsed */
MS_API double ms_scene_duration(const ms_scene *sc);        /* s */
MS_API float ms_scene_frame_dt(const ms_scene *sc);         /* s */
MS_API unsigned ms_scene_output_fields(const ms_scene *sc); /* MS_FIELD_* bits asked for */
MS_API int ms_scene_output_every(const ms_scene *sc);       /* write every n-th frame, >= 1 */
MS_API int ms_scene_output_deflate(const ms_scene *sc);     /* 0..9, 0 = no compression */
MS_API int ms_scene_has_render(const ms_scene *sc);         /* a `render` section exists */

/* A scene with overrides "KEY=VALUE" of keys by their dotted path
 * ("volume.spacing=0.025", "surface.cells=[512,512]",
 * "obstacles[0].position=[1,2,0.5]"); VALUE is JSON, or else a string
 * ("volume.pressure=tait"). The same type and range checks as the file
 * apply; an error at an overridden key names "--set KEY=VALUE" (an unknown
 * key lists the allowed ones). The file alone must be valid. The scene text
 * (ms_scene_text) is the merged JSON, listing the overrides under
 * "overrides". n = 0 is ms_scene_load / ms_scene_parse. */
MS_API ms_status ms_scene_load_with_overrides(const char *path, int n, const char *const *overrides,
                                              ms_scene **out);
MS_API ms_status ms_scene_parse_with_overrides(const char *json, size_t len, int n,
                                               const char *const *overrides, ms_scene **out);

/* The parts' descs a scene's keys make, for an engine that wants a file's
 * settings without the sim (ms_sim_create_from_scene uses the same): each
 * started from its *_desc_default(), each key of the section setting the
 * field of its name (volume.spacing -> ms_volume_desc.spacing;
 * surface.cells -> nx, ny; dx = the domain's x extent / cells[0]), and
 * checked by the part's ms_*_desc_check when the scene was read.
 * MS_ERR_STATE when the scene has no such section (out untouched); out is
 * written up to its .size (core.h: struct sizes): start from the
 * *_desc_default(). ms_scene_sim_desc is in sim.h, the renderer's
 * (ms_scene_renderer_desc) in render.h. */
MS_API ms_status ms_scene_volume_desc(const ms_scene *sc, ms_volume_desc *out);
MS_API ms_status ms_scene_surface_desc(const ms_scene *sc, ms_surface_desc *out);

/* output.checkpoint_every: a snapshot of the sim (ms_sim_snapshot) goes
 * into the run file with every n-th written frame, 0 = none; default 1. */
MS_API int ms_scene_output_checkpoint_every(const ms_scene *sc);

#ifdef __cplusplus
}
#endif

#endif /* MODESPLIT_SCENE_H */
