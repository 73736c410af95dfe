/* Output of a run: ms_writer writes HDF5 files of the fields and particles
 * (DESIGN 5), ms_reader reads them back, ms_field_write_png draws a quick
 * shaded-relief preview of a height field.
 *
 *     ms_writer *w;
 *     if (ms_writer_open("run.h5", sim, MS_FIELD_COMBINED | MS_FIELD_PARTICLES, &w))
 *         return fprintf(stderr, "%s\n", ms_last_error()), 1;
 *     for (int i = 0; i < 600; ++i) {
 *         if (ms_sim_step(sim, dt) || ms_writer_frame(w, sim)) break;
 *     }
 *     ms_writer_close(w);           // run.h5 + run.xmf (ParaView)
 *
 * The file (format "modesplit", format_version 2; version 1 files, which
 * lack /particles and the `id` arrays, are still read):
 *   /                     attributes format, format_version, library_version,
 *                         scene (the scene JSON), scene_name, frame_dt (s),
 *                         output_every, frames (complete frames in the file)
 *   /time                 float64 [frame], s
 *   /fields/combined      float32 [frame][y][x], m; also /fields/surface and
 *   /fields/volume        /fields/volume; extendible, one frame per chunk,
 *                         shuffle + deflate; attributes dx = [dx, dy] (m),
 *                         origin = [x0, y0] (m, corner of cell (0, 0))
 *   /Step#<n>/x,y,z,vx,vy,vz   particles (H5Part), float32 [count], m and
 *                         m/s; attribute TimeValue (s); id, int32 [count]
 *                         (the particle's insertion index, stable in time)
 *   /particles/<n>/position, velocity   the same particles as float32
 *                         [count][3] (what ParaView's Xdmf3 reader reads)
 *   /floaters             float32 [frame][n][3], m: the scene's floating
 *                         objects (leaves), when it has any
 *   /spray, /spray_count  float32 [frame][budget][3] (m) and int32 [frame]:
 *                         the spray droplets in flight, when the scene
 *                         throws spray (/spray_id: 0 .. budget-1, their
 *                         vertex cells in run.xmf)
 *   /foam                 float32 [frame][y][x]: the foam cover in [0, 1]
 *                         (attributes dx, origin as a field), with spray
 *   /checkpoint/0, /1     uint8 snapshots of the sim (ms_sim_snapshot),
 *                         attribute frame (see checkpoints below)
 * Only the fields asked for are present. Frame n is the n-th written frame.
 *
 * Crash safety: each frame is written and flushed before ms_writer_frame
 * returns, then the root attribute `frames` is raised and flushed again;
 * freed file space is never reused. A run killed at any point after its
 * first frame leaves a file that h5dump and ms_reader read, with every frame
 * whose ms_writer_frame returned, even when killed in the middle of a
 * flush: the writer forks one helper process at the first flush that
 * rewrites what an earlier one wrote, and the helper applies each flush's
 * in-place writes whole once it has received them all (it holds only the
 * file and its socket, ignores terminal signals, sits in its own process
 * group and ends when the writer closes or dies; the writer reaps it). If
 * the fork is refused, the writer writes each flush itself, with a narrow
 * window left. Before each frame the writer checks the space left on the file
 * system (and RLIMIT_FSIZE) and stops with MS_ERR_IO instead of writing a
 * frame that cannot fit. The writer turns off HDF5 file locking so that the
 * file can be read while the run goes on.
 *
 * The XDMF sidecars (run.xmf beside run.h5, the path with ".h5" replaced,
 * or ".xmf" appended; and run.xdmf2) are temporal collections, one entry
 * per frame, extended in place after each frame. run.xmf is for ParaView's
 * default reader (Xdmf3), run.xdmf2 for the legacy XDMF reader and VisIt
 * (each reads a hyperslab only in its own syntax). Both open height fields
 * as point data on an image grid (points at the cell centres) and
 * particles as poly-vertices with a `velocity` vector and an `id`.
 *
 * None of this prints: HDF5's own error printing is silenced during each
 * call (and restored after), its errors become one ms_last_error() sentence.
 */
#ifndef MODESPLIT_IO_H
#define MODESPLIT_IO_H

#include "core.h"
#include "sim.h"

