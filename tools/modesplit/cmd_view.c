/* modesplit view SCENE.json: the scene in a window, in real time, handled
 * with the mouse and keys (the paper's Fig. 1: "The water can be handled
 * interactively by mouse dragging").
 *
 * SDL2 makes the window and its OpenGL context; the library's renderer
 * draws into that context (ms_renderer_create_in_context), then the
 * overlay is drawn over it and the buffers swapped. One loop iteration:
 * input (live, or replayed from --script), the effects of held keys and
 * the drag (view_input.c), one ms_sim_step when running, a draw, pacing
 * to the scene's frame_dt (F: as fast as it can). Everything that acts on
 * the sim is keyed by the frame it happened in, so a recorded session
 * (--record-input) replays to the same bytes. */
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "tool.h"

#if !MS_HAVE_SDL2
int cmd_view(int argc, char **argv)
{
    (void)argc, (void)argv;
    tool_error("view: this modesplit was built without SDL2, so it cannot open a window; "
               "install libsdl2-dev and rebuild");
    return EXIT_USAGE;
}
#else
#include <SDL.h>
#include <SDL_syswm.h>
#include <dlfcn.h>

#include "view.h"
#include "view_gl.h"

/* A window destroyed by another client (xdotool windowclose, a window
 * manager's kill) gets no SDL event: the next request SDL or GLX makes on
 * it fails with BadWindow or BadDrawable, which Xlib's default handler
 * (SDL chains to it) reports by ending the process with status 1. So the
 * viewer puts its own handler in front: an error about its own window
 * marks it gone, and the loop ends as if the window had been closed; any
 * other X error goes on to the handler that was there. Xlib keeps one
 * handler per process, hence the file-static state. libX11 is already
 * loaded by SDL; its XSetErrorHandler is looked up, not linked, so the
 * tool links no X library. */
typedef int (*x_error_handler)(Display *, XErrorEvent *);
static x_error_handler x_previous;
static unsigned long x_window; /* the viewer's X window, 0: not on X11 */
static volatile int x_window_gone;

static int x_error(Display *d, XErrorEvent *e)
{
    if (x_window && e->resourceid == x_window) {
        x_window_gone = 1;
        return 0;
    }
    return x_previous ? x_previous(d, e) : 0;
}

static Display *x_display;
static Status (*x_get_attributes)(Display *, Window, XWindowAttributes *);
static int (*x_grab)(Display *), (*x_ungrab)(Display *), (*x_flush)(Display *);
static int x_grab_frames; /* software GLX: each frame's drawing under a server grab */

/* 1 while the viewer's window exists, asked of the X server in one round
 * trip (a failure reaches x_error, which marks the window gone). Asked
 * before each frame's drawing: Mesa's software GLX draws into a window
 * the server no longer has at a size of 0 and its rasteriser threads then
 * write out of bounds (a SIGSEGV in llvmpipe, 1 run in 3 of a window
 * closed by xdotool), so no GL call may reach a destroyed window. With
 * software GLX the check and the frame's drawing run under a server grab
 * (x_frame_begin), so no other client can destroy the window in between;
 * its swap is an XPutImage that waits for no other client, so the grab
 * lasts one frame's drawing. A hardware driver's swap may wait for a
 * compositor, which a grab would block: there the check alone is made. */
static int x_window_alive(void)
{
    if (!x_window || x_window_gone)
        return !x_window_gone;
    XWindowAttributes a;
    if (x_get_attributes && !x_get_attributes(x_display, (Window)x_window, &a))
        x_window_gone = 1;
    return !x_window_gone;
}

static void x_frame_begin(void)
{
    if (x_grab_frames && x_window && !x_window_gone)
        x_grab(x_display);
}

static void x_frame_end(void)
{
    if (x_grab_frames && x_window) {
        x_ungrab(x_display);
        x_flush(x_display);
    }
}

static void *x_symbol(const char *name)
{
    return dlsym(RTLD_DEFAULT, name);
}

