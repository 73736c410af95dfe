/* Internal interface of lib/io (never installed).
 *
 * The writer is built in two layers: writer.c writes raw arrays described
 * by an ms_writer_layout (no sim needed: the tests and ms_writer_open both
 * use it), writer_sim.c fills the layout and the frame data from an ms_sim.
 * h5util.c holds the HDF5 glue every file here shares: silencing HDF5's
 * error printing and turning its error stack into one sentence.
 */
#ifndef MS_IO_INTERNAL_H
#define MS_IO_INTERNAL_H

#include <hdf5.h>
#include <stdint.h>

#include "core/core_internal.h"
#include "modesplit/io.h"

/* The three height fields, in MS_FIELD_* bit order (bit = 1 << slot). */
enum { MS_IO_COMBINED = 0, MS_IO_SURFACE = 1, MS_IO_VOLUME = 2, MS_IO_NFIELDS = 3 };
#define MS_IO_HEIGHT_FIELDS (MS_FIELD_COMBINED | MS_FIELD_SURFACE | MS_FIELD_VOLUME)
#define MS_IO_ALL_FIELDS (MS_IO_HEIGHT_FIELDS | MS_FIELD_PARTICLES)
/* "combined", "surface", "volume". */
extern const char *const ms_io_field_names[MS_IO_NFIELDS];
/* Slot of a single height-field bit, -1 for anything else. */
int ms_io_field_slot(unsigned field);

/* Largest grid side and cell count a file may hold (also what the reader
 * accepts): 65536 cells a side, 2^28 cells (1 GiB of float32 per frame). */
#define MS_IO_MAX_SIDE 65536
#define MS_IO_MAX_CELLS (1L << 28)
/* Most particles in one step. */
#define MS_IO_MAX_PARTICLES (1L << 28)

/* ---- the raw writer ---- */
typedef struct ms_writer_layout {
    unsigned fields;             /* MS_FIELD_* bits to write */
    ms_grid grid[MS_IO_NFIELDS]; /* where each height field lies */
    const char *scene_text;      /* may be NULL */
    const char *scene_name;      /* may be NULL */
    const char *scene_path;      /* the file the scene came from, never written;
                                     NULL or "" when there is none */
    double frame_dt;             /* s, of the simulation */
    int output_every;            /* frames of the sim per written frame, >= 1 */
    int deflate;                 /* height fields: deflate level 1..9 after shuffle;
                                     0 = stored without filters (fastest, largest) */
    int checkpoint_every;        /* written frames per sim snapshot, 0 = none */
    int floaters;                /* floating objects per frame (/floaters), 0 = none */
    int spray;                   /* the spray budget (/spray rows a frame), 0 = no spray */
    ms_grid foam;                /* with spray: where /foam lies */
} ms_writer_layout;

typedef struct ms_writer_data {
    double time;                       /* s */
    const float *field[MS_IO_NFIELDS]; /* nx*ny each, for the fields written */
    int particles;                     /* count, >= 0 */
    const float *pos[3], *vel[3];      /* particles views, may be NULL if count is 0 */
    const void *checkpoint;            /* an ms_sim_snapshot blob of this frame, or NULL */
    size_t checkpoint_bytes;
    const float *floaters;  /* 3 * layout.floaters: x, y, z (m) */
    int spray;              /* droplets in flight, [0, layout.spray] */
    const float *spray_xyz; /* 3 * spray: x, y, z (m) */
    const float *foam;      /* layout.foam's cells, cover in [0, 1] */
} ms_writer_data;

ms_status ms_writer_open_layout(const char *path, const ms_writer_layout *l, ms_writer **out);
/* ms_writer_existing for a layout. */
ms_status ms_writer_existing_layout(const char *path, const ms_writer_layout *l, char *name,
                                    size_t size, int *exists);
/* Reopen a run file written with layout l to append to it: refuses another
 * format version, library version, scene text or set of fields (nothing in
 * the file is changed then), drops a frame cut by a kill and lists the
 * complete frames in fresh sidecars (ms_writer_open_append). */
ms_status ms_writer_open_append_layout(const char *path, const ms_writer_layout *l,
                                       ms_writer **out);
