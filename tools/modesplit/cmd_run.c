/* modesplit run SCENE.json [options]: load the scene, build the sim, step
 * it, write every `output.every`-th frame to HDF5 (and PNG), report
 * progress and a summary. SIGINT/SIGTERM finish the frame in hand, close
 * the file, and then end the program by the same signal. */
#include <math.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "tool.h"

static volatile sig_atomic_t stop_signal;
static ms_sim *volatile running_sim;

/* The first SIGINT/SIGTERM finishes the frame in hand; a second cancels
 * it (ms_sim_cancel only stores atomic flags: safe in a handler), and the
 * run still closes its file; a third ends the program at once. */
static void on_stop(int sig)
{
    if (!stop_signal) {
        stop_signal = sig;
        return;
    }
    if (running_sim)
        ms_sim_cancel(running_sim);
    signal(sig, SIG_DFL);
}

static void catch_stop_signals(void)
{
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_stop;
    sigemptyset(&sa.sa_mask);
    sa.sa_flags = SA_RESTART;
    sigaction(SIGINT, &sa, NULL);
    sigaction(SIGTERM, &sa, NULL);
}

typedef struct run_opts {
    const char *scene;
    const char *out; /* NULL: default name */
    const char *png;
    const char *resume;                /* --resume RUN.h5 (resume.c) */
    long frames;                       /* -1: from the duration */
    double duration;                   /* s, < 0: the scene's */
    int threads;                       /* 0: the scene's */
    int no_out, quiet, preview, force; /* force: replace an existing run file */
    tool_sets sets;                    /* --set KEY=VALUE */
} run_opts;

static int parse_args(int argc, char **argv, run_opts *o)
{
    memset(o, 0, sizeof *o);
    o->frames = -1;
    o->duration = -1;
    for (int i = 1; i < argc; ++i) {
        const char *v = NULL, *a = argv[i];
        int bad = 0;
        if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
            tool_command_usage(stdout, "run");
            return -1;
        } else if (tool_opt_value(argc, argv, &i, "--frames", &v, &bad)) {
            if (bad)
                return EXIT_USAGE;
            if (!tool_parse_long(v, 0, 1000000000L, &o->frames)) {
                tool_error("run: --frames %s is not a whole number in [0, 1e9]", v);
                return EXIT_USAGE;
            }
        } else if (tool_opt_value(argc, argv, &i, "--duration", &v, &bad)) {
            if (bad)
                return EXIT_USAGE;
            if (!tool_parse_double(v, 0, 1e9, &o->duration)) {
                tool_error("run: --duration %s is not a number of seconds in [0, 1e9]", v);
                return EXIT_USAGE;
            }
        } else if (tool_opt_value(argc, argv, &i, "--out", &v, &bad)) {
            if (bad)
                return EXIT_USAGE;
            if (!*v) {
                tool_error("run: --out needs a file name");
                return EXIT_USAGE;
            }
            o->out = v;
        } else if (tool_opt_value(argc, argv, &i, "--resume", &v, &bad)) {
            if (bad)
                return EXIT_USAGE;
            o->resume = v;
        } else if (tool_opt_value(argc, argv, &i, "--png", &v, &bad)) {
            if (bad)
                return EXIT_USAGE;
            if (!*v) {
                tool_error("run: --png needs a directory");
                return EXIT_USAGE;
            }
            o->png = v;
        } else if (tool_opt_value(argc, argv, &i, "--threads", &v, &bad)) {
            long t;
            if (bad)
                return EXIT_USAGE;
            if (!tool_parse_long(v, 1, 2, &t)) {
                tool_error("run: --threads %s must be 1 (sequential) or 2 (two-core split)", v);
                return EXIT_USAGE;
            }
            o->threads = (int)t;
        } else if (tool_set_option(argc, argv, &i, &o->sets, &bad)) {
            if (bad)
                return EXIT_USAGE;
        } else if (!strcmp(a, "--preview")) {
            o->preview = 1;
        } else if (!strcmp(a, "--force")) {
            o->force = 1;
        } else if (!strcmp(a, "--no-out")) {
            o->no_out = 1;
        } else if (!strcmp(a, "--quiet") || !strcmp(a, "-q")) {
            o->quiet = 1;
        } else if (a[0] == '-' && a[1]) {
            tool_unknown_option("run", a);
            return EXIT_USAGE;
        } else if (o->scene) {
            tool_error("run: one scene at a time (got %s and %s)", o->scene, a);
            return EXIT_USAGE;
        } else {
            o->scene = a;
        }
    }
    if (!o->scene) {
        tool_error("run: which scene? usage: modesplit run SCENE.json [--frames N | --duration "
                   "S] [--out RUN.h5 [--force]] [--png DIR [--preview]] [--threads 1|2] [--quiet]");
        return EXIT_USAGE;
    }
    if (o->frames >= 0 && o->duration >= 0) {
        tool_error("run: give --frames or --duration, not both");
        return EXIT_USAGE;
    }
    if (o->resume && (o->out || o->no_out)) {
        tool_error("run: --resume RUN.h5 appends to RUN.h5: give no --out or --no-out with it");
        return EXIT_USAGE;
    }
    if (o->resume && o->force) {
        tool_error("run: --force replaces a run file, --resume appends to one: give one of them");
        return EXIT_USAGE;
    }
    if (o->out && o->no_out) {
        tool_error("run: give --out or --no-out, not both");
        return EXIT_USAGE;
    }
    return EXIT_OK;
}

