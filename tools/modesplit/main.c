/* modesplit: run scenes, inspect run files, validate scenes, list plugins.
 * main() dispatches to one cmd_*.c per command; the usage text here is the
 * reference (docs/tool.md repeats it). */
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "tool.h"

/* One string, so each command's help is the block of it that starts with
 * the command (command_block): past C99's 4095 characters, which GCC and
 * clang take in full; the pedantic warning is off for this one literal. */
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Woverlength-strings"
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
    "                             with .h5, in the current directory); RUN.xmf\n"
    "                             (ParaView) and RUN.xdmf2 (legacy XDMF reader,\n"
    "                             VisIt) are written beside it\n"
    "      --force                replace RUN.h5 (or its sidecars) if it exists; without\n"
    "                             it an existing run is refused and kept\n"
    "      --no-out               write no HDF5 file\n"
    "      --resume RUN.h5        continue a killed or stopped run, appending to RUN.h5\n"
    "                             (same scene and build; the fields end as an unbroken\n"
    "                             run's, byte for byte)\n"
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
    "  info --build               the compiler, the SIMD paths built and this CPU's, the\n"
    "                             one chosen (MODESPLIT_ISA=c|sse2|avx2|avx512|neon)\n"
    "  check SCENE.json... [--set KEY=VALUE]...\n"
    "                             validate scene files without running them\n"
    "  plugins                    the shape and shader plugins found, and where from\n"
    "  export RUN.h5 --usd OUT.usdc  write a run as USD (Blender, Houdini, Omniverse):\n"
    "      --usd OUT.usdc         the height field as a time-sampled mesh, particles as\n"
    "                             time-sampled points (python3 with usd-core)\n"
    "      --field NAME           the mesh's field: combined (default), surface, volume\n"
    "  view SCENE.json [options]  the scene in a window, in real time: left-drag the\n"
    "                             water, right-drag orbit, wheel zoom, middle-drag pan,\n"
    "                             shift-click a drop; H in the window lists the keys\n"
    "      --size WxH             window size (default: the scene's render size)\n"
    "      --threads 1|2          as for run\n"
    "      --fast                 start as fast as it can (F toggles) instead of at frame_dt\n"
    "      --frames N             quit after N frames shown (paused ones count)\n"
    "      --record DIR           DIR/frame_NNNNN.png: every frame as the user saw it\n"
    "      --record-input FILE    log the mouse and keys with their frame numbers\n"
    "      --script FILE          replay such a log (the same frames, the same water)\n"
    "      --out RUN.h5           also write the session's frames as run does\n"
    "      --force                replace an existing RUN.h5, as for run\n"
    "  render RUN.h5 [options]    draw a run file's frames again, without simulating\n"
    "      --png DIR              write DIR/frame_NNNNN.png (NNNNN = the frame's index)\n"
    "      --video FILE.mp4       pipe the frames to ffmpeg (when it is installed)\n"
    "      --shader NAME          another shader plugin (water, milk, oil, honey)\n"
    "      --camera EX,EY,EZ,TX,TY,TZ[,FOV]  eye and target (m), vertical FOV (degrees)\n"
    "      --size WxH             another image size (pixels)\n"
    "      --frames A:B           only frames A to B (A: to the end)\n"
    "  cubemap --out DIR [--size N] [--sun X,Y,Z]\n"
    "                             write the builtin sky as six PNG faces (px.png ...\n"
    "                             nz.png) for a scene's render.cubemap\n"
    "  accuracy [--quick] [--out DIR] [--jobs | --case NAME | --merge PARTS]\n"
    "                             validation studies against analytic and experimental\n"
    "                             references, with what each setting costs: DIR/\n"
    "                             accuracy.csv, accuracy.md, accuracy.gp and PNG plots\n"
    "                             (default DIR: accuracy). --jobs prints one command per\n"
    "                             case (run them with `| parallel`), --case runs one into\n"
    "                             DIR, --merge joins the parts in PARTS into DIR\n"
    "  help [COMMAND], --help, -h this text, or one command's part of it\n"
    "                             (also: modesplit COMMAND --help)\n"
    "  --version, -V              the library version\n"
    "\n"
    "Fields are written at the rate the scene's `output.every` asks for, and only\n"
    "those its `output.fields` lists. Each frame is flushed to disk when written:\n"
    "SIGINT or SIGTERM finishes the frame in hand and closes the file; a second one\n"
    "drops the frame in hand (a long one) and closes the file; a third, or a kill,\n"
    "ends at once, and the file keeps every frame written before.\n"
    "\n"
    "exit status: 0 success; 1 a failure while running (I/O, an unstable step);\n"
    "2 bad usage or bad input (a scene error names file:line:col and the key).\n"
    "A run ended by SIGINT/SIGTERM ends by that signal once the file is closed.\n";
