/* The `modesplit` command-line tool: shared declarations.
 *
 * One file per command (cmd_run.c, cmd_info.c, cmd_check.c, cmd_plugins.c),
 * main.c dispatches and holds the usage text, progress.c draws the progress
 * bar or lines, frames_png.c writes the PNG frames. The tool uses only the
 * public API of libmodesplit (it links the shared library).
 *
 * Exit status: 0 success, 1 a failure while running, 2 bad usage or bad
 * input. Messages go to stderr as one sentence each, "modesplit: ...".
 */
#ifndef MS_TOOL_H
#define MS_TOOL_H

#include <stddef.h>
#include <stdio.h>

#include "modesplit/modesplit.h"
#include "modesplit/plugin.h"

enum { EXIT_OK = 0, EXIT_RUNTIME = 1, EXIT_USAGE = 2 };

/* Strings from a file are data, not terminal commands: control
 * characters (ESC sequences that retitle or rewrite the terminal, CR, BEL,
 * ...), DEL and bytes that are not well-formed UTF-8 are written to f as
 * \xNN, the C1 controls U+0080..U+009F as \uNNNN; `keep` lists the
 * control characters written as they are. The one escaping of the tool: `info`, `--resume`, `export`,
 * the viewer and every tool_error message use it. */
void tool_put_escaped(FILE *f, const char *s, const char *keep);
/* Open a file to read only when it is a regular file: a FIFO would block
 * the open, /dev/zero never ends. NULL with *why the reason (errno kept
 * from the open, ENOENT for a missing file; 0 for a file that is not
 * regular). The tool's one such open: view --script logs and accuracy's
 * part files use it. */
FILE *tool_fopen_regular(const char *path, const char **why);
/* Print "modesplit: <message>\n" to stderr, the message escaped
 * (tool_put_escaped, newlines and tabs kept). */
void tool_error(const char *fmt, ...) __attribute__((format(printf, 1, 2)));
/* An output never overwrites an input: 0 when `out` (an option's file to
 * write) is not the existing file `in`, under any spelling or hard link
 * (same device and inode); else prints "CMD: OPTION OUT is WHAT IN: ..."
 * and returns -1. NULL names are never the same. */
int tool_refuse_same_file(const char *cmd, const char *option, const char *out, const char *what,
                          const char *in);
/* A run is replaced only on purpose: 0 when `force` is set or neither
 * `out` nor its XDMF sidecars exist (ms_writer_existing, which first gives
 * the writer's own refusals: EXIT_RUNTIME, the sentence printed); else
 * prints "CMD: OUT exists: pass --force to replace it, or choose another
 * --out" (naming the sidecar when that is the one there) and returns
 * EXIT_USAGE. */
int tool_refuse_replace(const char *cmd, const char *out, const ms_sim *sim, int force);
/* The usage text (modesplit --help) to f. */
void tool_usage(FILE *f);

/* Option parsing: argv[*i] is "--name" or "--name=value"; returns 1 and the
 * value (the next argument, consumed) when it matches `name`. A missing
 * value is a usage error reported here (*bad set). */
int tool_opt_value(int argc, char **argv, int *i, const char *name, const char **value, int *bad);
/* Strict number parsing: the whole string, finite, in [lo, hi]. */
int tool_parse_long(const char *s, long lo, long hi, long *out);
int tool_parse_double(const char *s, double lo, double hi, double *out);
/* "12.3 MB", "850 kB", "512 B" into buf. */
const char *tool_bytes(double bytes, char *buf, size_t size);

/* Frames a scene runs for `duration` s (< 0: the scene's own): at most
 * 1e9; 0 on success, else prints "<path>: ..." and returns -1. */
int tool_scene_frames(const ms_scene *sc, const char *path, double duration, long *frames);
/* 0, or -1 after printing why a frame of the scene's sim would not end in
 * reasonable time (a domain too small for its wave cells) or why its
 * render section would be refused by the renderer (a cubemap's faces);
 * cmd_check.c. `check` and `run` both call it. */
int tool_check_frame_work(const ms_scene *sc, ms_sim *sim, const char *path);

/* ---- --set KEY=VALUE (overrides.c) ---- */
#define TOOL_MAX_SETS 256
typedef struct tool_sets {
    int n;
    const char *v[TOOL_MAX_SETS]; /* views into argv */
} tool_sets;
/* argv[*i] is "--set": store its value in s and return 1 (*bad set, and a
 * message printed, when it is missing or not KEY=VALUE); else 0. */