static void watch_x_window(SDL_Window *win)
{
    SDL_SysWMinfo info;
    SDL_VERSION(&info.version);
    if (!SDL_GetWindowWMInfo(win, &info) || info.subsystem != SDL_SYSWM_X11)
        return;
    x_error_handler (*set)(x_error_handler) = NULL;
    void *sym = dlsym(RTLD_DEFAULT, "XSetErrorHandler");
    memcpy(&set, &sym, sizeof set); /* a data pointer to a function pointer, as POSIX allows */
    if (!set)
        return;
    sym = x_symbol("XGetWindowAttributes");
    memcpy(&x_get_attributes, &sym, sizeof x_get_attributes);
    sym = x_symbol("XGrabServer");
    memcpy(&x_grab, &sym, sizeof x_grab);
    sym = x_symbol("XUngrabServer");
    memcpy(&x_ungrab, &sym, sizeof x_ungrab);
    sym = x_symbol("XFlush");
    memcpy(&x_flush, &sym, sizeof x_flush);
    x_display = info.info.x11.display;
    x_window = (unsigned long)info.info.x11.window;
    x_previous = set(x_error);
}

typedef struct view_opts {
    const char *scene, *record_dir, *record_input, *script, *out;
    int w, h, threads, fast, force; /* force: --out may replace a run file */
    long frames;                    /* -1: until closed */
} view_opts;

static int parse_size(const char *s, int *w, int *h)
{
    char x, extra;
    return sscanf(s, "%d%c%d%c", w, &x, h, &extra) == 3 && (x == 'x' || x == 'X') && *w >= 16 &&
           *h >= 16 && *w <= MS_RENDER_MAX_SIDE && *h <= MS_RENDER_MAX_SIDE &&
           (long)*w * *h <= MS_RENDER_MAX_PIXELS;
}

static int parse_args(int argc, char **argv, view_opts *o)
{
    memset(o, 0, sizeof *o);
    o->frames = -1;
    for (int i = 1; i < argc; ++i) {
        const char *v = NULL, *a = argv[i];
        int bad = 0;
        if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
            tool_command_usage(stdout, "view");
            return -1;
        } else if (tool_opt_value(argc, argv, &i, "--size", &v, &bad)) {
            if (bad)
                return EXIT_USAGE;
            if (!parse_size(v, &o->w, &o->h)) {
                tool_error("view: --size %s must be WxH pixels, each in [16, %d], at most %ld "
                           "pixels in all",
                           v, MS_RENDER_MAX_SIDE, MS_RENDER_MAX_PIXELS);
                return EXIT_USAGE;
            }
        } else if (tool_opt_value(argc, argv, &i, "--threads", &v, &bad)) {
            long t;
            if (bad)
                return EXIT_USAGE;
            if (!tool_parse_long(v, 1, 2, &t)) {
                tool_error("view: --threads %s must be 1 (sequential) or 2 (two-core split)", v);
                return EXIT_USAGE;
            }
            o->threads = (int)t;
        } else if (tool_opt_value(argc, argv, &i, "--frames", &v, &bad)) {
            if (bad)
                return EXIT_USAGE;
            if (!tool_parse_long(v, 0, 1000000000L, &o->frames)) {
                tool_error("view: --frames %s is not a whole number in [0, 1e9]", v);
                return EXIT_USAGE;
            }
        } else if (tool_opt_value(argc, argv, &i, "--record", &v, &bad)) {
            if (bad || !*v) {
                tool_error("view: --record needs a directory");
                return EXIT_USAGE;
            }
            o->record_dir = v;
        } else if (tool_opt_value(argc, argv, &i, "--record-input", &v, &bad)) {
            if (bad || !*v) {
                tool_error("view: --record-input needs a file name");
                return EXIT_USAGE;
            }
            o->record_input = v;
        } else if (tool_opt_value(argc, argv, &i, "--script", &v, &bad)) {
            if (bad || !*v) {
                tool_error("view: --script needs an input log (written by --record-input)");
                return EXIT_USAGE;
            }
            o->script = v;
        } else if (tool_opt_value(argc, argv, &i, "--out", &v, &bad)) {
            if (bad || !*v) {
                tool_error("view: --out needs a file name");
                return EXIT_USAGE;
            }
            o->out = v;
        } else if (!strcmp(a, "--fast")) {
            o->fast = 1;
        } else if (!strcmp(a, "--force")) {
            o->force = 1;
        } else if (a[0] == '-' && a[1]) {
            tool_error("view: unknown option %s (see modesplit view --help)", a);
            return EXIT_USAGE;
        } else if (o->scene) {
            tool_error("view: one scene at a time (got %s and %s)", o->scene, a);
            return EXIT_USAGE;
        } else {
            o->scene = a;
        }
    }
    if (!o->scene) {
        tool_error("view: which scene? usage: modesplit view SCENE.json [--size WxH] [--threads "
                   "1|2] [--record DIR] [--record-input FILE] [--script FILE] [--frames N] "
                   "[--fast] [--out RUN.h5 [--force]]");
        return EXIT_USAGE;
    }
    return 0;
}