#pragma GCC diagnostic pop

void tool_usage(FILE *f)
{
    fputs(usage_text, f);
}

/* The block of usage_text that starts at "  <cmd> " and runs to the next
 * line indented by exactly two spaces (the next command). */
static const char *command_block(const char *cmd, size_t *len)
{
    size_t n = strlen(cmd);
    for (const char *l = usage_text; *l; l = strchr(l, '\n') + 1) {
        if (!strncmp(l, "  ", 2) && !strncmp(l + 2, cmd, n) && (l[2 + n] == ' ')) {
            const char *e = strchr(l, '\n') + 1;
            while (*e && !strncmp(e, "   ", 3))
                e = strchr(e, '\n') + 1;
            *len = (size_t)(e - l);
            return l;
        }
        if (!strchr(l, '\n'))
            break;
    }
    return NULL;
}

int tool_command_usage(FILE *f, const char *cmd)
{
    size_t len;
    const char *b = command_block(cmd, &len);
    if (!b)
        return -1;
    fprintf(f, "usage: modesplit %s", cmd);
    /* the command's own line without "  <cmd>", then its options */
    fwrite(b + 2 + strlen(cmd), 1, len - 2 - strlen(cmd), f);
    fputs("\n(modesplit --help: every command, exit statuses)\n", f);
    return 0;
}

/* Levenshtein distance, for "did you mean". */
static size_t edit_distance(const char *a, const char *b)
{
    size_t na = strlen(a), nb = strlen(b);
    if (na > 63 || nb > 63)
        return 64;
    size_t row[64];
    for (size_t j = 0; j <= nb; ++j)
        row[j] = j;
    for (size_t i = 1; i <= na; ++i) {
        size_t diag = row[0];
        row[0] = i;
        for (size_t j = 1; j <= nb; ++j) {
            size_t up = row[j];
            size_t best = diag + (a[i - 1] != b[j - 1]);
            if (row[j - 1] + 1 < best)
                best = row[j - 1] + 1;
            if (up + 1 < best)
                best = up + 1;
            row[j] = best;
            diag = up;
        }
    }
    return row[nb];
}

void tool_unknown_option(const char *cmd, const char *opt)
{
    /* the options are the "--word" tokens of the command's usage block */
    size_t len = 0, best_d = 64;
    char best[64] = "";
    const char *b = command_block(cmd, &len);
    char name[64];
    size_t optlen = strcspn(opt, "=");
    snprintf(name, sizeof name, "%.*s", (int)(optlen < 63 ? optlen : 63), opt);
    for (const char *p = b; p && p < b + len; ++p) {
        if (p[0] != '-' || p[1] != '-' || (p > b && p[-1] != ' ' && p[-1] != '['))
            continue;
        size_t k = strspn(p, "-abcdefghijklmnopqrstuvwxyz0123456789");
        char cand[64];
        snprintf(cand, sizeof cand, "%.*s", (int)(k < 63 ? k : 63), p);
        size_t d = edit_distance(name, cand);
        if (d < best_d) {
            best_d = d;
            snprintf(best, sizeof best, "%s", cand);
        }
        p += k - 1;
    }
    /* close enough to be a typo: at most 2 edits, fewer than half the name */
    if (best[0] && best_d <= 2 && best_d * 2 < strlen(best))
        tool_error("%s: unknown option %s; did you mean %s? (see modesplit %s --help)", cmd, opt,
                   best, cmd);
    else
        tool_error("%s: unknown option %s (see modesplit %s --help)", cmd, opt, cmd);
}

int tool_refuse_same_file(const char *cmd, const char *option, const char *out, const char *what,
                          const char *in)
{
    struct stat a, b;
    if (!out || !in || stat(out, &a) != 0 || stat(in, &b) != 0 || a.st_dev != b.st_dev ||
        a.st_ino != b.st_ino)
        return 0;
    tool_error("%s: %s %s is %s %s: an output never overwrites an input; choose another name", cmd,
               option, out, what, in);
    return -1;
}

int tool_refuse_replace(const char *cmd, const char *out, const ms_sim *sim, int force)
{
    char name[4096];
    int exists = 0;
    if (!out)
        return EXIT_OK;
    if (ms_writer_existing(out, sim, name, sizeof name, &exists) != MS_OK) {
        tool_error("%s", ms_last_error()); /* "io: ...", as the writer's open says it */
        return EXIT_RUNTIME;
    }
    if (!exists || force)
        return EXIT_OK;
    if (strcmp(name, out) != 0)
        tool_error("%s: %s, the XDMF sidecar of %s, exists: pass --force to replace the run, or "
                   "choose another --out",
                   cmd, name, out);
    else
        tool_error("%s: %s exists: pass --force to replace it, or choose another --out", cmd, out);
    return EXIT_USAGE;
}

