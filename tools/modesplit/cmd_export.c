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
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/statvfs.h>
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

/* What the export holds in memory (tools/python/modesplit/usd_export.py,
 * its peak RSS measured with /usr/bin/time -f %M: 128 MiB at 64 x 48 cells,
 * 570 MiB at 2048 x 1536, +12 MiB for 184800 particles). A .usdc (or
 * .usd) layer is saved whenever SAVE_BYTES (64 MiB) of time samples wait
 * and keeps what it saved on disk, so the export holds Python with usd-core
 * and numpy, those samples and one frame's arrays, whatever the number of
 * frames. A .usda text layer is written whole at its one save: every time
 * sample is held until then. */
#define EXPORT_BASE_BYTES (192.0 * (1u << 20)) /* Python, usd-core, numpy; SAVE_BYTES */
#define EXPORT_CELL_PEAK 160.0    /* a frame's heights, points, normals and their temporaries */
#define EXPORT_PARTICLE_PEAK 96.0 /* a step's six arrays, ids and their USD copies */
#define EXPORT_MAX_BYTES (16.0 * (1u << 30))
/* What the USD file holds per frame: a point and a normal (float3 each) a
 * cell, a position, a velocity (float3) and an int64 id a particle, and
 * some bookkeeping per time code and attribute. */
#define EXPORT_CELL_BYTES 24.0
#define EXPORT_PARTICLE_BYTES 32.0
#define EXPORT_FRAME_BYTES 4096.0

static double export_bound(void)
{
    long pages = sysconf(_SC_PHYS_PAGES), size = sysconf(_SC_PAGESIZE);
    double half = pages > 0 && size > 0 ? 0.5 * (double)pages * (double)size : EXPORT_MAX_BYTES;
    return half < EXPORT_MAX_BYTES ? half : EXPORT_MAX_BYTES;
}

/* Bytes free to this user in the folder of `usd`; INFINITY when unknown. */
static double free_bytes(const char *usd)
{
    char *dir = strdup(usd);
    if (!dir)
        return INFINITY;
    char *slash = strrchr(dir, '/');
    if (slash)
        slash[slash == dir ? 1 : 0] = '\0';
    struct statvfs vb;
    double avail =
        statvfs(slash ? dir : ".", &vb) == 0 ? (double)vb.f_bavail * (double)vb.f_frsize : INFINITY;
    free(dir);
    return avail;
}

/* The file written would not fit in the folder's free space: refused. */
static int refuse_disk(const char *run, const char *usd, long frames, const ms_grid *g,
                       double particles, double write)
{
    double avail = free_bytes(usd);
    if (write <= avail)
        return 0;
    char a[32], b[32];
    char parts[64] = "";
    if (particles > 0)
        snprintf(parts, sizeof parts, " and %.0f particles", particles);
    tool_error("export: %s: %ld frames of a %d x %d field%s would write about %s to %s; its "
               "folder has %s free, so it is refused",
               run, frames, g->nx, g->ny, parts, tool_bytes(write, a, sizeof a), usd,
               tool_bytes(avail, b, sizeof b));
    return EXIT_USAGE;
}

/* The memory the export needs (`need`) over this machine's bound: refused
 * with `what` needs it. */
static int refuse_memory(const char *run, const char *what, double need)
{
    double bound = export_bound();
    if (need <= bound)
        return 0;
    char a[32], b[32];
    tool_error("export: %s: %s would need about %s of memory; this machine's bound is %s (half "
               "its memory, at most 16 GiB), so it is refused",
               run, what, tool_bytes(need, a, sizeof a), tool_bytes(bound, b, sizeof b));
    return EXIT_USAGE;
}

/* The export's memory (one frame of g's cells and `most` particles; for a
 * .usda the whole file) and the file it writes (`write` bytes, of `total`
 * particles) against their bounds. 0, or an exit status after a message. */
static int check_size(const char *run, const char *usd, int text, long frames, const ms_grid *g,
                      int most, double total, double write)
{
    char what[200];
    int at = snprintf(what, sizeof what, "one frame of a %d x %d field", g->nx, g->ny);
    if (most > 0)
        snprintf(what + at, sizeof what - (size_t)at, " and %d particles", most);
    int rc = refuse_memory(run, what,
                           EXPORT_BASE_BYTES + (double)g->nx * g->ny * EXPORT_CELL_PEAK +
                               (double)most * EXPORT_PARTICLE_PEAK);
    if (rc == 0 && text) {
        snprintf(what, sizeof what,
                 "%ld frames as a .usda text layer (held whole until its one save; a .usdc is "
                 "saved as it grows)",
                 frames);
        rc = refuse_memory(run, what, EXPORT_BASE_BYTES + write);
    }
    return rc == 0 ? refuse_disk(run, usd, frames, g, total, write) : rc;
}