typedef struct viewer {
    view_opts o;
    ms_scene *sc;
    ms_sim *sim;
    ms_writer *writer;
    ms_renderer *r;
    SDL_Window *win;
    SDL_GLContext ctx;
    view_state v;
    view_script script;
    FILE *log;
    unsigned char *pixels; /* the window read back (--record, F12) */
    size_t pixels_cap;
    ms_stats before, after; /* around the last step */
    double fps, fps_t0;
    long fps_frames, screenshots, recorded;
    double render_ms_sum, step_ms_sum; /* for the summary: draws after a step, steps */
    char title[160];
} viewer;

static int make_renderer(viewer *vw)
{
    ms_renderer_destroy(vw->r); /* with the context current */
    vw->r = NULL;
    view_state *v = &vw->v;
    v->rdesc.width = v->w;
    v->rdesc.height = v->h;
    view_camera_eye(&v->cam, v->rdesc.eye);
    memcpy(v->rdesc.target, v->cam.target, sizeof v->rdesc.target);
    v->rdesc.up[0] = v->rdesc.up[1] = 0, v->rdesc.up[2] = 1;
    v->rdesc.fov = v->cam.fov;
    if (ms_renderer_create_in_context(&v->rdesc, &vw->r) != MS_OK) {
        tool_error("view: the renderer: %s", ms_last_error());
        return -1;
    }
    v->renderer_stale = v->camera_moved = 0;
    return 0;
}

/* A new GL context for the window (at start, and after one was lost) with
 * the renderer in it. */
static int make_context(viewer *vw)
{
    if (vw->ctx) {
        ms_renderer_destroy(vw->r); /* its objects go with the old context */
        vw->r = NULL;
        SDL_GL_DeleteContext(vw->ctx);
    }
    vw->ctx = SDL_GL_CreateContext(vw->win);
    if (!vw->ctx) {
        tool_error("view: no OpenGL context for the window: %s", SDL_GetError());
        return -1;
    }
    SDL_GL_SetSwapInterval(0); /* the loop paces itself at frame_dt */
    if (view_gl_load() != 0) {
        tool_error("view: the window's OpenGL lacks the calls the overlay needs (OpenGL 2.1 "
                   "compatibility profile)");
        return -1;
    }
    return make_renderer(vw);
}

/* The context is gone (the driver lost it, or the test's lose-context):
 * drop the renderer without touching GL, make both again. */
static int lose_context(viewer *vw)
{
    SDL_GL_MakeCurrent(vw->win, NULL);
    SDL_GL_DeleteContext(vw->ctx);
    vw->ctx = NULL;
    ms_renderer_destroy(vw->r); /* no context current: nothing to delete */
    vw->r = NULL;
    printf("view: the OpenGL context was lost; made a new one\n");
    return make_context(vw);
}

/* v as the input log writes and reads it ("%.6f"), so a live session and
 * its replay give the sim the same floats. */
static float as_logged(float v, const char *fmt)
{
    char buf[32];
    float out = v;
    snprintf(buf, sizeof buf, fmt, (double)v);
    sscanf(buf, "%f", &out);
    return out;
}