/* Bytes of the well-formed UTF-8 sequence of 2 to 4 bytes at p, 0 when
 * there is none (a stray or cut byte, an overlong form, a surrogate). The
 * checks stop at the first byte that is not a continuation, so a string's
 * NUL ends them. */
static int utf8_len(const unsigned char *p)
{
    if (p[0] >= 0xc2 && p[0] <= 0xdf)
        return (p[1] & 0xc0) == 0x80 ? 2 : 0;
    if (p[0] >= 0xe0 && p[0] <= 0xef) {
        if ((p[1] & 0xc0) != 0x80 || (p[2] & 0xc0) != 0x80 || (p[0] == 0xe0 && p[1] < 0xa0) ||
            (p[0] == 0xed && p[1] >= 0xa0))
            return 0;
        return 3;
    }
    if (p[0] >= 0xf0 && p[0] <= 0xf4) {
        if ((p[1] & 0xc0) != 0x80 || (p[2] & 0xc0) != 0x80 || (p[3] & 0xc0) != 0x80 ||
            (p[0] == 0xf0 && p[1] < 0x90) || (p[0] == 0xf4 && p[1] >= 0x90))
            return 0;
        return 4;
    }
    return 0;
}

void tool_put_escaped(FILE *f, const char *s, const char *keep)
{
    for (const unsigned char *p = (const unsigned char *)s; *p;) {
        int n = *p < 0x80 ? 1 : utf8_len(p);
        if ((*p < 0x20 && !strchr(keep, *p)) || *p == 0x7f || n == 0) {
            fprintf(f, "\\x%02x", *p++);
        } else if (n == 2 && p[0] == 0xc2 && p[1] < 0xa0) {
            /* U+0080..U+009F: the C1 controls (U+009B is a CSI to a
             * terminal that takes them) */
            fprintf(f, "\\u%04x", p[1]);
            p += 2;
        } else {
            fwrite(p, 1, (size_t)n, f);
            p += n;
        }
    }
}

void tool_error(const char *fmt, ...)
{
    /* a message quotes file names, scene text and run-file strings: it is
     * escaped as a whole, so no caller has to remember which part came
     * from a file */
    char small[1024], *msg = small;
    va_list ap;
    va_start(ap, fmt);
    int n = vsnprintf(small, sizeof small, fmt, ap);
    va_end(ap);
    if (n >= (int)sizeof small && (msg = malloc((size_t)n + 1)) != NULL) {
        va_start(ap, fmt);
        vsnprintf(msg, (size_t)n + 1, fmt, ap);
        va_end(ap);
    } else if (n >= (int)sizeof small) {
        msg = small; /* cut, but printed */
    }
    fputs("modesplit: ", stderr);
    tool_put_escaped(stderr, n < 0 ? fmt : msg, "\n\t");
    fputc('\n', stderr);
    if (msg != small)
        free(msg);
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
        tool_error("%s: duration %g s at frame_dt %g s (as a float) is more than 1e9 frames", path,
                   duration, dt);
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
        if (argc > 2 && !strcmp(cmd, "help")) {
            if (tool_command_usage(stdout, argv[2]) == 0)
                return EXIT_OK;
            tool_error("help: no command \"%s\"; commands: run, info, check, plugins, export, "
                       "view, render, cubemap, accuracy",
                       argv[2]);
            return EXIT_USAGE;
        }
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
    /* the renderer's commands */
    if (!strcmp(cmd, "render"))
        return cmd_render(argc - 1, argv + 1);
    if (!strcmp(cmd, "cubemap"))
        return cmd_cubemap(argc - 1, argv + 1);
    if (!strcmp(cmd, "view"))
        return cmd_view(argc - 1, argv + 1);
    if (!strcmp(cmd, "export"))
        return cmd_export(argc - 1, argv + 1);
    static const char *const commands[] = {"run",  "info",   "check",   "plugins", "export",
                                           "view", "render", "cubemap", "accuracy"};
    for (size_t i = 0; i < sizeof commands / sizeof commands[0]; ++i)
        if (edit_distance(cmd, commands[i]) <= 2 &&
            edit_distance(cmd, commands[i]) < strlen(commands[i])) {
            tool_error("unknown command \"%s\"; did you mean %s? (see modesplit --help)", cmd,
                       commands[i]);
            return EXIT_USAGE;
        }
    tool_error("unknown command \"%s\"; commands: run, info, check, plugins, export, view, render, "
               "cubemap, accuracy (see modesplit --help)",
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
