/* modesplit run SCENE --resume RUN.h5: continue a run that was
 * killed or stopped, appending to its file.
 *
 * How: the file holds the sim's whole state (ms_sim_snapshot) with every
 * output.checkpoint_every-th written frame, the two newest kept. The
 * newest checkpoint of a complete frame is restored (ms_sim_restore; a torn
 * or refused one sends it to the older, then to the start) and only the
 * steps from there to the file's last complete frame are taken again
 * without writing (none with checkpoint_every 1). The sim is deterministic
 * (same scene, same build -> same bytes, with 1 or 2 threads), so that
 * frame's fields, time and particles are then compared bit for bit with
 * what the file holds before anything is appended. The file must come from
 * the same scene text and library version (ms_writer_open_append refuses
 * others, naming what differs); a state that does not give the file's
 * bytes (another platform or compiler) is refused too. A frame cut by the
 * kill is dropped and written again. Without checkpoints
 * (checkpoint_every 0) the whole run is stepped again (a replay).
 */
#include <errno.h>
#include <fcntl.h>
#include <stdlib.h>
#include <string.h>
#include <sys/file.h>
#include <unistd.h>

#include "tool.h"

/* Compare n floats bitwise; the first cell that differs or -1. */
static long first_diff(const float *a, const float *b, size_t n)
{
    for (size_t i = 0; i < n; ++i)
        if (memcmp(&a[i], &b[i], sizeof(float)) != 0)
            return (long)i;
    return -1;
}

/* The sim's published frame against frame k of the file: 0, -1 when it
 * differs (another build), -2 when the file is of another grid. */
static int verify_frame(const char *path, ms_reader *r, long k, const ms_sim *sim)
{
    static const unsigned bits[3] = {MS_FIELD_COMBINED, MS_FIELD_SURFACE, MS_FIELD_VOLUME};
    static const char *const names[3] = {"combined", "surface", "volume"};
    double t = 0;
    if (ms_reader_time(r, k, &t) != MS_OK) {
        tool_error("%s", ms_last_error());
        return -1;
    }
    if (memcmp(&t, &(double){ms_sim_time(sim)}, sizeof t) != 0) {
        tool_error("%s: frame %ld is at t = %.17g s, the replay at %.17g s: the file was "
                   "written with another output.every or frame_dt; cannot resume it",
                   path, k, t, ms_sim_time(sim));
        return -1;
    }
    unsigned have = ms_reader_fields(r);
    for (int i = 0; i < 3; ++i) {
        if (!(have & bits[i]))
            continue;
        int nx = 0, ny = 0;
        const float *h = i == 0   ? ms_sim_height(sim, &nx, &ny)
                         : i == 1 ? ms_sim_surface_height(sim, &nx, &ny)
                                  : ms_sim_volume_height(sim, &nx, &ny);
        /* a grid that differs is named as such: only equal grids can
         * differ by build or platform */
        ms_grid g;
        if (h && ms_reader_field_grid(r, bits[i], &g) == MS_OK && (g.nx != nx || g.ny != ny)) {
            tool_error("%s: its %s field is %d x %d cells, this scene's sim makes %d x %d: the "
                       "file was written with another grid, so it cannot be continued",
                       path, names[i], g.nx, g.ny, nx, ny);
            return -2;
        }
        size_t n = (size_t)nx * (size_t)ny;
        float *f = h ? malloc(n * sizeof *f) : NULL;
        if (!f || ms_reader_read_field(r, bits[i], k, f, n) != MS_OK) {
            tool_error("%s: frame %ld's %s field: %s", path, k, names[i],
                       f ? ms_last_error() : "the sim has no such field");
            free(f);
            return -1;
        }
        long d = first_diff(f, h, n);
        if (d >= 0) {
            tool_error("%s: frame %ld's %s field differs from this build's replay of the scene "
                       "(cell %ld: file %.9g m, replay %.9g m): another build or platform "
                       "wrote it, so this one cannot continue it bit for bit",
                       path, k, names[i], d, (double)f[d], (double)h[d]);
            free(f);
            return -1;
        }
        free(f);
    }
    if (have & MS_FIELD_PARTICLES) {
        int n = 0, m = 0;
        const float *pos[3], *vel[3];
        if (ms_reader_particle_count(r, k, &n) != MS_OK ||
            ms_sim_particles(sim, &m, pos, vel) != MS_OK) {
            tool_error("%s: frame %ld's particles: %s", path, k, ms_last_error());
            return -1;
        }
        float *buf = n > 0 ? malloc((size_t)n * 6 * sizeof *buf) : NULL;
        if (n != m || (n > 0 && !buf)) {
            tool_error("%s: frame %ld holds %d particles, the replay %d: cannot resume it", path, k,
                       n, m);
            free(buf);
            return -1;
        }
        float *fp[3], *fv[3];
        for (int c = 0; c < 3; ++c) {
            fp[c] = buf ? buf + (size_t)c * (size_t)n : NULL;
            fv[c] = buf ? buf + (size_t)(3 + c) * (size_t)n : NULL;
        }
        int bad = n > 0 && ms_reader_read_particles(r, k, n, fp, fv) != MS_OK;
        for (int c = 0; c < 3 && !bad && n > 0; ++c)
            bad = first_diff(fp[c], pos[c], (size_t)n) >= 0 ||
                  first_diff(fv[c], vel[c], (size_t)n) >= 0;
        free(buf);
        if (bad) {
            tool_error("%s: frame %ld's particles differ from this build's replay: cannot "
                       "continue it bit for bit",
                       path, k);
            return -1;
        }
    }
    return 0;
}

