/* A snapshot blob (ms_sim_snapshot, lib/sim/snapshot.c): a run of named,
 * size-led records. Internal.
 *
 * Each record is a 24-byte head (name, up to 15 characters, NUL-padded to
 * 16; the payload's byte count as uint64) and the payload, padded to 8
 * bytes. One function moves a record either way (ms_blob_io): a part's
 * snapshot code is one list of records that both writes and reads, so
 * adding state to a part is one line in its snapshot.c (or one entry of a
 * table of arrays). A writer with a NULL buffer only counts
 * (ms_sim_snapshot_size). A reader checks each record's name and size
 * before it copies it. Numbers are stored in the machine's own
 * representation: a blob is for the build and platform that wrote it (its
 * header names the library version).
 */
#ifndef MS_CORE_BLOB_H
#define MS_CORE_BLOB_H

#include <math.h>
#include <stddef.h>
#include <stdint.h>

#include "core/core_internal.h"

#define MS_BLOB_NAME 16

typedef struct ms_blob {
    int reading;
    unsigned char *out;      /* writing: the buffer, NULL = count only */
    const unsigned char *in; /* reading */
    size_t cap;              /* writing: bytes of out */
    size_t len;              /* writing: bytes so far; reading: bytes of in */
    size_t pos;              /* reading: next record */
} ms_blob;

/* Writing: append record `name` of `bytes` bytes from p (always MS_OK).
 * Reading: the next record must be `name` of exactly `bytes` bytes (else
 * MS_ERR_INVALID_ARGUMENT naming the record, what the blob holds and what
 * this sim needs); it is copied to p. */
ms_status ms_blob_io(ms_blob *b, const char *name, void *p, size_t bytes);
/* Reading: the size of the next record, which must be `name` (writing:
 * *bytes is left alone). */
ms_status ms_blob_peek(const ms_blob *b, const char *name, size_t *bytes);
/* A count that sizes arrays: written as is; read and refused outside
 * [0, max] with a sentence naming it. */
ms_status ms_blob_count(ms_blob *b, const char *name, int *n, int max);

/* Reading a blob is reading untrusted input: its checksum finds damage,
 * not forgery, so every value that indexes, sizes or bounds work is
 * checked before use, as a desc's are. */

/* Reading: the next record must be `name` of exactly `bytes` bytes,
 * without moving on: a count read from the blob is checked against the
 * record it sizes before anything is allocated for it. */
ms_status ms_blob_expect(const ms_blob *b, const char *name, size_t bytes);
/* `count` floats either way; read, each must be finite and in [lo, hi]
 * (unit names their unit in the sentence; -INFINITY/INFINITY for "finite
 * only"). */
ms_status ms_blob_floats(ms_blob *b, const char *name, float *p, size_t count, double lo, double hi,
                         const char *unit);
/* One double either way; read, it must be finite and in [lo, hi]. */
ms_status ms_blob_double(ms_blob *b, const char *name, double *p, double lo, double hi,
                         const char *unit);
/* Checks of values already read (the same sentences): each of p[0..count)
 * finite and in [lo, hi]; an integer in [lo, hi]. */
ms_status ms_blob_check_floats(const char *name, const float *p, size_t count, double lo, double hi,
                               const char *unit);
ms_status ms_blob_check_int(const char *name, long v, long lo, long hi);

/* A 64-bit hash of bytes (8 bytes a step; FNV-1a for the tail),
 * continuing from h (start with MS_BLOB_HASH0). Not cryptographic: it
 * finds torn and damaged blobs, not forged ones. */
#define MS_BLOB_HASH0 1469598103934665603ull
uint64_t ms_blob_hash(uint64_t h, const void *data, size_t bytes);

/* One scalar or fixed array each way. */
#define MS_BLOB_IO(b, name, var) ms_blob_io((b), (name), &(var), sizeof(var))
/* A finite float scalar or fixed float array each way (any value). */
#define MS_BLOB_FINITE(b, name, var)                                                               \
    ms_blob_floats((b), (name), (float *)&(var), sizeof(var) / sizeof(float), -INFINITY, INFINITY, \
                   "")

#endif /* MS_CORE_BLOB_H */