#ifdef __cplusplus
extern "C" {
#endif

#define MS_FILE_FORMAT "modesplit"
#define MS_FILE_FORMAT_VERSION 2

/* ---- writing ----------------------------------------------------------- */

/* Create (or truncate) `path` and write its layout for `sim`. `fields` is a
 * set of MS_FIELD_* bits (core.h); 0 means what the sim's scene asks for
 * (ms_scene_output_fields), or MS_FIELD_COMBINED for a sim made from a desc.
 * Asking for a part the sim does not have (a surface field without a
 * surface, particles without a volume) is MS_ERR_INVALID_ARGUMENT. An
 * unwritable path or a full disk is MS_ERR_IO with the system's reason.
 * A path whose file or sidecars (or their temporary names) would be the
 * file the sim's scene was loaded from is MS_ERR_INVALID_ARGUMENT, before
 * anything is created (ms_writer_open_append too). One writer per run
 * file: a writer holds an exclusive flock on its file until it is closed,
 * and a second writer of that file (in any process) is MS_ERR_STATE. */
MS_API ms_status ms_writer_open(const char *path, const ms_sim *sim, unsigned fields,
                                ms_writer **out);
/* Before a new run at `path` of this sim: the refusals ms_writer_open
 * would give for its names (a name that is the scene's file, one that is
 * not a regular file), then the files it would replace: *exists 1 and the
 * first of path, its XDMF sidecar (ms_writer_xdmf_path's name) and the
 * legacy reader's sidecar that is there (a regular file or a symbolic
 * link, dangling too) in name, cut to size; *exists 0 and name "" when
 * none is. How `modesplit run` and `view` refuse to replace a run without
 * --force. The check and ms_writer_open are two steps: a file made between
 * them is replaced. */
MS_API ms_status ms_writer_existing(const char *path, const ms_sim *sim, char *name, size_t size,
                                    int *exists);
/* Append the sim's current frame (fields, particles, ms_sim_time) and flush
 * it to disk. After an MS_ERR_IO the writer is failed: later frames return
 * MS_ERR_STATE, and ms_writer_close keeps the frames written before. */
MS_API ms_status ms_writer_frame(ms_writer *w, const ms_sim *sim);
/* Close the file and the sidecar, free the writer (NULL is fine). Returns
 * the first error met while closing. */
MS_API ms_status ms_writer_close(ms_writer *w);
/* Frames written and flushed so far. */
MS_API long ms_writer_frames(const ms_writer *w);
/* The XDMF sidecar's path. */
MS_API const char *ms_writer_xdmf_path(const ms_writer *w);

/* Reopen a run file that a writer of this sim's scene wrote (killed or
 * finished) to append frames to it: how `modesplit run --resume` continues
 * a run. The file must hold format_version MS_FILE_FORMAT_VERSION, be
 * written by this library version, from the same scene text (the sentence
 * names the first line that differs) and with the same fields and grids;
 * otherwise MS_ERR_INVALID_ARGUMENT (MS_ERR_UNSUPPORTED for another format
 * version, MS_ERR_PARSE for a file that is not a run) and the file is left
 * as it was. A frame cut by a kill (data past the `frames` attribute) is
 * dropped; ms_writer_frames then gives the frames kept, the next
 * ms_writer_frame appends after them, and the sidecars are written again.
 * The caller brings the sim to the state of the last frame kept (replaying
 * it: same scene, same build -> same bytes). */
MS_API ms_status ms_writer_open_append(const char *path, const ms_sim *sim, unsigned fields,
                                       ms_writer **out);

/* ---- reading ----------------------------------------------------------- */

typedef struct ms_reader ms_reader;

/* Open a run file for reading (also while a writer is still adding frames,
 * or after it was killed; a file caught in the middle of a flush may fail
 * to open, so try again, and HDF5 1.10.8 then leaks a few hundred bytes). MS_ERR_IO when the file cannot be opened or is
 * not HDF5, MS_ERR_PARSE when it is HDF5 but not a well-formed modesplit
 * run (the sentence names the object), MS_ERR_UNSUPPORTED for a newer
 * format_version. */
MS_API ms_status ms_reader_open(const char *path, ms_reader **out);
MS_API void ms_reader_close(ms_reader *r);

/* Complete frames: the smallest of the `frames` attribute and the lengths
 * of /time and of every field dataset. */
MS_API long ms_reader_frames(const ms_reader *r);
/* MS_FIELD_* bits present in the file (MS_FIELD_PARTICLES if /Step#0 is). */
MS_API unsigned ms_reader_fields(const ms_reader *r);
MS_API int ms_reader_format_version(const ms_reader *r);
/* Strings held by the reader; "" when the file lacks them. */
MS_API const char *ms_reader_library_version(const ms_reader *r);
MS_API const char *ms_reader_scene(const ms_reader *r); /* scene JSON text */
MS_API const char *ms_reader_scene_name(const ms_reader *r);
MS_API double ms_reader_frame_dt(const ms_reader *r);  /* s, NAN if absent */
MS_API int ms_reader_output_every(const ms_reader *r); /* 1 if absent */

/* Time of a frame, s. */
MS_API ms_status ms_reader_time(const ms_reader *r, long frame, double *t);
/* Grid of one field (a single MS_FIELD_COMBINED/SURFACE/VOLUME bit). */
MS_API ms_status ms_reader_field_grid(const ms_reader *r, unsigned field, ms_grid *out);
/* Bytes the field takes in the file (compressed) and would take raw. */
MS_API ms_status ms_reader_field_bytes(const ms_reader *r, unsigned field, uint64_t *stored,
                                       uint64_t *raw);
/* Copy one frame of a field into out (capacity `count` floats, >= nx*ny). */
MS_API ms_status ms_reader_read_field(const ms_reader *r, unsigned field, long frame, float *out,
                                      size_t count);
/* Particles stored for a frame (0 when the file has none). */
MS_API ms_status ms_reader_particle_count(const ms_reader *r, long frame, int *n);
/* Copy the particles of a frame: pos[0..2] = x, y, z and vel[0..2] = vx,
 * vy, vz, each of capacity `capacity` floats (>= the count); any of the six
 * pointers (or pos, vel) may be NULL to skip it. */
MS_API ms_status ms_reader_read_particles(const ms_reader *r, long frame, int capacity,
                                          float *const pos[3], float *const vel[3]);

/* The legacy (Xdmf2 / VisIt) sidecar's path, "run.xdmf2". */
MS_API const char *ms_writer_xdmf_legacy_path(const ms_writer *w);

/* ---- checkpoints ------------------------------------------------------ */
/* ms_writer_frame stores a snapshot of the sim (ms_sim_snapshot) with
 * every n-th written frame (frames 0, n, 2n, ...; the scene's
 * output.checkpoint_every, 1 for a sim made from descs; 0 = none). The
 * file keeps the two newest, in /checkpoint/0 and /checkpoint/1 (uint8,
 * attributes `frame` and `bytes`, the blob's length: a slot only grows);
 * a new one replaces the older, so a kill while one is written leaves the
 * other. */
MS_API ms_status ms_writer_set_checkpoint_every(ms_writer *w, int every);
/* The checkpoints a reader may use: those of complete frames, newest
 * first, at most 2; frames[i] is the written frame each holds. Returns
 * how many. */
MS_API int ms_reader_checkpoints(const ms_reader *r, long frames[2]);
/* Bytes of checkpoint i (as ms_reader_checkpoints orders them), and a copy
 * of it into buf (capacity bytes); then ms_sim_restore it into a sim of the
 * file's scene. */
MS_API ms_status ms_reader_checkpoint_size(const ms_reader *r, int i, size_t *bytes);
MS_API ms_status ms_reader_read_checkpoint(const ms_reader *r, int i, void *buf, size_t capacity);

/* Floating objects (the scene's effects.floaters, fig10's leaves) per
 * frame: /floaters, float32 [frame][n][3], m (what ms_sim_floaters showed
 * when the frame was written). The count n (0 when the file has none), and
 * frame's positions x, y, z into xyz (capacity >= n triples). */
MS_API int ms_reader_floater_count(const ms_reader *r);
MS_API ms_status ms_reader_read_floaters(const ms_reader *r, long frame, float *xyz, int capacity);

/* Spray (the scene's effects.spray) per frame: /spray, float32
 * [frame][budget][3], m, the droplets in flight in the first
 * /spray_count[frame] rows (NaN past them); /foam, float32 [frame][y][x],
 * the foam cover in [0, 1] on its grid (attributes dx, origin as
 * /fields). The budget (0 when the file has no spray); frame's droplets
 * into xyz (capacity >= *n triples; the budget always is); the foam's
 * grid, and frame's cover into out (count >= nx * ny). */
MS_API int ms_reader_spray_budget(const ms_reader *r);
MS_API ms_status ms_reader_read_spray(const ms_reader *r, long frame, float *xyz, int capacity,
                                      int *n);
MS_API ms_status ms_reader_foam_grid(const ms_reader *r, ms_grid *out);
MS_API ms_status ms_reader_read_foam(const ms_reader *r, long frame, float *out, size_t count);

/* ---- shaded-relief preview (PNG) ---------------------------------------- */

typedef struct ms_preview_desc {
    uint32_t size; /* sizeof, set by ms_preview_desc_default() (core.h: struct sizes) */
    float dx, dy;  /* m, cell size: sets the slopes of the shading; > 0 */
    float height_min, height_max; /* m, the colour ramp's range; equal: the field's own */
    float relief;                 /* vertical exaggeration of the shading; 0 .. 1e6 */
    float sun_azimuth;            /* degrees clockwise from +y (north); any finite value */
    float sun_elevation;          /* degrees above the horizon; 0 .. 90 */
    int scale;                    /* pixels per cell (bilinear); 1 .. 16 */
} ms_preview_desc;

/* dx = dy = 0.01 m, range from the field, relief 1, sun from the north-west
 * (azimuth 315) at 45 degrees, scale 1. */
MS_API ms_preview_desc ms_preview_desc_default(void);

/* Shade a height field (nx*ny, row-major, x fastest) into RGB8 pixels,
 * (nx*scale) x (ny*scale), top row first, the top row being the largest y
 * (north up): a water colour ramp (deep blue troughs, turquoise, pale
 * crests) lit by a hillshade (Lambert, normals from central differences).
 * A non-finite height is drawn magenta. */
MS_API ms_status ms_field_shade(const float *h, int nx, int ny, const ms_preview_desc *d,
                                unsigned char *rgb, size_t rgb_bytes);
/* The same, written as an 8-bit RGB PNG (libpng) to path. */
MS_API ms_status ms_field_write_png(const float *h, int nx, int ny, const char *path,
                                    const ms_preview_desc *d);

#ifdef __cplusplus
}
#endif

#endif /* MODESPLIT_IO_H */
