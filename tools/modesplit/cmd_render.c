/* modesplit render RUN.h5 [--shader NAME] [--camera EX,EY,EZ,TX,TY,TZ[,FOV]]
 *                  [--size WxH] [--frames A:B] --png DIR [--video FILE.mp4]
 *
 * Re-renders a finished (or still growing, or killed) run file without
 * simulating again: each frame's combined field is read back and drawn by
 * the renderer with the scene stored in the file (its `render` section and
 * its pool, the boat on its path), so a batch user changes the shader, the
 * camera or the size after a long run. --video pipes the frames as raw
 * RGBA to ffmpeg (libx264, yuv420p) when ffmpeg is on PATH, and says so
 * when it is not. */
#include <errno.h>
#include <math.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "tool.h"

typedef struct render_opts {
    const char *run, *shader, *png, *video;
    int have_camera, width, height;
    float eye[3], target[3], fov;
    long first, last; /* frames [first, last], last < 0: to the end */
} render_opts;

static int parse_camera(const char *s, render_opts *o)
{
    double v[7];
    int n = 0;
    const char *p = s;
    while (n < 7) {
        char *end;
        errno = 0;
        v[n] = strtod(p, &end);
        if (end == p || errno || !(v[n] > -1e6 && v[n] < 1e6))
            return 0;
        ++n;
        if (*end == '\0')
            break;
        if (*end != ',')
            return 0;
        p = end + 1;
    }
    if (n != 6 && n != 7)
        return 0;
    for (int k = 0; k < 3; ++k) {
        o->eye[k] = (float)v[k];
        o->target[k] = (float)v[3 + k];
    }
    o->fov = n == 7 ? (float)v[6] : 0;
    o->have_camera = 1;
    return 1;
}

static int parse_args(int argc, char **argv, render_opts *o)
{
    memset(o, 0, sizeof *o);
    o->last = -1;
    for (int i = 1; i < argc; ++i) {
        const char *a = argv[i], *v = NULL;
        int bad = 0;
        if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
            tool_command_usage(stdout, "render");
            return -1;
        } else if (tool_opt_value(argc, argv, &i, "--shader", &v, &bad)) {
            if (bad || !v[0]) {
                tool_error("render: --shader needs a shader plugin name (water, milk, oil, "
                           "honey)");
                return EXIT_USAGE;
            }
            o->shader = v;
        } else if (tool_opt_value(argc, argv, &i, "--png", &v, &bad)) {
            if (bad || !v[0]) {
                tool_error("render: --png needs a directory");
                return EXIT_USAGE;
            }
            o->png = v;
        } else if (tool_opt_value(argc, argv, &i, "--video", &v, &bad)) {
            if (bad || !v[0]) {
                tool_error("render: --video needs a file name (FILE.mp4)");
                return EXIT_USAGE;
            }
            o->video = v;
        } else if (tool_opt_value(argc, argv, &i, "--camera", &v, &bad)) {
            if (bad || !parse_camera(v, o)) {
                tool_error("render: --camera %s: give EX,EY,EZ,TX,TY,TZ[,FOV] (eye and "
                           "target in m, finite; FOV in degrees)",
                           v ? v : "");
                return EXIT_USAGE;
            }
        } else if (tool_opt_value(argc, argv, &i, "--size", &v, &bad)) {
            int w = 0, h = 0;
            char tail;
            if (bad || sscanf(v, "%dx%d%c", &w, &h, &tail) != 2 || w < 16 || h < 16 || w > 8192 ||
                h > 8192) {
                tool_error("render: --size %s: give WxH, each in [16, 8192] pixels", v ? v : "");
                return EXIT_USAGE;
            }
            o->width = w, o->height = h;
        } else if (tool_opt_value(argc, argv, &i, "--frames", &v, &bad)) {
            long a0 = 0, b0 = -1;
            char tail;
            int n = bad ? 0 : sscanf(v, "%ld:%ld%c", &a0, &b0, &tail);
            if (n == 1 && strchr(v, ':') == NULL)
                b0 = a0;
            if (n < 1 || n > 2 || a0 < 0 || (b0 >= 0 && b0 < a0)) {
                tool_error("render: --frames %s: give A:B or A: or A (frame indices, A <= B)",
                           v ? v : "");
                return EXIT_USAGE;
            }
            o->first = a0, o->last = b0;
        } else if (a[0] == '-' && a[1]) {
            tool_error("render: unknown option %s (see modesplit render --help)", a);
            return EXIT_USAGE;
        } else if (o->run) {
            tool_error("render: one run file at a time (got %s and %s)", o->run, a);
            return EXIT_USAGE;
        } else {
            o->run = a;
        }
    }
    if (!o->run) {
        tool_error("render: which run file? usage: modesplit render RUN.h5 [--shader NAME] "
                   "[--camera EX,EY,EZ,TX,TY,TZ[,FOV]] [--size WxH] [--frames A:B] --png DIR "
                   "[--video FILE.mp4]");
        return EXIT_USAGE;
    }
    if (!o->png && !o->video) {
        tool_error("render: say where the frames go: --png DIR and/or --video FILE.mp4");
        return EXIT_USAGE;
    }
    return 0;
}

