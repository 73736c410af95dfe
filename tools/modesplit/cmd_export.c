/* modesplit export RUN.h5 --usd OUT.usdc [--field NAME]: write a run file
 * as USD (a time-sampled mesh of the height field, time-sampled points of
 * the particles) for Blender, Houdini and Omniverse.
 *
 * USD is written with Pixar's own library (usd-core, `pxr`), which is
 * Python; so this command runs tools/python/modesplit/usd_export.py with
 * python3 (or $MODESPLIT_PYTHON), found beside the tool: the install's
 * share/modesplit/python, or the source tree's tools/python when the tool
 * runs from its build tree (build/bin). */
#define _XOPEN_SOURCE 700 /* realpath */
#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "tool.h"

static const char export_usage[] =
    "usage: modesplit export RUN.h5 --usd OUT.usdc [--field combined|surface|volume]\n"
    "\n"
    "Write a run file as USD: the height field (combined, or --field) as a\n"
    "time-sampled mesh (points, normals, UVs, the file's frame rate) and the\n"
    "particles as time-sampled points with velocities and ids. Needs python3\n"
    "with usd-core (pip install usd-core), h5py and numpy; $MODESPLIT_PYTHON\n"
    "names another interpreter.\n";

/* The directory holding modesplit/usd_export.py, or NULL. */
static char *python_dir(void)
{
    char exe[PATH_MAX];
    ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
    if (n <= 0)
        return NULL;
    exe[n] = '\0';
    char *slash = strrchr(exe, '/');
    if (!slash)
        return NULL;
    *slash = '\0'; /* .../bin */
    static const char *const rel[] = {"/../share/modesplit/python", "/../../tools/python"};
    for (size_t i = 0; i < sizeof rel / sizeof rel[0]; ++i) {
        char p[PATH_MAX + 64], probe[PATH_MAX + 128];
        snprintf(p, sizeof p, "%s%s", exe, rel[i]);
        snprintf(probe, sizeof probe, "%s/modesplit/usd_export.py", p);
        if (access(probe, R_OK) == 0)
            return realpath(p, NULL);
    }
    return NULL;
}

int cmd_export(int argc, char **argv)
{
    const char *run = NULL, *usd = NULL, *field = NULL;
    for (int i = 1; i < argc; ++i) {
        const char *v = NULL, *a = argv[i];
        int bad = 0;
        if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
            tool_command_usage(stdout, "export");
            fputs("\n", stdout);
            fputs(export_usage, stdout);
            return EXIT_OK;
        } else if (tool_opt_value(argc, argv, &i, "--usd", &v, &bad)) {
            if (bad)
                return EXIT_USAGE;
            usd = v;
        } else if (tool_opt_value(argc, argv, &i, "--field", &v, &bad)) {
            if (bad)
                return EXIT_USAGE;
            field = v;
        } else if (a[0] == '-' && a[1]) {
            tool_unknown_option("export", a);
            return EXIT_USAGE;
        } else if (run) {
            tool_error("export: one run file at a time (got %s and %s)", run, a);
            return EXIT_USAGE;
        } else {
            run = a;
        }
    }
    if (!run || !usd || !*usd) {
        tool_error("export: %s; usage: modesplit export RUN.h5 --usd OUT.usdc",
                   !run ? "which run file?" : "--usd OUT.usdc is needed (the USD file to write)");
        return EXIT_USAGE;
    }
    char *dir = python_dir();
    if (!dir) {
        tool_error("export: cannot find modesplit/usd_export.py (looked in share/modesplit/python "
                   "beside the tool and in the source tree); reinstall modesplit");
        return EXIT_RUNTIME;
    }
    /* The script by its path, not `-m modesplit.usd_export`: -m imports the
     * package first, which needs numpy and the C library, so a Python
     * without numpy would stop in a traceback before the script could say
     * what to install. The script itself imports only h5py, numpy and pxr,
     * each behind its own sentence. */
    size_t sn = strlen(dir) + sizeof "/modesplit/usd_export.py";
    char *script = malloc(sn);
    if (!script) {
        free(dir);
        tool_error("export: out of memory");
        return EXIT_RUNTIME;
    }
    snprintf(script, sn, "%s/modesplit/usd_export.py", dir);
    const char *old = getenv("PYTHONPATH");
    size_t n = strlen(dir) + (old ? strlen(old) : 0) + 2;
    char *pp = malloc(n);
    if (!pp) {
        free(dir);
        free(script);
        tool_error("export: out of memory");
        return EXIT_RUNTIME;
    }
    snprintf(pp, n, "%s%s%s", dir, old && *old ? ":" : "", old && *old ? old : "");
    setenv("PYTHONPATH", pp, 1);
    free(pp);
    free(dir);
    const char *py = getenv("MODESPLIT_PYTHON");
    if (!py || !*py)
        py = "python3";
    const char *args[10];
    int k = 0;
    args[k++] = py;
    args[k++] = script;
    args[k++] = run;
    args[k++] = "--usd";
    args[k++] = usd;
    if (field) {
        args[k++] = "--field";
        args[k++] = field;
    }
    args[k] = NULL;
    fflush(stdout);
    fflush(stderr);
    execvp(py, (char *const *)args);
    tool_error("export: cannot run %s: %s (install python3 with usd-core, h5py and numpy, or "
               "set MODESPLIT_PYTHON)",
               py, strerror(errno));
    free(script);
    return EXIT_RUNTIME;
}