/* SDL's event as the viewer's; 0 if it is not one the viewer uses. */
static int from_sdl(const viewer *vw, const SDL_Event *e, view_event *out)
{
    memset(out, 0, sizeof *out);
    out->frame = ms_sim_frame(vw->sim);
    const float w = (float)vw->v.w, h = (float)vw->v.h;
    switch (e->type) {
    case SDL_QUIT:
        out->type = VIEW_QUIT;
        return 1;
    case SDL_KEYDOWN:
    case SDL_KEYUP:
        if (e->key.repeat)
            return 0;
        out->type = e->type == SDL_KEYDOWN ? VIEW_KEY_DOWN : VIEW_KEY_UP;
        snprintf(out->key, sizeof out->key, "%s", SDL_GetKeyName(e->key.keysym.sym));
        return out->key[0] != '\0';
    case SDL_MOUSEBUTTONDOWN:
    case SDL_MOUSEBUTTONUP:
        if (e->button.button < 1 || e->button.button > 3)
            return 0;
        out->type = e->type == SDL_MOUSEBUTTONDOWN ? VIEW_BUTTON_DOWN : VIEW_BUTTON_UP;
        out->button = e->button.button;
        out->x = as_logged(SDL_clamp((float)e->button.x / w, 0.0f, 1.0f), "%.6f");
        out->y = as_logged(SDL_clamp((float)e->button.y / h, 0.0f, 1.0f), "%.6f");
        out->shift = (SDL_GetModState() & KMOD_SHIFT) != 0;
        return 1;
    case SDL_MOUSEMOTION:
        out->type = VIEW_MOTION;
        out->x = as_logged(SDL_clamp((float)e->motion.x / w, 0.0f, 1.0f), "%.6f");
        out->y = as_logged(SDL_clamp((float)e->motion.y / h, 0.0f, 1.0f), "%.6f");
        return 1;
    case SDL_MOUSEWHEEL:
        out->type = VIEW_WHEEL;
        out->wheel = as_logged(
            (float)e->wheel.y * (e->wheel.direction == SDL_MOUSEWHEEL_FLIPPED ? -1 : 1), "%.3f");
        return out->wheel != 0;
    case SDL_WINDOWEVENT:
        if (e->window.event == SDL_WINDOWEVENT_SIZE_CHANGED) {
            out->type = VIEW_RESIZE;
            out->w = SDL_clamp(e->window.data1, 16, MS_RENDER_MAX_SIDE);
            out->h = SDL_clamp(e->window.data2, 16, MS_RENDER_MAX_SIDE);
            return out->w != vw->v.w || out->h != vw->v.h;
        }
        if (e->window.event == SDL_WINDOWEVENT_CLOSE) {
            out->type = VIEW_QUIT;
            return 1;
        }
        return 0;
    default:
        return 0;
    }
}

static int apply(viewer *vw, const view_event *e)
{
    if (vw->log && (view_log_write(vw->log, e) != 0 || fflush(vw->log) != 0)) {
        tool_error("view: %s: cannot write the input log: %s", vw->o.record_input, strerror(errno));
        return -1;
    }
    return view_apply_event(&vw->v, e);
}

/* This iteration's input: SDL's queue (while a script plays, only closing
 * the window counts), then the script's events of the current frame. */
static int input(viewer *vw)
{
    SDL_Event e;
    view_event ve;
    while (SDL_PollEvent(&e)) {
        if (!from_sdl(vw, &e, &ve))
            continue;
        if (vw->script.ev && vw->script.next < vw->script.n && ve.type != VIEW_QUIT &&
            ve.type != VIEW_RESIZE)
            continue;
        if (apply(vw, &ve) != 0)
            return -1;
    }
    const long frame = ms_sim_frame(vw->sim);
    view_script *s = &vw->script;
    while (s->next < s->n && s->ev[s->next].frame <= frame) {
        if (s->ev[s->next].type == VIEW_RESIZE)
            SDL_SetWindowSize(vw->win, s->ev[s->next].w, s->ev[s->next].h);
        if (apply(vw, &s->ev[s->next++]) != 0)
            return -1;
        if (vw->v.step_once)
            break; /* N: the step comes before the events of the next frame */
    }
    return 0;
}

