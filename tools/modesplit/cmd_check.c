/* modesplit check SCENE.json...: validate scenes without running them.
 * Each is parsed (unknown keys, wrong types, ranges: the error names
 * file:line:col and the key) and its sim is built (so a scene that cannot
 * be allocated or made stable is refused too), the work of one frame is
 * bounded and the render section checked as the renderer takes it
 * (tool_check_frame_work, which `run` calls too); nothing is stepped. */
#include <math.h>
#include <string.h>

#include "tool.h"

static const char *field_list(unsigned f, char *buf, size_t size)
{
    static const char *const names[4] = {"combined", "surface", "volume", "particles"};
    buf[0] = '\0';
    for (int i = 0; i < 4; ++i)
        if (f & (1u << i)) {
            if (buf[0])
                strncat(buf, ", ", size - strlen(buf) - 1);
            strncat(buf, names[i], size - strlen(buf) - 1);
        }
    return buf[0] ? buf : "none";
}

int tool_check_frame_work(const ms_scene *sc, ms_sim *sim, const char *path)
{
    /* The render section as the renderer would take it (a cubemap's face
     * sizes from the files' headers, every row decoded), so that check
     * refuses what run --png would, and run refuses it before its first
     * frame. */
    if (ms_scene_has_render(sc)) {
        ms_renderer_desc rd = ms_renderer_desc_default();
        if (ms_renderer_desc_from_scene(sc, &rd) != MS_OK || ms_renderer_desc_check(&rd) != MS_OK) {
            tool_error("%s: %s", path, ms_last_error());
            return -1;
        }
    }
    /* The sim splits a frame into N_time wave steps (eq. 19), each within
     * the surface's own sub-step cap, so a domain whose cells are tiny
     * (dx ~ nm) runs ~1e6 sub-steps a frame for hours without an error:
     * hold the frame's whole wave work to the cap the surface gives one
     * step. */
    ms_surface *s = ms_sim_surface(sim);
    if (!s)
        return 0;
    ms_surface_info info = ms_surface_info_init();
    ms_surface_get_info(s, &info);
    ms_surface_desc d = ms_surface_get_desc(s);
    double dt = ms_scene_frame_dt(sc);
    double need = info.max_dt > 0 ? ceil(dt / info.max_dt) : INFINITY;
    if (need <= d.max_substeps)
        return 0;
    tool_error("%s: a frame of %g s needs %.3g wave sub-steps of at most %g s (cells of %g m "
               "at %g m/s); allowed: at most surface.max_substeps = %d a frame: the domain "
               "is too small for %d x %d cells (enlarge the domain or lower surface.cells)",
               path, dt, need, (double)info.max_dt, (double)d.dx, (double)info.max_speed,
               d.max_substeps, d.nx, d.ny);
    return -1;
}

int cmd_check(int argc, char **argv)
{
    int n = 0, bad = 0;
    tool_sets sets = {0};
    for (int i = 1; i < argc; ++i) {
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) {
            tool_command_usage(stdout, "check");
            return EXIT_OK;
        }
        int usage = 0, start = i;
        if (tool_set_option(argc, argv, &i, &sets, &usage)) {
            if (usage)
                return EXIT_USAGE;
            for (int k = start; k <= i; ++k)
                argv[k] = NULL; /* --set and its value are not scenes */
            continue;
        }
        if (argv[i][0] == '-' && argv[i][1]) {
            tool_unknown_option("check", argv[i]);
            return EXIT_USAGE;
        }
    }
    for (int i = 1; i < argc; ++i) {
        if (!argv[i])
            continue;
        ++n;
        ms_scene *sc = NULL;
        if (tool_load_scene(argv[i], &sets, &sc) != 0) {
            ++bad;
            continue;
        }
        long frames;
        if (tool_scene_frames(sc, argv[i], -1, &frames) != 0) {
            ms_scene_destroy(sc);
            ++bad;
            continue;
        }
        ms_sim *sim = NULL;
        if (ms_sim_create_from_scene(sc, 0, &sim) != MS_OK) {
            tool_error("%s: %s", argv[i], ms_last_error());
            ms_scene_destroy(sc);
            ++bad;
            continue;
        }
        if (tool_check_frame_work(sc, sim, argv[i]) != 0) {
            ms_sim_destroy(sim);
            ms_scene_destroy(sc);
            ++bad;
            continue;
        }
        ms_stats st = ms_stats_init();
        ms_sim_get_stats(sim, &st);
        char fields[64], mem[32];
        printf("%s: ok: \"%s\", %.4g s in %ld frames of %.4g s, writes %s every %d frame%s, "
               "%s of state%s\n",
               argv[i], ms_scene_name(sc), ms_scene_duration(sc), frames, ms_scene_frame_dt(sc),
               field_list(ms_scene_output_fields(sc), fields, sizeof fields),
               ms_scene_output_every(sc), ms_scene_output_every(sc) == 1 ? "" : "s",
               tool_bytes((double)st.bytes, mem, sizeof mem),
               ms_scene_has_render(sc) ? ", rendered" : "");
        ms_sim_destroy(sim);
        ms_scene_destroy(sc);
    }
    if (n == 0) {
        tool_error("check: which scenes? usage: modesplit check SCENE.json...");
        return EXIT_USAGE;
    }
    return bad ? EXIT_USAGE : EXIT_OK;
}
