/* modesplit: run scenes, inspect run files, validate scenes, list plugins.
 * main() dispatches to one cmd_*.c per command; the usage text here is the
 * reference (README.md repeats it). */
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "tool.h"

static const char usage_text[] =
    "usage: modesplit <command> [options]\n"
    "\n"
    "Mode-splitting liquid simulation (SPH volume + 2D wave-equation surface)\n"
    "from scene files, written to HDF5 files that ParaView opens.\n"
    "\n"
    "commands:\n"
    "  run SCENE.json [options]   run a scene; write RUN.h5, RUN.xmf and PNG frames\n"
    "      --frames N             run N frames (default: the scene's duration / frame_dt)\n"
    "      --duration S           run S seconds of simulated time instead\n"
    "      --out RUN.h5           the HDF5 file (default: the scene file's base name\n"
    "                             with .h5, in the current directory); RUN.xmf is\n"
    "                             written beside it\n"
    "      --no-out               write no HDF5 file\n"
    "      --png DIR              also write DIR/frame_NNNNN.png for every written frame\n"
    "                             (DIR is created if missing), drawn by the renderer\n"
    "                             when the scene has a `render` section\n"
    "      --preview              draw the PNG frames as shaded-relief previews of the\n"
    "                             height field instead (fast; also without OSMesa)\n"
    "      --threads 1|2          1: sequential, 2: the two-core split\n"
    "                             (default: the scene's `threads`)\n"
    "      --quiet                no progress and no summary\n"
    "      --set KEY=VALUE        override a scene key by its dotted path, e.g.\n"
    "                             --set volume.spacing=0.025 --set surface.cells=[512,512]\n"
    "                             (checked as the file is; listed in the stored scene)\n"
    "  info [--scene] RUN.h5      what a run file holds: scene, frames, fields, sizes;\n"
    "                             --scene prints the scene JSON stored in it instead\n"
    "  check SCENE.json... [--set KEY=VALUE]...\n"
    "                             validate scene files without running them\n"
    "  plugins                    the shape and shader plugins found, and where from\n"
    "  accuracy [--quick] [--out DIR] [--jobs | --case NAME | --merge PARTS]\n"
    "                             validation studies against analytic and experimental\n"
    "                             references, with what each setting costs: DIR/\n"
    "                             accuracy.csv, accuracy.md, accuracy.gp and PNG plots\n"
    "                             (default DIR: accuracy). --jobs prints one command per\n"
    "                             case (run them with `| parallel`), --case runs one into\n"
    "                             DIR, --merge joins the parts in PARTS into DIR\n"
    "  help, --help, -h           this text\n"
    "  --version, -V              the library version\n"
    "\n"
    "Fields are written at the rate the scene's `output.every` asks for, and only\n"
    "those its `output.fields` lists. Each frame is flushed to disk when written:\n"
    "SIGINT or SIGTERM finishes the frame in hand and closes the file; a run that\n"
    "is killed keeps every frame written before.\n"
    "\n"
    "exit status: 0 success; 1 a failure while running (I/O, an unstable step);\n"
    "2 bad usage or bad input (a scene error names file:line:col and the key).\n"
    "A run ended by SIGINT/SIGTERM ends by that signal once the file is closed.\n";

void tool_usage(FILE *f)
{
    fputs(usage_text, f);
}

void tool_error(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    fputs("modesplit: ", stderr);
    vfprintf(stderr, fmt, ap);
    fputc('\n', stderr);
    va_end(ap);
}

int tool_opt_value(int argc, char **argv, int *i, const char *name, const char **value, int *bad)
{
    const char *a = argv[*i];
    size_t n = strlen(name);
    if (strncmp(a, name, n) != 0)
        return 0;
    if (a[n] == '=') {
        *value = a + n + 1;
        return 1;
    }
    if (a[n] != '\0')
        return 0;
    if (*i + 1 >= argc) {
        tool_error("option %s needs a value (see modesplit --help)", name);
        *bad = 1;
        *value = NULL;
        return 1;
    }
    *value = argv[++*i];
    return 1;
}

int tool_parse_long(const char *s, long lo, long hi, long *out)
{
    if (!s || !*s)
        return 0;
    char *end;
    errno = 0;
    long v = strtol(s, &end, 10);
    if (errno || *end || v < lo || v > hi)
        return 0;
    *out = v;
    return 1;
}

int tool_parse_double(const char *s, double lo, double hi, double *out)
{
    if (!s || !*s)
        return 0;
    char *end;
    errno = 0;
    double v = strtod(s, &end);
    if (errno || *end || !isfinite(v) || v < lo || v > hi)
        return 0;
    *out = v;
    return 1;
}

const char *tool_bytes(double bytes, char *buf, size_t size)
{
    if (bytes >= 1e9)
        snprintf(buf, size, "%.2f GB", bytes / 1e9);
    else if (bytes >= 1e6)
        snprintf(buf, size, "%.1f MB", bytes / 1e6);
    else if (bytes >= 1e3)
        snprintf(buf, size, "%.1f kB", bytes / 1e3);
    else
        snprintf(buf, size, "%.0f B", bytes);
    return buf;
}

int tool_scene_frames(const ms_scene *sc, const char *path, double duration, long *frames)
{
    double dt = ms_scene_frame_dt(sc);
    if (duration < 0)
        duration = ms_scene_duration(sc);
    /* frame_dt is a float: 1 s / 0.02f is 50.0000001, which is 50 frames */
    double f = dt > 0 ? ceil(duration / dt * (1.0 - 1e-7)) : INFINITY;
    if (!(f <= 1e9)) {
        tool_error("%s: duration %g s at frame_dt %g s (as a float) is more than 1e9 frames",
                   path, duration, dt);
        return -1;
    }
    *frames = f > 0 ? (long)f : 0;
    return 0;
}

double tool_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static int dispatch(int argc, char **argv)
{
    if (argc < 2) {
        tool_usage(stderr);
        return EXIT_USAGE;
    }
    const char *cmd = argv[1];
    if (!strcmp(cmd, "--help") || !strcmp(cmd, "-h") || !strcmp(cmd, "help")) {
        tool_usage(stdout);
        return EXIT_OK;
    }
    if (!strcmp(cmd, "--version") || !strcmp(cmd, "-V")) {
        printf("modesplit %s (HDF5 file format %s %d)\n", ms_version(), MS_FILE_FORMAT,
               MS_FILE_FORMAT_VERSION);
        return EXIT_OK;
    }
    if (!strcmp(cmd, "run"))
        return cmd_run(argc - 1, argv + 1);
    if (!strcmp(cmd, "info"))
        return cmd_info(argc - 1, argv + 1);
    if (!strcmp(cmd, "check"))
        return cmd_check(argc - 1, argv + 1);
    if (!strcmp(cmd, "plugins"))
        return cmd_plugins(argc - 1, argv + 1);
    if (!strcmp(cmd, "accuracy"))
        return cmd_accuracy(argc - 1, argv + 1);
    tool_error("unknown command \"%s\"; commands: run, info, check, plugins, accuracy (see modesplit --help)",
               cmd);
    return EXIT_USAGE;
}

/* Every file is closed by the command itself; the process then ends with
 * _exit so that no library's exit handler runs: HDF5's, after a corrupt
 * input file it could not fully close, prints "infinite loop closing
 * library" (HDF5 1.10.8 does so in h5dump too). */
int main(int argc, char **argv)
{
    int rc = dispatch(argc, argv);
    fflush(stdout);
    fflush(stderr);
    _exit(rc);
}
