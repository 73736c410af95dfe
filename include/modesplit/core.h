/* libmodesplit core: version, status codes, the thread-local error sentence,
 * and the opaque handle types every other header refers to.
 *
 * Every fallible call returns an ms_status: MS_OK (0) or a negative error.
 * After an error, ms_last_error() returns a sentence that names the bad value
 * and the bound it broke, e.g.
 *   "surface: wave_speed 40 m/s with dx 0.01 m needs dt <= 1.77e-4 s".
 * The sentence is thread-local: it belongs to the thread that made the call
 * and stays until that thread's next failing call.
 *
 * Which code: a value outside its domain (a negative dx, a NaN, an unknown
 * enum, a size the library does not know) is MS_ERR_INVALID_ARGUMENT;
 * MS_ERR_UNSTABLE is only for valid values that no sub-stepping can keep
 * stable (a step needing more than max_substeps sub-steps, a fixed n_time
 * below the CFL bound). Each part checks its own desc before the checks
 * across parts, so the sentence names the value that is wrong.
 *
 * The library never prints, exits or aborts on bad input.
 */
#ifndef MODESPLIT_CORE_H
#define MODESPLIT_CORE_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#if defined(__GNUC__) || defined(__clang__)
#define MS_API __attribute__((visibility("default")))
#else
#define MS_API
#endif

/* Old names kept for one release: the compiler says what replaces them.
 * Define MS_NO_DEPRECATION_WARNINGS to silence it while porting. */
#if defined(MS_NO_DEPRECATION_WARNINGS)
#define MS_DEPRECATED(msg)
#elif defined(__GNUC__) || defined(__clang__)
#define MS_DEPRECATED(msg) __attribute__((deprecated(msg)))
#elif defined(_MSC_VER)
#define MS_DEPRECATED(msg) __declspec(deprecated(msg))
#else
#define MS_DEPRECATED(msg)
#endif

#define MS_VERSION_MAJOR 0
#define MS_VERSION_MINOR 1
#define MS_VERSION_PATCH 0
#define MS_VERSION_STRING "0.1.0"

/* Opaque handles. */
typedef struct ms_surface ms_surface;   /* 2D wave equation (paper eq. 2) */
typedef struct ms_volume ms_volume;     /* 3D SPH (paper eqs. 9-18) */
typedef struct ms_shape ms_shape;       /* collision shape from a plugin */
typedef struct ms_scene ms_scene;       /* parsed scene file */
typedef struct ms_sim ms_sim;           /* the mode-splitting coupler */
typedef struct ms_renderer ms_renderer; /* OSMesa off-screen renderer */
typedef struct ms_writer ms_writer;     /* HDF5 output */

/* X-macro of the status codes: name, value, short description. */
#define MS_STATUS_MAP(X)                                                \
    X(OK, 0, "success")                                                 \
    X(ERR_INVALID_ARGUMENT, -1, "invalid argument")                     \
    X(ERR_OUT_OF_MEMORY, -2, "out of memory")                           \
    X(ERR_UNSTABLE, -3, "parameters cannot be made numerically stable") \
    X(ERR_IO, -4, "input/output error")                                 \
    X(ERR_PARSE, -5, "parse error")                                     \
    X(ERR_PLUGIN, -6, "plugin error")                                   \
    X(ERR_UNSUPPORTED, -7, "not supported by this build")               \
    X(ERR_STATE, -8, "call not allowed in the current state")           \
    X(ERR_CANCELED, -9, "stopped by a cancel request")

typedef enum ms_status {
#define MS_STATUS_ENUM_(name, value, text) MS_##name = value,
    MS_STATUS_MAP(MS_STATUS_ENUM_)
#undef MS_STATUS_ENUM_
        MS_STATUS_FORCE_32BIT_ = 0x7fffffff /* public enums are 32-bit */
} ms_status;

/* The fields of a run, as bits (scene `output.fields`, ms_writer_open). */
enum {
    MS_FIELD_COMBINED = 1u << 0, /* SPH field up-sampled + wave field (eq. 20) */
    MS_FIELD_SURFACE = 1u << 1,  /* the wave-equation field alone */
    MS_FIELD_VOLUME = 1u << 2,   /* the SPH height field alone (eq. 16) */
    MS_FIELD_PARTICLES = 1u << 3 /* SPH particle positions and velocities */
};

