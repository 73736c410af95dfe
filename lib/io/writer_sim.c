/* lib/io: ms_writer_open / ms_writer_frame, the public writer on an
 * ms_sim. Reads the sim's grids (ms_sim_field_grid), scene (text, name,
 * frame_dt, output.every) and views (fields, particles, time) and hands
 * them to the raw writer (writer.c).
 */
#include <string.h>

#include "io/io_internal.h"

/* Does the sim hold this part? (Its grids exist from creation on; its
 * views only after the first step.) */
static int sim_has(const ms_sim *sim, unsigned bit)
{
    ms_grid g;
    unsigned grid_of = bit == MS_FIELD_PARTICLES ? MS_FIELD_VOLUME : bit;
    return ms_sim_field_grid(sim, grid_of, &g) == MS_OK;
}

/* The layout of sim's run file with `fields` (0: the scene's). */
static ms_status sim_layout(const ms_sim *sim, unsigned fields, ms_writer_layout *out)
{
    ms_status st;
    if ((st = ms_check_not_null("io", "sim", sim)) != MS_OK)
        return st;
    const ms_scene *sc = ms_sim_scene(sim);
    if (fields == 0)
        fields = sc ? ms_scene_output_fields(sc) : MS_FIELD_COMBINED;
    if (fields & ~(unsigned)MS_IO_ALL_FIELDS)
        return ms_fail(MS_ERR_INVALID_ARGUMENT,
                       "io: fields 0x%x has bits other than MS_FIELD_COMBINED, _SURFACE, "
                       "_VOLUME and _PARTICLES",
                       fields);
    static const char *const part[4] = {"combined", "surface (the sim has no surface)",
                                        "volume (the sim has no volume)",
                                        "particles (the sim has no volume)"};
    ms_writer_layout l = {0};
    l.fields = fields;
    for (int i = 0; i < 4; ++i) {
        unsigned bit = 1u << i;
        if (!(fields & bit))
            continue;
        if (!sim_has(sim, bit))
            return ms_fail(MS_ERR_INVALID_ARGUMENT, "io: cannot write the field %s", part[i]);
        if (i < MS_IO_NFIELDS && (st = ms_sim_field_grid(sim, bit, &l.grid[i])) != MS_OK)
            return st;
    }
    l.scene_text = sc ? ms_scene_text(sc) : NULL;
    l.scene_name = sc ? ms_scene_name(sc) : NULL;
    l.scene_path = sc ? ms_scene_path(sc) : NULL;
    l.frame_dt = sc ? ms_scene_frame_dt(sc) : 0.0;
    l.output_every = sc ? ms_scene_output_every(sc) : 1;
    l.deflate = sc ? ms_scene_output_deflate(sc) : 1;
    l.checkpoint_every = sc ? ms_scene_output_checkpoint_every(sc) : 1;
    ms_sim_info info = ms_sim_info_init();
    ms_sim_get_info(sim, &info);
    l.floaters = info.floaters;  /* fig10's leaves, every frame */
    if (info.spray_budget > 0) { /* spray in flight and the foam, every frame */
        if ((st = ms_sim_foam_grid(sim, &l.foam)) != MS_OK)
            return st;
        l.spray = info.spray_budget;
    }
    *out = l;
    return MS_OK;
}

ms_status ms_writer_open(const char *path, const ms_sim *sim, unsigned fields, ms_writer **out)
{
    ms_status st;
    if ((st = ms_check_not_null("io", "out", out)) != MS_OK)
        return st;
    *out = NULL;
    ms_writer_layout l;
    if ((st = sim_layout(sim, fields, &l)) != MS_OK)
        return st;
    return ms_writer_open_layout(path, &l, out);
}

ms_status ms_writer_existing(const char *path, const ms_sim *sim, char *name, size_t size,
                             int *exists)
{
    ms_status st;
    if ((st = ms_check_not_null("io", "exists", exists)) != MS_OK)
        return st;
    *exists = 0;
    ms_writer_layout l;
    if ((st = sim_layout(sim, 0, &l)) != MS_OK)
        return st;
    return ms_writer_existing_layout(path, &l, name, size, exists);
}

ms_status ms_writer_open_append(const char *path, const ms_sim *sim, unsigned fields,
                                ms_writer **out)
{
    ms_status st;
    if ((st = ms_check_not_null("io", "out", out)) != MS_OK)
        return st;
    *out = NULL;
    ms_writer_layout l;
    if ((st = sim_layout(sim, fields, &l)) != MS_OK)
        return st;
    return ms_writer_open_append_layout(path, &l, out);
}

ms_status ms_writer_frame(ms_writer *w, const ms_sim *sim)
{
    ms_status st;
    if ((st = ms_check_not_null("io", "writer", w)) != MS_OK ||
        (st = ms_check_not_null("io", "sim", sim)) != MS_OK)
        return st;
    const ms_writer_layout *l = ms_writer_get_layout(w);
    ms_writer_data d = {0};
    d.time = ms_sim_time(sim);
    for (int i = 0; i < MS_IO_NFIELDS; ++i) {
        if (!(l->fields & (1u << i)))
            continue;
        int nx = 0, ny = 0;
        d.field[i] = i == MS_IO_COMBINED  ? ms_sim_height(sim, &nx, &ny)
                     : i == MS_IO_SURFACE ? ms_sim_surface_height(sim, &nx, &ny)
                                          : ms_sim_volume_height(sim, &nx, &ny);
        if (!d.field[i])
            return ms_fail(MS_ERR_STATE,
                           "io: the sim has published no %s field yet (step it before writing "
                           "a frame)",
                           ms_io_field_names[i]);
        if (nx != l->grid[i].nx || ny != l->grid[i].ny)
            return ms_fail(MS_ERR_STATE,
                           "io: the sim's %s field is %d x %d, the file's %d x %d: not the sim "
                           "the writer was opened with",
                           ms_io_field_names[i], nx, ny, l->grid[i].nx, l->grid[i].ny);
    }
    if (l->fields & MS_FIELD_PARTICLES) {
        int n = 0;
        if ((st = ms_sim_particles(sim, &n, d.pos, d.vel)) != MS_OK)
            return st;
        d.particles = n;
    }
    if (l->floaters > 0) {
        int n = 0;
        d.floaters = ms_sim_floaters(sim, &n);
        if (!d.floaters || n != l->floaters)
            return ms_fail(MS_ERR_STATE, "io: the sim shows %d floaters, the file holds %d", n,
                           l->floaters);
    }
    if (l->spray > 0) {
        int nx = 0, ny = 0;
        d.spray_xyz = ms_sim_spray(sim, &d.spray);
        d.foam = ms_sim_foam(sim, &nx, &ny);
        if (!d.spray_xyz || nx != l->foam.nx || ny != l->foam.ny)
            return ms_fail(MS_ERR_STATE, "io: the sim's spray is not the file's");
    }
    /* the sim's whole state with every checkpoint_every-th frame */
    if (l->checkpoint_every > 0 && ms_writer_frames(w) % l->checkpoint_every == 0) {
        size_t bytes = 0;
        void *buf = NULL;
        if ((st = ms_sim_snapshot_size(sim, &bytes)) != MS_OK)
            return st;
        if (!(buf = ms_writer_checkpoint_buffer(w, bytes)))
            return ms_fail(MS_ERR_OUT_OF_MEMORY, "io: out of memory for a checkpoint of %zu bytes",
                           bytes);
        if ((st = ms_sim_snapshot(sim, buf, bytes, &d.checkpoint_bytes)) != MS_OK)
            return st;
        d.checkpoint = buf;
    }
    return ms_writer_write(w, &d);
}