int tool_set_option(int argc, char **argv, int *i, tool_sets *s, int *bad);
/* ms_scene_load_with_overrides; 0 on success, else prints and returns -1. */
int tool_load_scene(const char *path, const tool_sets *s, ms_scene **out);

int cmd_run(int argc, char **argv);
/* resume.c: --resume RUN.h5: replay sim to the file's last complete frame,
 * check it bit for bit, reopen the file to append; *done steps taken and
 * *written frames kept. 0 or an EXIT_* code (the error printed). */
int resume_run(const char *path, ms_sim *sim, float dt, int every, long frames, int quiet,
               ms_writer **w, long *done, long *written);
int cmd_info(int argc, char **argv);
int cmd_check(int argc, char **argv);
int cmd_plugins(int argc, char **argv);
int cmd_export(int argc, char **argv);
/* The progress line for a terminal of `width` columns: "[bar] core |
 * stages", dropping the stages, then the bar, then cutting the core, so it
 * never takes more than width - 1 columns (progress.c). */
void progress_fit(char *out, size_t size, int width, const char *bar, const char *core,
                  const char *stages);
/* One command's part of the usage text ("modesplit run --help"); -1 for
 * an unknown command. */
int tool_command_usage(FILE *f, const char *cmd);
/* "run: unknown option --frame; did you mean --frames?" from the options
 * the command's usage text lists. */
void tool_unknown_option(const char *cmd, const char *opt);
int cmd_view(int argc, char **argv); /* cmd_view.c, view_*.c */
/* the renderer's commands */
int cmd_render(int argc, char **argv);
int cmd_cubemap(int argc, char **argv);
int cmd_accuracy(int argc, char **argv);

/* ---- progress (progress.c) ---- */
typedef struct tool_progress {
    int tty; /* stderr is a terminal: one line redrawn */
    int quiet;
    long total;       /* frames to run */
    long base;        /* frames done before this run started (replayed by
                            --resume): not counted in frames/s */
    double start;     /* s, monotonic */
    double last_draw; /* s */
    int last_decile;  /* plain lines: last 10 % step printed */
} tool_progress;

/* Per-frame stage times, ms (averages over the frames so far). */
typedef struct tool_stages {
    double volume, surface, extract, combine, write, png;
} tool_stages;

double tool_now(void);
void progress_begin(tool_progress *p, long total, int quiet);
/* After frame `done` (1..total). */
void progress_update(tool_progress *p, long done, const tool_stages *s);
/* Clear the bar (before the summary or an error). */
void progress_end(tool_progress *p);

/* ---- PNG frames (frames_png.c) ---- */
typedef struct tool_png {
    char *dir;
    ms_renderer *renderer; /* the scene's renderer, NULL: shaded-relief previews */
    float lo, hi;          /* m, the colour range, widened as frames need */
    float relief;          /* vertical exaggeration, lowered as frames need */
    int have_range;
    long written;
    const ms_sim *sim;       /* set: the renderer draws its field with floaters and boat */
    struct png_queue *queue; /* the renderer's frames are encoded off the render thread */
} tool_png;

/* Create DIR (and its parents) if missing and, when the scene has a
 * `render` section and `preview` is 0, its renderer (without OSMesa: a
 * note, then previews). 0 on success, else prints. */
int png_begin(tool_png *p, const char *dir, const ms_scene *sc, int preview, int quiet);
/* Write DIR/frame_NNNNN.png of a height field at time t (s); 0 on
 * success, else prints. */
int png_frame(tool_png *p, long index, const float *h, const ms_grid *g, double t);
/* Wait until every frame handed over is written; 0, or -1 (printed) if one
 * could not be. */
int png_finish(tool_png *p);
void png_end(tool_png *p);

/* ---- PNG encoding off the render thread (png_queue.c) ---- */
/* One writer thread encodes the frames pushed, in order, with
 * ms_image_write_png; push copies the pixels and blocks while 2 frames
 * wait; finish writes what is queued, stops the thread and frees q.
 * Each returns 0, or -1 after printing why (push: an earlier frame could
 * not be written). */
typedef struct png_queue png_queue;
int png_queue_start(png_queue **q);
int png_queue_push(png_queue *q, const char *path, const unsigned char *rgba, int w, int h);
int png_queue_finish(png_queue *q);

#endif /* MS_TOOL_H */