ms_status ms_writer_write(ms_writer *w, const ms_writer_data *d);
/* Tests only: turn off the free-space check, so that the write itself
 * meets the full disk. */
void ms_writer_skip_space_check(ms_writer *w);
/* The layout the writer was opened with (its grids and fields). */
const ms_writer_layout *ms_writer_get_layout(const ms_writer *w);
/* The writer's scratch for a checkpoint blob of `bytes` (kept between
 * frames), NULL when out of memory. */
void *ms_writer_checkpoint_buffer(ms_writer *w, size_t bytes);
/* Checkpoints: /checkpoint/0 and /checkpoint/1, uint8 blobs of
 * ms_sim_snapshot, each with an int64 attribute `frame` (the written frame
 * whose sim state it holds); a new one overwrites the older, so a kill
 * while one is written leaves the other. */
#define MS_IO_CHECKPOINTS 2

/* ---- scene texts compared key by key (scene_diff.c) ---- */
/* Name up to three dotted key paths whose values differ between the two
 * scene JSON texts, with both values, into buf; returns how many differ
 * (0: the same scene, numbers compared by value), -1 if either does not parse. */
int ms_io_scene_diff(const char *file_text, const char *this_text, char *buf, size_t size);

/* ---- XDMF sidecar (xdmf.c) ---- */
typedef struct ms_xdmf ms_xdmf;
/* Create the sidecar at xmf_path that refers to h5_name (a path relative
 * to the sidecar's directory); legacy = 1 writes the Xdmf2 flavour. */
ms_status ms_xdmf_open(const char *xmf_path, const char *h5_name, const ms_writer_layout *l,
                       int legacy, ms_xdmf **out);
/* The next frame's spray droplets (/spray rows, run.xmf only), 0 without. */
void ms_xdmf_set_spray(ms_xdmf *x, int n);
/* Append frame `frame` (time t, `particles` particles in /Step#frame). */
ms_status ms_xdmf_frame(ms_xdmf *x, long frame, double t, int particles);
/* run.xmf's next state with the frame, made before the HDF5 frame is written
 * (a refusal here leaves every file as it was); ms_xdmf_frame then renames
 * it in (or prepares it itself when nothing is pending). No-op for the
 * legacy sidecar. ms_xdmf_drop_pending forgets a prepared state. */
ms_status ms_xdmf_prepare(ms_xdmf *x, long frame, double t, int particles);
void ms_xdmf_drop_pending(ms_xdmf *x);
/* Bytes ms_xdmf_prepare may need on the file system (a copy of run.xmf). */
uint64_t ms_xdmf_copy_bytes(const ms_xdmf *x);
ms_status ms_xdmf_close(ms_xdmf *x);
/* "run.xmf" for "run.h5", "out.dat.xmf" for "out.dat"; ms_malloc'ed (ms_free it). */
char *ms_xdmf_path_for(const char *h5_path);
/* "run.xdmf2" for "run.h5" (the legacy reader's sidecar); malloc'ed. */
char *ms_xdmf_legacy_path_for(const char *h5_path);

/* ---- H5Part particles (h5part.c) ---- */
/* Create the group of one step, not yet linked into the file (anonymous),
 * with TimeValue, the six arrays and `id`; *group out (H5Gclose it). */
ms_status ms_h5part_write_step(hid_t file, double t, int n, const float *const pos[3],
                               const float *const vel[3], hid_t *group);
/* Link a written step as /Step#frame. */
ms_status ms_h5part_link_step(hid_t file, hid_t group, long frame);
/* The same particles as [n][3] arrays `position` and `velocity` (what
 * Xdmf3 reads), in an anonymous group linked as /particles/<frame>. */
ms_status ms_h5part_write_xyz(hid_t file, int n, const float *const pos[3],
                              const float *const vel[3], hid_t *group);
ms_status ms_h5part_link_xyz(hid_t file, hid_t group, long frame);
/* "Step#12" into buf. */
void ms_h5part_step_name(char *buf, size_t size, long frame);

/* ---- the superblock's EOA kept ahead of every flush (eoa_guard.c) ---- */
/* Call right before H5Fflush: see eoa_guard.c. */
ms_status ms_h5_guard_eoa(hid_t file);