/* ffmpeg on PATH? */
static int have_ffmpeg(void)
{
    return system("command -v ffmpeg >/dev/null 2>&1") == 0;
}

/* ffmpeg reading raw frames from a pipe, started without a shell: the
 * path is one argument, given to ffmpeg's file protocol ("file:"), so no
 * character of it is parsed by a shell or read as an option or another
 * protocol. *pid: the process, for close_video. */
static FILE *open_video(const render_opts *o, int w, int h, double fps, pid_t *pid)
{
    char size[32], rate[32], *out = malloc(strlen(o->video) + 6);
    int fd[2];
    if (!out || pipe(fd) != 0) {
        free(out);
        tool_error("render: cannot start ffmpeg: %s", strerror(errno));
        return NULL;
    }
    snprintf(size, sizeof size, "%dx%d", w, h);
    snprintf(rate, sizeof rate, "%.6g", fps);
    strcpy(out, "file:");
    strcat(out, o->video);
    fflush(NULL);
    *pid = fork();
    if (*pid == 0) {
        dup2(fd[0], STDIN_FILENO);
        close(fd[0]);
        close(fd[1]);
        execlp("ffmpeg", "ffmpeg", "-loglevel", "error", "-y", "-f", "rawvideo", "-pix_fmt", "rgba",
               "-s", size, "-r", rate, "-i", "-", "-vf", "scale=trunc(iw/2)*2:trunc(ih/2)*2",
               "-c:v", "libx264", "-pix_fmt", "yuv420p", out, (char *)NULL);
        _exit(127);
    }
    free(out);
    close(fd[0]);
    FILE *f = *pid > 0 ? fdopen(fd[1], "w") : NULL;
    if (!f) {
        tool_error("render: cannot start ffmpeg: %s", strerror(errno));
        close(fd[1]);
        if (*pid > 0)
            waitpid(*pid, NULL, 0);
    }
    return f;
}

/* Close ffmpeg's pipe and wait for it: its exit status, -1 if it did not
 * exit. */