/* What the export will read, checked by the library's reader first: a file
 * `info` refuses is refused here in the same sentence, and the Python
 * side only ever sees a file the reader accepted. *field becomes the field
 * the mesh is made of (NULL: none). 0, or an exit status after a message. */
static int check_run(const char *run, const char *usd, const char **field)
{
    static const char *const names[3] = {"combined", "surface", "volume"};
    static const unsigned bits[3] = {MS_FIELD_COMBINED, MS_FIELD_SURFACE, MS_FIELD_VOLUME};
    ms_reader *r;
    if (ms_reader_open(run, &r) != MS_OK) {
        tool_error("export: %s", ms_last_error());
        return EXIT_USAGE;
    }
    unsigned have = ms_reader_fields(r);
    int pick = -1;
    for (int i = 0; i < 3; ++i)
        if (*field ? !strcmp(*field, names[i]) : pick < 0 && (have & bits[i]))
            pick = i;
    if (*field && (pick < 0 || !(have & bits[pick]))) {
        char list[64] = "";
        for (int i = 0; i < 3; ++i)
            if (have & bits[i])
                snprintf(list + strlen(list), sizeof list - strlen(list), "%s%s", *list ? ", " : "",
                         names[i]);
        tool_error("export: %s has no field %s (it has: %s)", run, *field, *list ? list : "none");
        ms_reader_close(r);
        return EXIT_USAGE;
    }
    *field = pick >= 0 ? names[pick] : NULL;
    long frames = ms_reader_frames(r);
    ms_grid g = {0};
    if (pick >= 0)
        ms_reader_field_grid(r, bits[pick], &g);
    double cells = (double)g.nx * g.ny;
    size_t n = strlen(usd);
    int text = n > 5 && !strcmp(usd + n - 5, ".usda");
    /* the heights first, then the particles counted step by step: a claim
     * of 1e9 frames is refused before a look at each */
    double write = (double)frames * (cells * EXPORT_CELL_BYTES + EXPORT_FRAME_BYTES);
    int rc = check_size(run, usd, text, frames, &g, 0, 0, write);
    /* every step's particles as the reader sees them (their bytes stored
     * in the file), before Python reads them */
    double total = 0;
    int most = 0;
    for (long k = 0; rc == 0 && k < frames && (have & MS_FIELD_PARTICLES); ++k) {
        int count;
        if (ms_reader_particle_count(r, k, &count) != MS_OK) {
            tool_error("export: %s", ms_last_error());
            rc = EXIT_USAGE;
        } else {
            total += count;
            most = count > most ? count : most;
        }
    }
    ms_reader_close(r);
    if (rc == 0 && total > 0)
        rc = check_size(run, usd, text, frames, &g, most, total,
                        write + total * EXPORT_PARTICLE_BYTES);
    return rc;
}

/* The USD file to write: a .usd/.usda/.usdc name in an existing folder
 * (export creates no folders: a typo would otherwise leave a file in a
 * tree nobody asked for), not the run file, not a FIFO or a device. */
static int check_out(const char *run, const char *usd)
{
    size_t n = strlen(usd);
    int ext = (n > 4 && !strcmp(usd + n - 4, ".usd")) || (n > 5 && !strcmp(usd + n - 5, ".usda")) ||
              (n > 5 && !strcmp(usd + n - 5, ".usdc"));
    if (!ext) {
        tool_error("export: --usd %s: the name must end in .usdc, .usda or .usd", usd);
        return EXIT_USAGE;
    }
    char *dir = strdup(usd);
    if (!dir) {
        tool_error("export: out of memory");
        return EXIT_RUNTIME;
    }
    char *slash = strrchr(dir, '/');
    if (slash)
        slash[slash == dir ? 1 : 0] = '\0';
    struct stat sb;
    int ok = stat(slash ? dir : ".", &sb) == 0 && S_ISDIR(sb.st_mode);
    if (!ok) {
        tool_error("export: --usd %s: the folder %s does not exist (export creates no folders; "
                   "make it first)",
                   usd, slash ? dir : ".");
        free(dir);
        return EXIT_USAGE;
    }
    free(dir);
    if (stat(usd, &sb) == 0 && !S_ISREG(sb.st_mode)) {
        tool_error("export: --usd %s is not a regular file; give a file name to write", usd);
        return EXIT_USAGE;
    }
    if (tool_refuse_same_file("export", "--usd", usd, "the run file", run) != 0)
        return EXIT_USAGE;
    return 0;
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
    int rc = check_out(run, usd);
    if (rc == 0)
        rc = check_run(run, usd, &field);
    if (rc != 0)
        return rc;
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
