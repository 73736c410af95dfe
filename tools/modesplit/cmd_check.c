/* modesplit check SCENE.json...: validate scenes without running them.
 * Each is parsed (unknown keys, wrong types, ranges: the error names
 * file:line:col and the key) and its sim is built (so a scene that cannot
 * be allocated or made stable is refused too); nothing is stepped. */
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
        ms_stats st = ms_stats_init();
        ms_sim_get_stats(sim, &st);
        char fields[64], mem[32];
        printf("%s: ok: \"%s\", %.4g s in %ld frames of %.4g s, writes %s every %d frame%s, "
               "%s of state%s\n",
               argv[i], ms_scene_name(sc), ms_scene_duration(sc), frames,
               ms_scene_frame_dt(sc), field_list(ms_scene_output_fields(sc), fields, sizeof fields),
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