static int close_video(FILE *f, pid_t pid)
{
    fclose(f);
    int status = 0;
    while (waitpid(pid, &status, 0) < 0)
        if (errno != EINTR)
            return -1;
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

/* The file's floaters of frame f (/floaters) as leaves, drawn
 * as a run draws them (lib/render/draw_sim.c: 3 cm across in a 1 m pool,
 * brown); nothing when the file has none. 0 or -1 (ms_last_error). */
static int floater_discs(const ms_reader *rd, long f, ms_renderer *r, const ms_renderer_desc *d)
{
    int nf = ms_reader_floater_count(rd);
    if (nf <= 0)
        return 0;
    nf = nf < MS_RENDER_MAX_DISCS ? nf : MS_RENDER_MAX_DISCS;
    float *xyz = malloc((size_t)ms_reader_floater_count(rd) * 3 * sizeof *xyz);
    ms_render_disc *discs = malloc((size_t)nf * sizeof *discs);
    int rc =
        xyz && discs && ms_reader_read_floaters(rd, f, xyz, ms_reader_floater_count(rd)) == MS_OK
            ? 0
            : -1;
    const float side = fminf(d->pool_max[0] - d->pool_min[0], d->pool_max[1] - d->pool_min[1]);
    for (int k = 0; rc == 0 && k < nf; ++k) {
        memcpy(discs[k].pos, xyz + 3 * k, sizeof discs[k].pos);
        discs[k].radius = 0.015f * side;
        discs[k].color[0] = 0.45f, discs[k].color[1] = 0.30f, discs[k].color[2] = 0.08f;
    }
    if (rc == 0 && ms_renderer_set_discs(r, discs, nf) != MS_OK)
        rc = -1;
    free(xyz);
    free(discs);
    return rc;
}

/* The file's spray and foam of frame f (/spray, /foam) as a run draws
 * them (lib/render/draw_sim.c: droplets 0.15 particle spacings in radius,
 * the scene's spacing); nothing when the file has none. 0 or -1. */
static int spray_and_foam(const ms_reader *rd, const ms_scene *sc, long f, ms_renderer *r)
{
    const int budget = ms_reader_spray_budget(rd);
    if (budget <= 0)
        return 0;
    ms_grid g;
    ms_volume_desc vd = ms_volume_desc_default();
    if (ms_reader_foam_grid(rd, &g) != MS_OK || (sc && ms_scene_volume_desc(sc, &vd) != MS_OK))
        return -1;
    float *xyz = malloc((size_t)budget * 3 * sizeof *xyz);
    float *foam = malloc((size_t)g.nx * (size_t)g.ny * sizeof *foam);
    int n = 0;
    int rc = xyz && foam && ms_reader_read_spray(rd, f, xyz, budget, &n) == MS_OK &&
                     ms_reader_read_foam(rd, f, foam, (size_t)g.nx * (size_t)g.ny) == MS_OK &&
                     ms_renderer_set_spray(r, xyz, n, 0.15f * vd.spacing) == MS_OK &&
                     ms_renderer_set_foam(r, foam, &g) == MS_OK
                 ? 0
                 : -1;
    free(xyz);
    free(foam);
    return rc;
}

/* What a render holds open; render_close frees it all. */
typedef struct render_state {
    render_opts o;
    ms_reader *rd;
    ms_scene *sc;
    ms_renderer_desc d;
    ms_renderer *r;
    ms_grid g;
    float *h; /* one frame of the combined field */
    size_t n;
    long last; /* the last frame drawn */
    FILE *video;
    pid_t video_pid;
    png_queue *pngq;
} render_state;

/* The run file, its stored scene and the renderer; EXIT_OK or the exit. */
static int render_open(render_state *s)
{
    const render_opts *o = &s->o;
    if (ms_reader_open(o->run, &s->rd) != MS_OK) {
        tool_error("%s", ms_last_error());
        return EXIT_USAGE;
    }
    const char *json = ms_reader_scene(s->rd);
    if (!json || !json[0]) {
        tool_error("render: %s stores no scene, so its pool and camera are unknown", o->run);
        return EXIT_USAGE;
    }
    if (ms_scene_parse(json, strlen(json), &s->sc) != MS_OK) {
        tool_error("render: the scene stored in %s: %s", o->run, ms_last_error());
        return EXIT_USAGE;
    }
    if (!(ms_reader_fields(s->rd) & MS_FIELD_COMBINED)) {
        tool_error("render: %s holds no combined field (the scene's output.fields lacks "
                   "\"combined\"); nothing to draw",
                   o->run);
        return EXIT_USAGE;
    }
    const long frames = ms_reader_frames(s->rd);
    s->last = o->last < 0 ? frames - 1 : o->last;
    if (frames <= 0 || o->first >= frames || s->last >= frames) {
        tool_error("render: %s holds %ld frames; --frames asks for %ld:%ld", o->run, frames,
                   o->first, s->last);
        return EXIT_USAGE;
    }
    s->d = ms_renderer_desc_default();
    if (ms_renderer_desc_from_scene(s->sc, &s->d) != MS_OK) {
        tool_error("%s", ms_last_error());
        return EXIT_RUNTIME;
    }
    if (o->shader && strcmp(o->shader, s->d.shader)) {
        s->d.shader = o->shader;
        s->d.shader_params = NULL; /* the scene's are its own shader's */
    }
    if (o->width)
        s->d.width = o->width, s->d.height = o->height;
    if (o->have_camera) {
        memcpy(s->d.eye, o->eye, sizeof s->d.eye);
        memcpy(s->d.target, o->target, sizeof s->d.target);
        if (o->fov > 0)
            s->d.fov = o->fov;
    }
    ms_status st = ms_renderer_create_desc(&s->d, &s->r);
    if (st != MS_OK) {
        tool_error("%s", ms_last_error());
        return st == MS_ERR_INVALID_ARGUMENT || st == MS_ERR_PLUGIN ? EXIT_USAGE : EXIT_RUNTIME;
    }
    if (ms_reader_field_grid(s->rd, MS_FIELD_COMBINED, &s->g) != MS_OK) {
        tool_error("%s", ms_last_error());
        return EXIT_RUNTIME;
    }
    s->n = (size_t)s->g.nx * (size_t)s->g.ny;
    if (!(s->h = malloc(s->n * sizeof *s->h))) {
        tool_error("render: out of memory for a %d x %d field", s->g.nx, s->g.ny);
        return EXIT_RUNTIME;
    }
    return EXIT_OK;
}

/* The PNG folder and its writer thread, the ffmpeg pipe; 0 or -1. */
static int render_outputs_open(render_state *s)
{
    const render_opts *o = &s->o;
    if (o->png) {
        if (mkdir(o->png, 0777) != 0 && errno != EEXIST) {
            tool_error("render: cannot create %s: %s", o->png, strerror(errno));
            return -1;
        }
        if (png_queue_start(&s->pngq) != 0)
            return -1;
    }
    if (o->video) {
        double dt = ms_reader_frame_dt(s->rd) * ms_reader_output_every(s->rd);
        double fps = dt > 0 ? 1.0 / dt : 30.0;
        signal(SIGPIPE, SIG_IGN);
        if (!(s->video = open_video(o, s->d.width, s->d.height, fps, &s->video_pid)))
            return -1;
    }
    return 0;
}

/* Draws one frame and hands its pixels to the PNG thread and ffmpeg. */
static int render_frame(render_state *s, long f)
{
    double t = 0;
    if (ms_reader_read_field(s->rd, MS_FIELD_COMBINED, f, s->h, s->n) != MS_OK ||
        ms_reader_time(s->rd, f, &t) != MS_OK || floater_discs(s->rd, f, s->r, &s->d) != 0 ||
        spray_and_foam(s->rd, s->sc, f, s->r) != 0 ||
        ms_renderer_draw_scene_field(s->r, s->sc, s->h, &s->g, t) != MS_OK) {
        tool_error("render: frame %ld: %s", f, ms_last_error());
        return -1;
    }
    int w = 0, hh = 0;
    const unsigned char *px = ms_renderer_pixels(s->r, &w, &hh);
    if (s->o.png) { /* encoded by png_queue.c's thread while the next frame draws */
        char path[4096];
        snprintf(path, sizeof path, "%s/frame_%05ld.png", s->o.png, f);
        if (png_queue_push(s->pngq, path, px, w, hh) != 0)
            return -1;
    }
    if (s->video && fwrite(px, 4, (size_t)w * (size_t)hh, s->video) != (size_t)w * (size_t)hh) {
        tool_error("render: ffmpeg stopped taking frames (frame %ld)", f);
        return -1;
    }
    return 0;
}

/* ffmpeg and the PNG thread finish, then the summary; 0 or -1. */
static int render_finish(render_state *s, long written)
{
    if (s->video) {
        int vrc = close_video(s->video, s->video_pid);
        s->video = NULL;
        if (vrc != 0) {
            tool_error("render: ffmpeg failed writing %s (status %d)", s->o.video, vrc);
            return -1;
        }
    }
    int png_rc = png_queue_finish(s->pngq); /* every frame on disk before the summary */
    s->pngq = NULL;
    if (png_rc != 0)
        return -1;
    printf("rendered %ld frames of %s (%dx%d, shader %s)", written, s->o.run, s->d.width,
           s->d.height, s->d.shader);
    if (s->o.png)
        printf(" to %s", s->o.png);
    if (s->o.video)
        printf("%s%s", s->o.png ? " and " : " to ", s->o.video);
    printf("\n");
    return 0;
}

static void render_close(render_state *s)
{
    png_queue_finish(s->pngq);
    if (s->video)
        close_video(s->video, s->video_pid);
    free(s->h);
    ms_renderer_destroy(s->r);
    ms_scene_destroy(s->sc);
    ms_reader_close(s->rd);
}

int cmd_render(int argc, char **argv)
{
    render_state s;
    memset(&s, 0, sizeof s);
    int rc = parse_args(argc, argv, &s.o);
    if (rc != 0)
        return rc < 0 ? EXIT_OK : rc;
    if (s.o.video && !have_ffmpeg()) {
        tool_error("render: --video needs ffmpeg, which is not installed (Debian: apt-get "
                   "install ffmpeg); use --png DIR and encode the frames later");
        return EXIT_USAGE;
    }
    rc = render_open(&s);
    if (rc == EXIT_OK && render_outputs_open(&s) != 0)
        rc = EXIT_RUNTIME;
    long written = 0;
    for (long f = s.o.first; rc == EXIT_OK && f <= s.last; ++f, ++written)
        if (render_frame(&s, f) != 0)
            rc = EXIT_RUNTIME;
    if (rc == EXIT_OK && render_finish(&s, written) != 0)
        rc = EXIT_RUNTIME;
    render_close(&s);
    return rc;
}