static int step(viewer *vw)
{
    if (view_before_step(&vw->v) != 0)
        return -1;
    vw->before = ms_stats_init();
    ms_sim_get_stats(vw->sim, &vw->before);
    ms_status st = ms_sim_step(vw->sim, vw->v.frame_dt);
    if (st != MS_OK) {
        tool_error("view: frame %ld: %s", ms_sim_frame(vw->sim) + 1, ms_last_error());
        return -1;
    }
    vw->after = ms_stats_init();
    ms_sim_get_stats(vw->sim, &vw->after);
    vw->step_ms_sum += vw->after.total_ms - vw->before.total_ms;
    if (vw->writer && ms_writer_frame(vw->writer, vw->sim) != MS_OK) {
        tool_error("view: %s: %s", vw->o.out, ms_last_error());
        return -1;
    }
    vw->fps_frames++;
    double now = tool_now();
    if (now - vw->fps_t0 >= 0.5) {
        vw->fps = (double)vw->fps_frames / (now - vw->fps_t0);
        vw->fps_t0 = now;
        vw->fps_frames = 0;
    }
    return 0;
}

/* The window's back buffer, top row first, into vw->pixels. */
static int read_window(viewer *vw)
{
    const int w = vw->v.w, h = vw->v.h;
    size_t need = (size_t)w * (size_t)h * 4;
    if (vw->pixels_cap < need) {
        free(vw->pixels);
        vw->pixels = malloc(need);
        vw->pixels_cap = vw->pixels ? need : 0;
        if (!vw->pixels) {
            tool_error("view: out of memory for a %d x %d picture", w, h);
            return -1;
        }
    }
    const view_gl *gl = &view_gl_fn;
    gl->BindFramebuffer(GL_FRAMEBUFFER, 0);
    gl->ReadBuffer(GL_BACK);
    gl->PixelStorei(GL_PACK_ALIGNMENT, 1);
    gl->ReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, vw->pixels);
    const size_t row = (size_t)w * 4;
    unsigned char *tmp = malloc(row);
    if (!tmp)
        return -1;
    for (int y = 0; y < h / 2; ++y) {
        unsigned char *a = vw->pixels + (size_t)y * row,
                      *b = vw->pixels + (size_t)(h - 1 - y) * row;
        memcpy(tmp, a, row);
        memcpy(a, b, row);
        memcpy(b, tmp, row);
    }
    free(tmp);
    for (size_t i = 3; i < need; i += 4)
        vw->pixels[i] = 255; /* the window is opaque */
    return 0;
}

static int save_png(viewer *vw, const char *path)
{
    if (read_window(vw) != 0)
        return -1;
    if (view_png_write(path, vw->pixels, vw->v.w, vw->v.h) != 0) {
        tool_error("view: %s: cannot write the PNG: %s", path, strerror(errno));
        return -1;
    }
    return 0;
}

