/* lib/io: keeps the end-of-allocation (EOA) address stored in the file's
 * superblock ahead of every object the file points to, so that a run
 * killed in the middle of an HDF5 flush still opens in h5dump. Used only
 * when h5_atomic.c could not start its helper process (whose flushes land
 * whole, superblock included); it narrows the window that driver closes.
 *
 * Why: HDF5 (without SWMR) writes a flush's metadata entries first and the
 * superblock, which holds the EOA, last. A kill between the two leaves
 * objects on disk that point past the stored EOA, and every reader then
 * refuses them ("address of object past end of allocation"). SWMR writing
 * orders flushes safely but marks the file "open for write" until closed,
 * so after a kill h5dump refuses the whole file until `h5clear -s`.
 *
 * What: just before each flush, ms_h5_guard_eoa extends the file to the
 * in-memory EOA (H5Fget_eoa; a sparse extension) and writes that EOA into
 * the on-disk superblock itself (format version 2, the version this
 * library's files have: 48 bytes, base address at offset 12, EOA at 28, Jenkins lookup3
 * checksum of the first 44 bytes at offset 44), with one pwrite. The flush
 * that follows writes the same value again. Anything else (another
 * superblock version, other address sizes) is left alone.
 */
#include <errno.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "io/io_internal.h"

#define SB_SIZE 48
#define SB_EOA_AT 28
#define SB_SUM_AT 44

static const unsigned char signature[8] = {0x89, 'H', 'D', 'F', '\r', '\n', 0x1a, '\n'};

#define ROT(x, k) (((x) << (k)) | ((x) >> (32 - (k))))

/* Bob Jenkins' lookup3 hashlittle(), byte by byte (public domain); HDF5's
 * metadata checksum with initval 0. */
uint32_t ms_lookup3(const void *key, size_t length, uint32_t initval)
{
    const uint8_t *k = key;
    uint32_t a, b, c;
    a = b = c = 0xdeadbeefu + (uint32_t)length + initval;
    while (length > 12) {
        a += k[0] + ((uint32_t)k[1] << 8) + ((uint32_t)k[2] << 16) + ((uint32_t)k[3] << 24);
        b += k[4] + ((uint32_t)k[5] << 8) + ((uint32_t)k[6] << 16) + ((uint32_t)k[7] << 24);
        c += k[8] + ((uint32_t)k[9] << 8) + ((uint32_t)k[10] << 16) + ((uint32_t)k[11] << 24);
        a -= c;
        a ^= ROT(c, 4);
        c += b;
        b -= a;
        b ^= ROT(a, 6);
        a += c;
        c -= b;
        c ^= ROT(b, 8);
        b += a;
        a -= c;
        a ^= ROT(c, 16);
        c += b;
        b -= a;
        b ^= ROT(a, 19);
        a += c;
        c -= b;
        c ^= ROT(b, 4);
        b += a;
        length -= 12;
        k += 12;
    }
    switch (length) { /* every case falls through */
    case 12:
        c += (uint32_t)k[11] << 24; /* fall through */
    case 11:
        c += (uint32_t)k[10] << 16; /* fall through */
    case 10:
        c += (uint32_t)k[9] << 8; /* fall through */
    case 9:
        c += k[8]; /* fall through */
    case 8:
        b += (uint32_t)k[7] << 24; /* fall through */
    case 7:
        b += (uint32_t)k[6] << 16; /* fall through */
    case 6:
        b += (uint32_t)k[5] << 8; /* fall through */
    case 5:
        b += k[4]; /* fall through */
    case 4:
        a += (uint32_t)k[3] << 24; /* fall through */
    case 3:
        a += (uint32_t)k[2] << 16; /* fall through */
    case 2:
        a += (uint32_t)k[1] << 8; /* fall through */
    case 1:
        a += k[0];
        break;
    case 0:
        return c;
    }
    c ^= b;
    c -= ROT(b, 14);
    a ^= c;
    a -= ROT(c, 11);
    b ^= a;
    b -= ROT(a, 25);
    c ^= b;
    c -= ROT(b, 16);
    a ^= c;
    a -= ROT(c, 4);
    b ^= a;
    b -= ROT(a, 14);
    c ^= b;
    c -= ROT(b, 24);
    return c;
}

static uint64_t get_le64(const unsigned char *p)
{
    uint64_t v = 0;
    for (int i = 7; i >= 0; --i)
        v = (v << 8) | p[i];
    return v;
}

static void put_le64(unsigned char *p, uint64_t v)
{
    for (int i = 0; i < 8; ++i, v >>= 8)
        p[i] = (unsigned char)(v & 0xff);
}

static void put_le32(unsigned char *p, uint32_t v)
{
    for (int i = 0; i < 4; ++i, v >>= 8)
        p[i] = (unsigned char)(v & 0xff);
}

int ms_h5_superblock_ok(const unsigned char *sb)
{
    if (memcmp(sb, signature, 8) != 0 || sb[8] != 2 || sb[9] != 8 || sb[10] != 8)
        return 0;
    uint32_t sum = (uint32_t)sb[SB_SUM_AT] | (uint32_t)sb[SB_SUM_AT + 1] << 8 |
                   (uint32_t)sb[SB_SUM_AT + 2] << 16 | (uint32_t)sb[SB_SUM_AT + 3] << 24;
    return sum == ms_lookup3(sb, SB_SUM_AT, 0);
}

ms_status ms_h5_guard_eoa(hid_t file)
{
    int *fdp = NULL;
    haddr_t eoa;
    if (H5Fget_vfd_handle(file, H5P_DEFAULT, (void **)&fdp) < 0 || !fdp ||
        H5Fget_eoa(file, &eoa) < 0) {
        H5Eclear2(H5E_DEFAULT);
        return MS_OK; /* not the sec2 driver: nothing to guard */
    }
    int fd = *fdp;
    unsigned char sb[SB_SIZE];
    if (pread(fd, sb, SB_SIZE, 0) != SB_SIZE || !ms_h5_superblock_ok(sb) ||
        get_le64(sb + 12) != 0 /* base address */)
        return MS_OK;
    if (get_le64(sb + SB_EOA_AT) >= (uint64_t)eoa)
        return MS_OK;
    /* The file must reach the EOA (HDF5 refuses an EOF short of it). */
    struct stat st;
    if (fstat(fd, &st) != 0)
        return ms_fail(MS_ERR_IO, "io: cannot stat the run file: %s", strerror(errno));
    if ((uint64_t)st.st_size < (uint64_t)eoa && ftruncate(fd, (off_t)eoa) != 0)
        return ms_fail(MS_ERR_IO, "io: cannot extend the run file to %llu bytes: %s",
                       (unsigned long long)eoa, strerror(errno));
    put_le64(sb + SB_EOA_AT, (uint64_t)eoa);
    put_le32(sb + SB_SUM_AT, ms_lookup3(sb, SB_SUM_AT, 0));
    if (pwrite(fd, sb, SB_SIZE, 0) != SB_SIZE)
        return ms_fail(MS_ERR_IO, "io: cannot write the run file's superblock: %s",
                       strerror(errno));
    return MS_OK;
}
