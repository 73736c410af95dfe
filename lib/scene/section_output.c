/* The "output" section of the scene schema: which fields a run file
 * holds, how often, how compressed (the table of data/scenes/README.md;
 * keep both in step). */
#include <string.h>

#include "core/core_internal.h"
#include "scene/reader.h"
#include "scene/scene_internal.h"
#include "scene/sections.h"

ms_status ms_scene_read_output(ms_scene_ctx *c, json_t *root, ms_scene *sc)
{
    static const char *const keys[] = {"fields", "every", "deflate", "checkpoint_every", NULL};
    static const char *const names[] = {"combined", "surface", "volume", "particles", NULL};
    json_t *o, *fields;
    long every, deflate, checkpoint_every;
    sc->output_fields = MS_FIELD_COMBINED;
    sc->output_every = 1;
    sc->output_deflate = 1;
    sc->output_checkpoint_every = 1;
    MS_TRY(ms_scene_get_object(c, root, "output", &o));
    if (!o)
        return MS_OK;
    ms_scene_push_key(c, "output");
    MS_TRY(ms_scene_check_keys(c, o, keys));
    MS_TRY(ms_scene_get_int(c, o, "every", 1, 1, 1000000, &every));
    sc->output_every = (int)every;
    MS_TRY(ms_scene_get_int(c, o, "deflate", 1, 0, 9, &deflate));
    sc->output_deflate = (int)deflate;
    /* a snapshot of the sim every n-th written frame, 0 = none */
    MS_TRY(ms_scene_get_int(c, o, "checkpoint_every", 1, 0, 1000000, &checkpoint_every));
    sc->output_checkpoint_every = (int)checkpoint_every;
    MS_TRY(ms_scene_get_array(c, o, "fields", 0, 16, &fields));
    if (fields) {
        sc->output_fields = 0;
        ms_scene_push_key(c, "fields");
        for (size_t i = 0; i < json_array_size(fields); ++i) {
            json_t *e = json_array_get(fields, i);
            ms_scene_push_index(c, (long)i);
            int k = -1;
            for (int j = 0; names[j] && json_is_string(e); ++j)
                if (strcmp(json_string_value(e), names[j]) == 0)
                    k = j;
            if (k < 0)
                return ms_scene_fail(
                    c, json_is_string(e) ? MS_ERR_INVALID_ARGUMENT : MS_ERR_PARSE,
                    "is not a field name; allowed: \"combined\", \"surface\", \"volume\", "
                    "\"particles\"");
            if ((k == 1 && !sc->has_surface) || ((k == 2 || k == 3) && !sc->has_volume))
                return ms_scene_fail(c, MS_ERR_INVALID_ARGUMENT,
                                     "\"%s\" needs a \"%s\" section; allowed: fields of the "
                                     "parts the scene has",
                                     names[k], k == 1 ? "surface" : "volume");
            sc->output_fields |= 1u << k;
            ms_scene_pop(c);
        }
        ms_scene_pop(c);
    }
    ms_scene_pop(c);
    return MS_OK;
}