/* Restore the newest usable checkpoint of r into sim: the steps it stands
 * for (frame c is published by step c * every + 1), 0 with none, -1 when a
 * checkpoint broke the sim (a blob that passed its header's checks but not
 * its records: forged, never torn). */
static long restore_checkpoint(const char *path, ms_reader *r, ms_sim *sim, int every, int quiet)
{
    long at[2];
    int n = ms_reader_checkpoints(r, at);
    for (int i = 0; i < n; ++i) {
        size_t bytes = 0;
        void *blob = NULL;
        ms_status st = ms_reader_checkpoint_size(r, i, &bytes);
        if (st == MS_OK && !(blob = malloc(bytes)))
            st = MS_ERR_OUT_OF_MEMORY;
        if (st == MS_OK)
            st = ms_reader_read_checkpoint(r, i, blob, bytes);
        if (st == MS_OK)
            st = ms_sim_restore(sim, blob, bytes);
        free(blob);
        if (st == MS_OK) {
            if (!quiet)
                printf("modesplit: %s: restored the checkpoint of frame %ld\n", path, at[i]);
            return at[i] * (long)every + 1;
        }
        if (ms_sim_frame(sim) != 0 || ms_sim_time(sim) != 0.0) {
            tool_error("--resume: %s: the checkpoint of frame %ld: %s", path, at[i],
                       ms_last_error());
            return -1;
        }
        if (!quiet) {
            /* the sentence may quote the file's bytes */
            printf("modesplit: %s: cannot use the checkpoint of frame %ld (", path, at[i]);
            tool_put_escaped(stdout, ms_last_error(), "");
            printf(")\n");
        }
    }
    return 0;
}

int resume_run(const char *path, ms_sim *sim, float dt, int every, long frames, int quiet,
               ms_writer **w, long *done, long *written)
{
    *w = NULL;
    *done = *written = 0;
    /* a file another writer holds (a run still going) is refused before it
     * is read and replayed; ms_writer_open_append takes the lock itself */
    int fd = open(path, O_RDONLY | O_CLOEXEC);
    if (fd >= 0) {
        int held = flock(fd, LOCK_EX | LOCK_NB) != 0 && errno == EWOULDBLOCK;
        close(fd); /* the probe's lock, if it got one, ends here */
        if (held) {
            tool_error("--resume: %s is being written by another process (it holds the file's "
                       "lock); one writer per run file: wait until it ends",
                       path);
            return EXIT_RUNTIME;
        }
    }
    ms_reader *r = NULL;
    if (ms_reader_open(path, &r) != MS_OK) {
        tool_error("--resume: %s", ms_last_error());
        return EXIT_RUNTIME;
    }
    const ms_scene *sc = ms_sim_scene(sim);
    if (strcmp(ms_reader_scene(r), ms_scene_text(sc)) != 0 ||
        strcmp(ms_reader_library_version(r), ms_version()) != 0) {
        /* the writer names the difference */
        ms_reader_close(r);
        if (ms_writer_open_append(path, sim, 0, w) == MS_OK) {
            ms_writer_close(*w); /* cannot happen: it refuses the same */
            *w = NULL;
        }
        tool_error("--resume: %s", ms_last_error());
        return EXIT_USAGE;
    }
    long kept = ms_reader_frames(r);
    long steps = kept > 0 ? (kept - 1) * (long)every + 1 : 0; /* frame k is step k*every+1 */
    if (steps > frames) {
        tool_error("--resume: %s holds %ld frames, more than a run of %ld frames writes", path,
                   kept, frames);
        ms_reader_close(r);
        return EXIT_USAGE;
    }
    long from = restore_checkpoint(path, r, sim, every, quiet);
    if (from < 0) {
        ms_reader_close(r);
        return EXIT_RUNTIME;
    }
    if (!quiet && kept > 0) {
        printf("modesplit: resuming %s after its frame %ld: replaying %ld steps\n", path, kept - 1,
               steps - from);
        fflush(stdout);
    }
    for (long s = from; s < steps; ++s)
        if (ms_sim_step(sim, dt) != MS_OK) {
            tool_error("--resume: replaying step %ld: %s", s, ms_last_error());
            ms_reader_close(r);
            return EXIT_RUNTIME;
        }
    int bad = kept > 0 ? verify_frame(path, r, kept - 1, sim) : 0;
    ms_reader_close(r);
    if (bad)
        return bad == -2 ? EXIT_USAGE : EXIT_RUNTIME;
    if (ms_writer_open_append(path, sim, 0, w) != MS_OK) {
        tool_error("--resume: %s", ms_last_error());
        return EXIT_RUNTIME;
    }
    if (ms_writer_frames(*w) != kept) {
        tool_error("--resume: %s changed while it was replayed (%ld frames, then %ld)", path, kept,
                   ms_writer_frames(*w));
        ms_writer_close(*w);
        *w = NULL;
        return EXIT_RUNTIME;
    }
    *done = steps;
    *written = kept;
    return EXIT_OK;
}