static int draw_frame(viewer *vw, int stepped)
{
    view_state *v = &vw->v;
    const view_gl *gl = &view_gl_fn;
    if (v->renderer_stale && make_renderer(vw) != 0)
        return -1;
    if (v->camera_moved) {
        float eye[3], up[3] = {0, 0, 1};
        view_camera_eye(&v->cam, eye);
        if (ms_renderer_set_camera(vw->r, eye, v->cam.target, up, v->cam.fov) != MS_OK) {
            tool_error("view: the camera: %s", ms_last_error());
            return -1;
        }
        v->camera_moved = 0;
    }
    double render_ms = 0;
    if (ms_sim_frame(vw->sim) > 0) {
        gl->BindFramebuffer(GL_FRAMEBUFFER, 0);
        if (ms_renderer_draw(vw->r, vw->sim) != MS_OK) {
            /* the context may be lost: a new one, and one more try */
            tool_error("view: drawing: %s", ms_last_error());
            if (lose_context(vw) != 0 || ms_renderer_draw(vw->r, vw->sim) != MS_OK)
                return -1;
        }
        ms_render_stats rs = ms_render_stats_init();
        ms_renderer_get_stats(vw->r, &rs);
        render_ms = rs.total_ms;
        if (stepped)
            vw->render_ms_sum += render_ms;
    } else {
        gl->BindFramebuffer(GL_FRAMEBUFFER, 0);
        gl->ClearColor(0, 0, 0, 1);
        gl->Clear(GL_COLOR_BUFFER_BIT);
    }
    view_overlay_info in = {
        .scene = ms_scene_name(vw->sc),
        .frame = ms_sim_frame(vw->sim),
        .time = ms_sim_time(vw->sim),
        .fps = vw->fps,
        .paced = v->paced,
        .paused = v->paused,
        .render_ms = render_ms,
        .threads = vw->o.threads,
        .shader = v->rdesc.shader,
        .caustics = v->rdesc.caustics,
        .rain = v->rain,
    };
    ms_sim_info info = ms_sim_info_init();
    ms_sim_get_info(vw->sim, &info);
    in.particles = info.particles;
    in.threads = info.threads;
    char text[1024];
    view_overlay_text(&in, &vw->before, &vw->after, text, sizeof text);
    if (v->status[0]) {
        size_t n = strlen(text);
        snprintf(text + n, sizeof text - n, "\n> %s", v->status);
    }
    view_overlay_draw(text, v->w, v->h, 1);
    if (v->help)
        view_overlay_draw(view_help_text, v->w, v->h, 0);
    if (stepped && vw->o.record_dir) {
        char path[4200];
        snprintf(path, sizeof path, "%s/frame_%05ld.png", vw->o.record_dir, ms_sim_frame(vw->sim));
        if (save_png(vw, path) != 0)
            return -1;
        vw->recorded++;
    }
    if (v->screenshot) {
        v->screenshot = 0;
        char path[4200];
        snprintf(path, sizeof path, "%s%smodesplit_view_%05ld_%ld.png",
                 vw->o.record_dir ? vw->o.record_dir : "", vw->o.record_dir ? "/" : "",
                 ms_sim_frame(vw->sim), ++vw->screenshots);
        if (save_png(vw, path) != 0)
            return -1;
        snprintf(v->status, sizeof v->status, "saved %.80s", path);
        printf("view: %s\n", v->status);
        fflush(stdout);
    }
    SDL_GL_SwapWindow(vw->win);
    return 0;
}

/* One frame's drawing, none once another program destroyed the window
 * (run() then ends the loop). */
static int draw(viewer *vw, int stepped)
{
    x_frame_begin();
    int rc = x_window_alive() ? draw_frame(vw, stepped) : 0;
    x_frame_end();
    return rc;
}

static int mkdirs(const char *dir)
{
    char buf[4096];
    snprintf(buf, sizeof buf, "%s", dir);
    for (char *p = buf + 1;; ++p) {
        if (*p == '/' || *p == '\0') {
            char c = *p;
            *p = '\0';
            if (mkdir(buf, 0777) != 0 && errno != EEXIST)
                return -1;
            if (!c)
                return 0;
            *p = c;
        }
    }
}

