/* modesplit cubemap --out DIR [--size N] [--sun X,Y,Z]: writes the builtin
 * procedural sky (sun, horizon gradient, clouds, a lawn and a tree line)
 * as six PNG faces a scene's render.cubemap loads (data/cubemaps/ holds
 * ones made so). --sun is the direction the sunlight travels (z < 0: from
 * above), as the scene's render.caustics.light. */
#include <stdlib.h>
#include <string.h>

#include "tool.h"

int cmd_cubemap(int argc, char **argv)
{
    const char *out = NULL;
    long size = 512;
    float sun[3] = {0.3f, 0.2f, -1.0f};
    for (int i = 1; i < argc; ++i) {
        const char *a = argv[i], *v = NULL;
        int bad = 0;
        if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
            tool_command_usage(stdout, "cubemap");
            return EXIT_OK;
        } else if (tool_opt_value(argc, argv, &i, "--out", &v, &bad)) {
            if (bad || !v[0]) {
                tool_error("cubemap: --out needs a directory");
                return EXIT_USAGE;
            }
            out = v;
        } else if (tool_opt_value(argc, argv, &i, "--size", &v, &bad)) {
            if (bad || !tool_parse_long(v, 16, 4096, &size)) {
                tool_error("cubemap: --size %s: give texels per face side in [16, 4096]",
                           v ? v : "");
                return EXIT_USAGE;
            }
        } else if (tool_opt_value(argc, argv, &i, "--sun", &v, &bad)) {
            double x, y, z;
            char tail;
            if (bad || sscanf(v, "%lf,%lf,%lf%c", &x, &y, &z, &tail) != 3 ||
                !(x * x + y * y + z * z > 1e-12) || !(x * x + y * y + z * z < 1e12)) {
                tool_error("cubemap: --sun %s: give X,Y,Z, the direction sunlight travels "
                           "(finite, not all 0)",
                           v ? v : "");
                return EXIT_USAGE;
            }
            sun[0] = (float)x, sun[1] = (float)y, sun[2] = (float)z;
        } else {
            tool_error("cubemap: unknown argument %s (see modesplit --help)", a);
            return EXIT_USAGE;
        }
    }
    if (!out) {
        tool_error("cubemap: where to? usage: modesplit cubemap --out DIR [--size N] "
                   "[--sun X,Y,Z]");
        return EXIT_USAGE;
    }
    ms_status st = ms_sky_write_cubemap(out, (int)size, sun);
    if (st != MS_OK) {
        tool_error("cubemap: %s", ms_last_error());
        return st == MS_ERR_INVALID_ARGUMENT ? EXIT_USAGE : EXIT_RUNTIME;
    }
    printf("wrote the sky cubemap (6 faces of %ld x %ld) to %s\n", size, size, out);
    return EXIT_OK;
}