/* "dir/fig1.json" -> "fig1.h5" (in the current directory). */
static char *default_out(const char *scene)
{
    const char *base = strrchr(scene, '/');
    base = base ? base + 1 : scene;
    size_t n = strlen(base);
    if (n > 5 && !strcmp(base + n - 5, ".json"))
        n -= 5;
    if (n == 0) {
        base = "run";
        n = 3;
    }
    char *p = malloc(n + 4);
    if (p) {
        memcpy(p, base, n);
        memcpy(p + n, ".h5", 4);
    }
    return p;
}

static void fill_stages(const ms_sim *sim, double write_s, double png_s, long frames,
                        tool_stages *s)
{
    ms_stats st = ms_stats_init();
    ms_sim_get_stats(sim, &st);
    double n = frames > 0 ? (double)frames : 1.0;
    s->volume = st.volume_ms / n;
    s->surface = st.surface_ms / n;
    s->extract = st.extract_ms / n;
    s->combine = st.combine_ms / n;
    s->write = 1e3 * write_s / n;
    s->png = 1e3 * png_s / n;
}

/* Everything one run holds; run_open fills it, run_close frees it. */
typedef struct run_state {
    run_opts o;
    ms_scene *sc;
    ms_sim *sim;
    ms_writer *w;
    char *out; /* run file name, NULL with --no-out */
    tool_png png;
    ms_grid grid;
    float dt;                    /* s per frame */
    long frames;                 /* frames to step */
    int every;                   /* write every N-th published frame */
    long done, written;          /* frames stepped, frames written */
    long base;                   /* of done, the frames a --resume replayed before the loop */
    double write_s, png_s, wall; /* s spent writing HDF5 / PNG, s of the loop */
} run_state;

/* Load the scene, build the sim, open the PNG folder and the run file.
 * Returns EXIT_OK or the exit code; on failure nothing stays open. */
static int run_open(run_state *r)
{
    run_opts *o = &r->o;
    if (tool_load_scene(o->scene, &o->sets, &r->sc) != 0)
        return EXIT_USAGE;
    r->dt = ms_scene_frame_dt(r->sc);
    r->frames = o->frames;
    if (r->frames < 0 && tool_scene_frames(r->sc, o->scene, o->duration, &r->frames) != 0)
        return EXIT_USAGE;
    r->every = ms_scene_output_every(r->sc);

    if (ms_sim_create_from_scene(r->sc, o->threads, &r->sim) != MS_OK) {
        tool_error("%s: %s", o->scene, ms_last_error());
        return EXIT_USAGE;
    }
    if (tool_check_frame_work(r->sc, r->sim, o->scene) != 0)
        return EXIT_USAGE;
    if (!o->resume && !o->no_out) {
        /* before the PNG folder: a refused run leaves nothing behind */
        int rc = EXIT_RUNTIME;
        r->out = o->out ? strdup(o->out) : default_out(o->scene);
        if (!r->out)
            tool_error("run: out of memory");
        else
            rc = tool_refuse_replace("run", r->out, r->sim, o->force);
        if (rc != EXIT_OK)
            return rc;
    }
    /* The PNG directory first: a --png that cannot be used (a file, no
     * permission) must not leave an empty run file and sidecar behind. */
    if (o->png && png_begin(&r->png, o->png, r->sc, o->preview, o->quiet) != 0)
        return EXIT_RUNTIME;
    if (o->resume) {
        r->out = strdup(o->resume);
        int rc = r->out ? resume_run(r->out, r->sim, r->dt, r->every, r->frames, o->quiet, &r->w,
                                     &r->done, &r->written)
                        : EXIT_RUNTIME;
        if (rc != EXIT_OK)
            return rc;
    } else if (!o->no_out) {
        if (ms_writer_open(r->out, r->sim, 0, &r->w) != MS_OK) {
            tool_error("%s", ms_last_error());
            return EXIT_RUNTIME;
        }
    }
    ms_sim_field_grid(r->sim, MS_FIELD_COMBINED, &r->grid);
    r->png.sim = r->sim; /* the renderer draws the sim's floaters and boat too */
    return EXIT_OK;
}

/* Write published frame `done - 1` to the run file and the PNG folder. */
static int run_write_frame(run_state *r)
{
    double t0 = tool_now();
    if (r->w && ms_writer_frame(r->w, r->sim) != MS_OK) {
        tool_error("%s", ms_last_error());
        return EXIT_RUNTIME;
    }
    double t1 = tool_now();
    if (r->o.png) {
        int nx, ny;
        const float *h = ms_sim_height(r->sim, &nx, &ny);
        if (png_frame(&r->png, r->written, h, &r->grid, ms_sim_time(r->sim)) != 0)
            return EXIT_RUNTIME;
    }
    r->write_s += t1 - t0;
    r->png_s += tool_now() - t1;
    ++r->written;
    return EXIT_OK;
}