static int open_window(viewer *vw)
{
    const char *display = getenv("DISPLAY"), *wayland = getenv("WAYLAND_DISPLAY");
    if ((!display || !*display) && (!wayland || !*wayland)) {
        tool_error("view: no display to open a window on (DISPLAY is not set); run it in a "
                   "desktop session or under xvfb-run");
        return EXIT_USAGE;
    }
    /* Without a Wayland display SDL may only use X11: left to choose, it
     * would try Wayland (which prints its own complaint) and then fall back
     * to its offscreen driver when DISPLAY names a server it cannot reach,
     * and run the scene with no window. A driver the user names is kept. */
    const char *asked = getenv("SDL_VIDEODRIVER");
    if ((!asked || !*asked) && (!wayland || !*wayland))
        setenv("SDL_VIDEODRIVER", "x11", 1);
    if (SDL_Init(SDL_INIT_VIDEO) != 0) {
        tool_error("view: no display to open a window on (DISPLAY=%s: %s); run it in a desktop "
                   "session or under xvfb-run",
                   display && *display ? display : "(unset)", SDL_GetError());
        return EXIT_USAGE;
    }
    /* the offscreen and dummy drivers make windows nobody sees */
    const char *driver = SDL_GetCurrentVideoDriver();
    if (!driver || !strcmp(driver, "offscreen") || !strcmp(driver, "dummy")) {
        tool_error("view: no display to open a window on (SDL's only video driver here is "
                   "\"%s\", which shows no window); run it in a desktop session or under "
                   "xvfb-run",
                   driver ? driver : "none");
        return EXIT_USAGE;
    }
    SDL_GL_SetAttribute(SDL_GL_CONTEXT_MAJOR_VERSION, 2);
    SDL_GL_SetAttribute(SDL_GL_CONTEXT_MINOR_VERSION, 1);
    SDL_GL_SetAttribute(SDL_GL_DOUBLEBUFFER, 1);
    SDL_GL_SetAttribute(SDL_GL_DEPTH_SIZE, 0); /* the renderer draws into its own buffers */
    snprintf(vw->title, sizeof vw->title, "modesplit \xe2\x80\x94 %s", ms_scene_name(vw->sc));
    vw->win = SDL_CreateWindow(vw->title, SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED, vw->v.w,
                               vw->v.h, SDL_WINDOW_OPENGL | SDL_WINDOW_RESIZABLE);
    if (!vw->win) {
        tool_error("view: cannot open a %d x %d OpenGL window: %s", vw->v.w, vw->v.h,
                   SDL_GetError());
        return EXIT_RUNTIME;
    }
    watch_x_window(vw->win);
    /* the window manager may not give the size asked for */
    SDL_GL_GetDrawableSize(vw->win, &vw->v.w, &vw->v.h);
    if (make_context(vw) != 0)
        return EXIT_RUNTIME;
    const char *gpu = (const char *)view_gl_fn.GetString(GL_RENDERER);
    x_grab_frames = x_grab && x_ungrab && x_flush && gpu &&
                    (strstr(gpu, "llvmpipe") || strstr(gpu, "softpipe") || strstr(gpu, "swrast"));
    return EXIT_OK;
}

static int run(viewer *vw)
{
    view_state *v = &vw->v;
    v->paced = !vw->o.fast;
    vw->fps_t0 = tool_now();
    double next = tool_now();
    const double t_start = next;
    long stepped_total = 0, shown = 0;
    while (!v->quit) {
        if (input(vw) != 0)
            return EXIT_RUNTIME;
        if (x_window_gone)
            break;
        if (v->quit) {
            if (v->screenshot && draw(vw, 0) != 0) /* F12 then Esc: the picture first */
                return EXIT_RUNTIME;
            break;
        }
        if (v->lose_context) {
            v->lose_context = 0;
            if (lose_context(vw) != 0)
                return EXIT_RUNTIME;
        }
        int stepped = 0;
        if (!v->paused || v->step_once) {
            v->step_once = 0;
            if (step(vw) != 0)
                return EXIT_RUNTIME;
            stepped = 1;
            stepped_total++;
        }
        if (draw(vw, stepped) != 0 && !x_window_gone)
            return EXIT_RUNTIME;
        if (x_window_gone)
            break;
        /* --frames counts the frames shown, paused or not: a script that
         * pauses (and never resumes) still ends */
        if (vw->o.frames >= 0 && ++shown >= vw->o.frames)
            break;
        /* pacing: one frame each frame_dt of wall time (paused: about
         * the same rate of redraws); a late frame does not make the next
         * ones hurry */
        if (v->paced || v->paused) {
            next += v->frame_dt;
            double now = tool_now();
            if (next > now)
                SDL_Delay((Uint32)((next - now) * 1e3));
            else if (now - next > v->frame_dt)
                next = now;
        }
    }
    if (x_window_gone)
        printf("view: the window was closed by another program\n");
    double wall = tool_now() - t_start;
    const double per = stepped_total > 0 ? 1.0 / (double)stepped_total : 0.0;
    printf("view: %ld frames stepped in %.2f s (%.1f frames/s), %ld recorded; per frame: "
           "step %.1f ms, render %.1f ms\n",
           stepped_total, wall, wall > 0 ? (double)stepped_total / wall : 0.0, vw->recorded,
           vw->step_ms_sum * per, vw->render_ms_sum * per);
    return EXIT_OK;
}