/* ---- crash-safe writing (h5_atomic.c) ---- */
/* ms_h5_fapl with the driver whose flushes land all or nothing, even when
 * the process is killed in one (a helper process applies each flush). */
hid_t ms_h5_fapl_atomic(void);
/* 1 when `file` is written by that driver with its helper (or still
 * without one), 0 for another driver or when no helper could start. */
int ms_h5_atomic_active(hid_t file);
/* Drop what the file has not committed: nothing more reaches it (the
 * writer gives up a file after a write error). */
void ms_h5_atomic_abandon(hid_t file);
/* Tests: the process kills itself (SIGKILL) in a flush's in-place writes
 * (the flush after `batch` others that had some), `at` bytes into them
 * (or, when negative, -at bytes short of their end), while they go to the
 * helper or, with without_helper, to the file (no helper is started
 * then); at 0 turns it off. Just before that flush the file's committed
 * bytes are copied to <file>.before. */
void ms_h5_atomic_test_die(int batch, long at, int without_helper);
/* The file was renamed to `name` (the writer's "<path>.part"), which the
 * tests' snapshot is named after. */
void ms_h5_atomic_renamed(hid_t file, const char *name);
/* Tests: the process kills itself (SIGKILL) once `bytes` more bytes have
 * gone straight to a file (outside any flush's journal: a new file's
 * first flush, a frame's raw data); the write that crosses the count
 * lands only up to it. 0 turns it off. */
void ms_h5_atomic_test_die_writing(size_t bytes);
/* Jenkins lookup3 (HDF5's metadata checksum). */
uint32_t ms_lookup3(const void *key, size_t length, uint32_t initval);
/* A 48-byte version-2 superblock with 8-byte addresses and a good checksum. */
int ms_h5_superblock_ok(const unsigned char *sb);

/* ---- HDF5 glue (h5util.c) ---- */
/* Silence HDF5's automatic error printing for the current thread until
 * ms_h5_loud restores what was there. */
typedef struct ms_h5_quiet {
    H5E_auto2_t func;
    void *data;
} ms_h5_quiet;
void ms_h5_hush(ms_h5_quiet *q);
void ms_h5_loud(const ms_h5_quiet *q);
/* Fail with "<sentence>: <reason>" where the reason is the system error
 * HDF5 met (errno text, e.g. "No space left on device") or the innermost
 * HDF5 message; clears the HDF5 error stack. */
ms_status ms_h5_fail(ms_status s, const char *fmt, ...) MS_PRINTF(2, 3);
/* A file access property list: latest-1.8 format (readable by HDF5 1.8 and
 * later), file locking off, sec2 driver. H5Pclose it. */
hid_t ms_h5_fapl(void);
/* Attribute helpers on any object; each returns < 0 on failure. */
herr_t ms_h5_attr_string(hid_t obj, const char *name, const char *value);
herr_t ms_h5_attr_double(hid_t obj, const char *name, const double *v, int n);
herr_t ms_h5_attr_int64(hid_t obj, const char *name, int64_t v);
/* Readers of the same, defensive about what the file holds: the attribute
 * must exist with the right class and element count, or they return < 0.
 * ms_h5_read_string ms_mallocs *out (ms_free it) (NUL-terminated, at most max_len bytes). */
herr_t ms_h5_read_string(hid_t obj, const char *name, size_t max_len, char **out);
herr_t ms_h5_read_doubles(hid_t obj, const char *name, double *v, int n);
herr_t ms_h5_read_int64(hid_t obj, const char *name, int64_t *v);
/* A run file is one file: every link in it is a hard link. An external
 * link names another file (a FIFO there hangs the open, a device never
 * ends; a writer would extend and write that file) and a soft link can
 * point anywhere in this one, so both are refused before any object is
 * opened, by the reader and by the writer that appends. A group the file
 * does not hold yet (past the end of allocation while a run writes it) is
 * passed over, so `info` reads a live run. `path` names the file in the
 * sentence. */
ms_status ms_h5_check_links(hid_t file, const char *path);
/* 1 when dataset d keeps its values in this file: external raw storage and
 * virtual datasets name other files (a FIFO or a device would hang a read,
 * and an append would write there). */
int ms_h5_dataset_own(hid_t d);

#endif /* MS_IO_INTERNAL_H */