/* Step the frames, writing every `every`-th; stops early on a signal. */
static int run_frames(run_state *r)
{
    running_sim = r->sim;
    catch_stop_signals();
    tool_progress prog;
    progress_begin(&prog, r->frames, r->o.quiet);
    prog.base = r->done; /* frames a --resume replayed: not stepped in this loop's time */
    r->base = r->done;
    int rc = EXIT_OK;
    while (r->done < r->frames && !stop_signal) {
        ms_status step_st = ms_sim_step(r->sim, r->dt);
        if (step_st == MS_ERR_CANCELED && stop_signal)
            break; /* a second signal: the frame in hand is dropped */
        if (step_st != MS_OK) {
            progress_end(&prog);
            tool_error("frame %ld: %s", r->done, ms_last_error());
            rc = EXIT_RUNTIME;
            break;
        }
        ++r->done;
        /* The sim publishes a frame one step behind (its first step
         * publishes the start): write published frames 0, every, 2 every... */
        if ((r->done - 1) % r->every == 0) {
            rc = run_write_frame(r);
            if (rc != EXIT_OK) {
                progress_end(&prog);
                break;
            }
        }
        tool_stages st;
        fill_stages(r->sim, r->write_s, r->png_s, r->done, &st);
        progress_update(&prog, r->done, &st);
    }
    progress_end(&prog);
    r->wall = tool_now() - prog.start;
    return rc;
}

static void print_summary(const run_state *r, long in_file, const char *xmf)
{
    tool_stages st;
    fill_stages(r->sim, r->write_s, r->png_s, r->done, &st);
    printf("modesplit: %s: %ld of %ld frames (%.4g s simulated) in %.3g s, %.1f frames/s%s\n",
           ms_scene_name(r->sc), r->done, r->frames, ms_sim_time(r->sim), r->wall,
           r->wall > 0 ? (double)(r->done - r->base) / r->wall : 0.0,
           stop_signal ? (stop_signal == SIGINT ? ", stopped by SIGINT" : ", stopped by SIGTERM")
                       : "");
    printf("  per frame: volume %.3g ms, surface %.3g ms, extract %.3g ms, combine %.3g ms",
           st.volume, st.surface, st.extract, st.combine);
    if (r->out)
        printf(", write %.3g ms", st.write);
    if (r->o.png)
        printf(", png %.3g ms", st.png);
    printf("\n");
    if (r->out) {
        struct stat sb;
        char buf[32];
        printf("  wrote %s (%ld frames, %s) and %s\n", r->out, in_file,
               stat(r->out, &sb) == 0 ? tool_bytes((double)sb.st_size, buf, sizeof buf) : "?",
               xmf ? xmf : "");
    }
    if (r->o.png)
        printf("  wrote %ld PNG frames to %s\n", r->png.written, r->o.png);
    fflush(stdout);
}

/* Close the run file (its error turns rc into EXIT_RUNTIME) and print the
 * summary, which names the sidecars the writer made. */
static int run_finish(run_state *r, int rc)
{
    long in_file = r->w ? ms_writer_frames(r->w) : 0;
    char *xmf = NULL;
    if (r->w) {
        const char *a = ms_writer_xdmf_path(r->w), *b = ms_writer_xdmf_legacy_path(r->w);
        size_t n = strlen(a) + strlen(b) + 64;
        xmf = malloc(n);
        if (xmf)
            snprintf(xmf, n, "%s (ParaView), %s (legacy XDMF reader, VisIt)", a, b);
    }
    if (r->w && ms_writer_close(r->w) != MS_OK) {
        tool_error("%s", ms_last_error());
        rc = EXIT_RUNTIME;
    }
    r->w = NULL;
    if (r->o.png && png_finish(&r->png) != 0) /* the PNG frames still queued */
        rc = EXIT_RUNTIME;
    if (!r->o.quiet)
        print_summary(r, in_file, xmf);
    free(xmf);
    return rc;
}

/* Free what run_open made (the run file is already closed or never opened
 * unless run_open failed half-way). */
static void run_close(run_state *r)
{
    if (r->w)
        ms_writer_close(r->w);
    free(r->out);
    png_end(&r->png);
    running_sim = NULL;
    ms_sim_destroy(r->sim);
    ms_scene_destroy(r->sc);
}

int cmd_run(int argc, char **argv)
{
    run_state r;
    memset(&r, 0, sizeof r);
    int rc = parse_args(argc, argv, &r.o);
    if (rc < 0)
        return EXIT_OK; /* --help */
    if (rc != EXIT_OK)
        return rc;
    rc = run_open(&r);
    if (rc == EXIT_OK) {
        rc = run_frames(&r);
        rc = run_finish(&r, rc);
    }
    run_close(&r);
    if (stop_signal) {
        /* end as the signal would have, so the shell sees it */
        signal((int)stop_signal, SIG_DFL);
        raise((int)stop_signal);
    }
    return rc;
}