static void close_all(viewer *vw)
{
    /* A window another program destroyed is left as it is: destroying it
     * again is an X error that arrives after SDL_Quit has put Xlib's
     * default handler back, which ends the process with status 1. Its GL
     * context and renderer go with the process, which ends next. */
    if (x_window_gone)
        vw->ctx = NULL, vw->win = NULL;
    if (vw->ctx) {
        SDL_GL_MakeCurrent(vw->win, vw->ctx);
        ms_renderer_destroy(vw->r);
        SDL_GL_DeleteContext(vw->ctx);
    }
    if (vw->win)
        SDL_DestroyWindow(vw->win);
    if (!x_window_gone)
        SDL_Quit();
    free(vw->pixels);
    view_script_free(&vw->script);
    if (vw->log)
        fclose(vw->log);
    vw->log = NULL;
}

int cmd_view(int argc, char **argv)
{
    viewer vw;
    memset(&vw, 0, sizeof vw);
    int rc = parse_args(argc, argv, &vw.o);
    if (rc != 0)
        return rc < 0 ? EXIT_OK : rc;
    if (ms_scene_load(vw.o.scene, &vw.sc) != MS_OK) {
        tool_error("%s", ms_last_error());
        return EXIT_USAGE;
    }
    char err[600];
    if (vw.o.script && view_script_load(vw.o.script, &vw.script, err, sizeof err) != 0) {
        tool_error("view: %s", err);
        ms_scene_destroy(vw.sc);
        return EXIT_USAGE;
    }
    ms_renderer_desc rd = ms_renderer_desc_default();
    if (ms_renderer_desc_from_scene(vw.sc, &rd) != MS_OK) {
        tool_error("view: %s", ms_last_error());
        view_script_free(&vw.script);
        ms_scene_destroy(vw.sc);
        return EXIT_USAGE;
    }
    if (vw.o.w)
        rd.width = vw.o.w, rd.height = vw.o.h;
    rc = EXIT_RUNTIME;
    if (ms_sim_create_from_scene(vw.sc, vw.o.threads, &vw.sim) != MS_OK) {
        tool_error("view: %s", ms_last_error());
        rc = EXIT_USAGE;
        goto done_sim;
    }
    view_state_init(&vw.v, vw.sim, &rd, ms_scene_frame_dt(vw.sc));
    /* an existing run is refused before anything is made */
    if ((rc = tool_refuse_replace("view", vw.o.out, vw.sim, vw.o.force)) != EXIT_OK)
        goto done_sim;
    rc = EXIT_RUNTIME;
    if (vw.o.record_dir && mkdirs(vw.o.record_dir) != 0) {
        tool_error("view: %s: cannot make the directory: %s", vw.o.record_dir, strerror(errno));
        goto done_sim;
    }
    /* the outputs are checked against the inputs, and the run file (whose
     * writer checks its own names against the scene) opened, before the
     * input log is written */
    if (tool_refuse_same_file("view", "--record-input", vw.o.record_input, "the scene file",
                              vw.o.scene) != 0 ||
        tool_refuse_same_file("view", "--record-input", vw.o.record_input, "the --script",
                              vw.o.script) != 0) {
        rc = EXIT_USAGE;
        goto done_sim;
    }
    if (vw.o.out && ms_writer_open(vw.o.out, vw.sim, 0, &vw.writer) != MS_OK) {
        tool_error("view: %s", ms_last_error());
        goto done_sim;
    }
    if (vw.o.record_input) {
        vw.log = fopen(vw.o.record_input, "w");
        if (!vw.log ||
            fprintf(vw.log, "%s\n# scene %s\n", VIEW_LOG_HEADER, ms_scene_name(vw.sc)) < 0) {
            tool_error("view: %s: cannot write the input log: %s", vw.o.record_input,
                       strerror(errno));
            goto done_sim;
        }
    }
    rc = open_window(&vw);
    if (rc == EXIT_OK)
        rc = run(&vw);
    close_all(&vw);
    if (vw.writer && ms_writer_close(vw.writer) != MS_OK && rc == EXIT_OK) {
        tool_error("view: %s", ms_last_error());
        rc = EXIT_RUNTIME;
    }
    vw.writer = NULL;
done_sim:
    if (vw.writer)
        ms_writer_close(vw.writer);
    if (vw.log)
        fclose(vw.log);
    view_script_free(&vw.script);
    ms_sim_destroy(vw.sim);
    ms_scene_destroy(vw.sc);
    return rc;
}
#endif
