/* modesplit info [--scene] RUN.h5: what a run file holds.
 * modesplit info --build: what this build of the library is. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include <jansson.h>

#include "tool.h"

static void field_line(ms_reader *r, unsigned bit, const char *name, long frames)
{
    ms_grid g;
    if (ms_reader_field_grid(r, bit, &g) != MS_OK)
        return;
    uint64_t stored = 0, raw = 0;
    ms_reader_field_bytes(r, bit, &stored, &raw);
    char sb[32];
    printf("  %-9s %d x %d cells of %.4g x %.4g mm, origin (%g, %g) m, %s on disk", name, g.nx,
           g.ny, 1e3 * g.dx, 1e3 * g.dy, g.origin[0], g.origin[1],
           tool_bytes((double)stored, sb, sizeof sb));
    if (stored > 0 && raw > 0)
        printf(" (%.1fx smaller than raw)", (double)raw / (double)stored);
    if (frames > 0) {
        size_t n = (size_t)g.nx * (size_t)g.ny;
        float *h = malloc(n * sizeof *h);
        if (h && ms_reader_read_field(r, bit, frames - 1, h, n) == MS_OK) {
            double lo = INFINITY, hi = -INFINITY;
            size_t bad = 0;
            for (size_t i = 0; i < n; ++i) {
                if (!isfinite(h[i])) {
                    ++bad;
                    continue;
                }
                lo = h[i] < lo ? h[i] : lo;
                hi = h[i] > hi ? h[i] : hi;
            }
            if (bad < n)
                printf(", last frame in [%.4g, %.4g] m", lo, hi);
            if (bad)
                printf(", %zu non-finite values", bad);
        } else if (h) {
            {
                printf(", last frame unreadable: ");
                tool_put_escaped(stdout, ms_last_error(), "");
            }
        }
        free(h);
    }
    printf("\n");
}

/* The compiler, the volume's instruction-set paths built and run here,
 * and the one a volume takes (ms_get_build_info). */
static int build_info(void)
{
    ms_build_info b;
    ms_status st = ms_get_build_info(&b);
    printf("library   %s\n", ms_version());
    printf("compiler  %s\n", b.compiler);
    printf("paths     %s (built)\n", b.paths_built);
    printf("          %s (this CPU)\n", b.paths_cpu);
    if (st != MS_OK) {
        tool_error("%s", ms_last_error());
        return EXIT_USAGE;
    }
    printf("chosen    %s%s\n", b.path_chosen,
           getenv("MODESPLIT_ISA") && *getenv("MODESPLIT_ISA") ? " (MODESPLIT_ISA)" : " (widest)");
    return EXIT_OK;
}

int cmd_info(int argc, char **argv)
{
    const char *path = NULL;
    int scene_only = 0;
    for (int i = 1; i < argc; ++i) {
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) {
            tool_command_usage(stdout, "info");
            return EXIT_OK;
        }
        if (!strcmp(argv[i], "--build")) {
            return build_info();
        } else if (!strcmp(argv[i], "--scene")) {
            scene_only = 1;
        } else if (argv[i][0] == '-' && argv[i][1]) {
            tool_unknown_option("info", argv[i]);
            return EXIT_USAGE;
        } else if (path) {
            tool_error("info: one run file at a time (got %s and %s)", path, argv[i]);
            return EXIT_USAGE;
        } else {
            path = argv[i];
        }
    }
    if (!path) {
        tool_error("info: which run file? usage: modesplit info [--scene] RUN.h5");
        return EXIT_USAGE;
    }
    ms_reader *r;
    if (ms_reader_open(path, &r) != MS_OK) {
        tool_error("%s", ms_last_error());
        return EXIT_USAGE;
    }
    if (scene_only) {
        const char *s = ms_reader_scene(r);
        tool_put_escaped(stdout, s, "\n\t");
        if (*s && s[strlen(s) - 1] != '\n')
            fputc('\n', stdout);
        ms_reader_close(r);
        return EXIT_OK;
    }
    long frames = ms_reader_frames(r);
    unsigned fields = ms_reader_fields(r);
    printf("%s: modesplit run file, format %d, written by libmodesplit ", path,
           ms_reader_format_version(r));
    tool_put_escaped(
        stdout, *ms_reader_library_version(r) ? ms_reader_library_version(r) : "(unknown)", "");
    printf("\n");
    const char *name = ms_reader_scene_name(r);
    printf("  scene     ");
    tool_put_escaped(stdout, *name ? name : "(unnamed)", "");
    printf(", %zu bytes of JSON", strlen(ms_reader_scene(r)));
    double dt = ms_reader_frame_dt(r);
    if (isfinite(dt))
        printf(", frame_dt %.6g s", dt);
    int every = ms_reader_output_every(r);
    if (every > 1)
        printf(", written every %d frames", every);
    printf("\n");
    /* the --set overrides the run was made with (lib/scene/override.c) */
    json_t *root = json_loads(ms_reader_scene(r), 0, NULL);
    json_t *ovr = root ? json_object_get(root, "overrides") : NULL;
    for (size_t k = 0; json_is_array(ovr) && k < json_array_size(ovr); ++k)
        if (json_is_string(json_array_get(ovr, k))) {
            printf("  --set     ");
            tool_put_escaped(stdout, json_string_value(json_array_get(ovr, k)), "");
            printf("\n");
        }
    json_decref(root);
    if (frames > 0) {
        double t0 = NAN, t1 = NAN;
        ms_reader_time(r, 0, &t0);
        ms_reader_time(r, frames - 1, &t1);
        printf("  frames    %ld, t = %.6g .. %.6g s\n", frames, t0, t1);
    } else {
        printf("  frames    0\n");
    }
    static const unsigned bits[3] = {MS_FIELD_COMBINED, MS_FIELD_SURFACE, MS_FIELD_VOLUME};
    static const char *const names[3] = {"combined", "surface", "volume"};
    if (!(fields & (MS_FIELD_COMBINED | MS_FIELD_SURFACE | MS_FIELD_VOLUME)))
        printf("  fields    none\n");
    else
        printf("  fields    (float32 [frame][y][x], m)\n");
    for (int i = 0; i < 3; ++i)
        if (fields & bits[i])
            field_line(r, bits[i], names[i], frames);
    if (fields & MS_FIELD_PARTICLES) {
        int n0 = 0, n1 = 0;
        if (frames > 0 && ms_reader_particle_count(r, 0, &n0) == MS_OK &&
            ms_reader_particle_count(r, frames - 1, &n1) == MS_OK)
            printf("  particles H5Part /Step#0 .. /Step#%ld, %d in the first, %d in the last\n",
                   frames - 1, n0, n1);
        else if (frames > 0) {
            printf("  particles unreadable: ");
            tool_put_escaped(stdout, ms_last_error(), "");
            printf("\n");
        }
    }
    struct stat sb;
    char buf[32];
    if (stat(path, &sb) == 0)
        printf("  file      %s\n", tool_bytes((double)sb.st_size, buf, sizeof buf));
    ms_reader_close(r);
    return EXIT_OK;
}