/* A regular grid placed in the world (a fixed value type: it never grows
 * and has no size field): cell (i, j) spans
 * [origin + (i, j) * (dx, dy), origin + (i+1, j+1) * (dx, dy)]. */
typedef struct ms_grid {
    int nx, ny;
    float dx, dy;    /* m */
    float origin[2]; /* m, corner of cell (0, 0) */
} ms_grid;

/* Struct sizes (ABI). Every public desc and every struct the library fills
 * starts with `uint32_t size`, the sizeof the caller was compiled with (as
 * Win32's cbSize): that is how the library tells an older caller's smaller
 * struct from the current one, so structs can grow at the end.
 *   - descs (ms_surface_desc, ...): start from ms_X_desc_default(), which
 *     sets size, then set the fields you need. Create refuses size 0 ("start
 *     from ms_X_desc_default()") and a size the library does not know (a
 *     caller built against a newer header, or garbage) with
 *     MS_ERR_INVALID_ARGUMENT; a smaller known size (an older caller) is
 *     accepted: the fields it lacks keep their defaults.
 *   - structs the library fills (ms_stats, ms_surface_info, ...): the
 *     caller sets size, e.g. `ms_stats st = ms_stats_init();`; the library
 *     writes only size bytes. A getter that returns void and meets size 0 or
 *     an unknown size writes nothing (and ms_last_error() says why); one
 *     that returns ms_status refuses it with MS_ERR_INVALID_ARGUMENT.
 * FFI callers set size to the struct's sizeof from the ABI listing.
 * Small value types that never grow (ms_grid, ms_render_disc) carry no size. */
/* one line each: clang-format 14 spreads a braced macro body over four */
/* clang-format off */
#ifdef __cplusplus
#define MS_ZERO_INIT {}
#else
#define MS_ZERO_INIT {0}
#endif
/* clang-format on */

/* Threads. A game engine that owns its threads can run the library's
 * parallel work itself (as Box2D v3's enqueueTask/finishTask): enqueue
 * starts task(task_context) and returns a handle (NULL = it ran the task
 * inline already); finish waits for that handle. Used by ms_sim (its
 * two-core split and its volume's loops) and ms_volume_set_tasks. */
typedef void ms_task_fn(void *task_context);
typedef void *ms_enqueue_task_fn(ms_task_fn *task, void *task_context, void *user_context);
typedef void ms_finish_task_fn(void *user_task, void *user_context);

/* Memory. Every allocation the library makes (its handles, fields,
 * particles, the host side of plugins) goes through alloc_fn / free_fn
 * when given, as Box2D's b2SetAllocator: alloc_fn(size, alignment, user)
 * returns size bytes aligned to `alignment` (a power of two, 64) or NULL;
 * free_fn(p, user) frees what alloc_fn returned. Both NULL restores the
 * default (aligned_alloc/free). Set it before creating anything: while the
 * library holds memory from the allocator in use, a change is refused
 * with MS_ERR_STATE. Process-wide, not thread-safe against other calls.
 * The libraries libmodesplit uses (HDF5, jansson, libpng, OSMesa) allocate
 * through their own allocators. ms_surface_step allocates nothing (adding
 * a disturber makes its room); ms_sim_step allocates nothing after the
 * first frame, which makes every buffer at its largest and gives the
 * neighbour lists twice the room it needed; only particles added after it,
 * or liquid squeezed past twice those neighbour counts, grow a buffer
 * again (tests/test_alloc.c). */
typedef void *ms_alloc_fn(size_t size, size_t alignment, void *user);
typedef void ms_free_fn(void *p, void *user);
MS_API ms_status ms_set_allocator(ms_alloc_fn *alloc_fn, ms_free_fn *free_fn, void *user);

/* "0.1.0" */
MS_API const char *ms_version(void);
/* "MS_ERR_UNSTABLE"; "MS_UNKNOWN_STATUS" for a value not in the map. */
MS_API const char *ms_status_name(ms_status s);
/* One-line description of a status code ("out of memory"). */
MS_API const char *ms_status_text(ms_status s);
/* The sentence of this thread's last failed call; "" if none failed yet. */
MS_API const char *ms_last_error(void);

#ifdef __cplusplus
}
#endif

#endif /* MODESPLIT_CORE_H */
