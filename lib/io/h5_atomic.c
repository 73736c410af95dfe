/* lib/io: an HDF5 file driver whose flushes reach the file all or nothing,
 * even when the writing process is killed (SIGKILL) in the middle of one.
 *
 * Why: HDF5 (without SWMR) updates its metadata in place, and one flush
 * rewrites several blocks that point into each other: adding a link to a
 * group with dense storage rewrites a fractal-heap block and a B-tree leaf
 * and its header, each with its own checksum. A kill between two of those
 * pwrites leaves a file that h5dump, h5py and ParaView refuse (measured:
 * 2 of ~150 kills of a running `modesplit run` under load, "bad version
 * number for message" in the root group's links, and an h5dump crash).
 * No order of the writes is safe (a v2 B-tree leaf and its parent each
 * hold the other's record count), and no system call writes several
 * places of a file at once; even one write of several pages stops at a
 * page boundary when SIGKILL arrives.
 *
 * What: writes below `durable_end` (the space the file's last committed
 * state may point to) are kept in a journal in memory; writes above it
 * (space allocated since, which nothing committed points to: a frame's
 * raw data, new B-tree nodes) go to the file at once. At each flush the
 * journal goes, whole, to a helper process forked on the first flush,
 * which applies it with pwrite only once it has received all of it and
 * then answers. A kill of the writer while the journal is being sent
 * leaves the helper with half a journal, which it drops; a kill after it
 * was sent leaves the helper to finish it. Either way the file holds one
 * flush's state or the next's. The helper holds nothing else (it closes
 * every other descriptor, ignores the terminal's signals, sits in its own
 * process group) and ends when the writer closes the file or dies.
 * Reads see the journal laid over the file. Shrinking the file waits
 * until the superblock that names the smaller end has been applied.
 *
 * When no helper can be started (fork refused), the driver writes the
 * journal itself at each flush (what the sec2 driver does, with the same
 * window). The files are plain HDF5: no driver information is stored, and
 * every reader opens them with its default driver.
 */
#define _GNU_SOURCE /* close_range, mremap */
#include <errno.h>
#include <fcntl.h>
#include <pthread.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "io/io_internal.h"

#define ATOMIC_MAXADDR (((haddr_t)1 << (8 * sizeof(off_t) - 1)) - 1)
#define BATCH_MAGIC 0x6d73626174636831ull /* "msbatch1" */
#define BATCH_END 0x6d73626174636865ull   /* "msbatche" */

enum { HELPER_NONE = 0, HELPER_RUNNING = 1, HELPER_UNAVAILABLE = -1 };

typedef struct atomic_file {
    H5FD_t pub; /* first: HDF5 casts */
    int fd;
    dev_t dev;
    ino_t ino;
    haddr_t eoa;
    haddr_t eof;            /* as if the journal were applied */
    haddr_t durable_end;    /* below: in place, journaled */
    haddr_t shrink_to;      /* a truncate that waits for the next batch, 0 = none */
    unsigned char *journal; /* entries: u64 addr, u64 size, bytes */
    size_t journal_len, journal_cap;
    int helper; /* HELPER_* */
    pid_t pid;
    int sock;        /* our end of the socket pair */
    int abandoned;   /* ms_h5_atomic_abandon: drop the journal */
    char name[4096]; /* as opened, for the tests' snapshot */
} atomic_file;

static hid_t driver_id = -1;
/* tests: die (SIGKILL) after this many bytes of the next batch are sent
 * or, without a helper, written; 0 = never. No helper when set. */
static size_t test_die_after;
static long test_die_at;   /* as given: > 0 bytes in, < 0 bytes short of the end */
static int test_die_batch; /* batches with in-place writes to let pass first */
static int test_no_helper;
/* tests: die after this many more bytes written straight to a file (not
 * journaled), 0 = never */
static size_t test_die_direct;
static pthread_once_t driver_once = PTHREAD_ONCE_INIT;

/* ---- plain I/O, retried on EINTR and short counts ---- */

static int write_at(int fd, const void *buf, size_t n, haddr_t at)
{
    const unsigned char *p = buf;
    while (n > 0) {
        ssize_t k = pwrite(fd, p, n, (off_t)at);
        if (k < 0 && errno == EINTR)
            continue;
        if (k <= 0)
            return -1;
        p += k;
        n -= (size_t)k;
        at += (haddr_t)k;
    }
    return 0;
}

static int send_all(int s, const void *buf, size_t n)
{
    const unsigned char *p = buf;
    while (n > 0) {
        ssize_t k = send(s, p, n, MSG_NOSIGNAL);
        if (k < 0 && errno == EINTR)
            continue;
        if (k <= 0)
            return -1;
        p += k;
        n -= (size_t)k;
    }
    return 0;
}

/* 1 read all, 0 end of stream or error first */
static int recv_all(int s, void *buf, size_t n)
{
    unsigned char *p = buf;
    while (n > 0) {
        ssize_t k = recv(s, p, n, 0);
        if (k < 0 && errno == EINTR)
            continue;
        if (k <= 0)
            return 0;
        p += k;
        n -= (size_t)k;
    }
    return 1;
}

/* A journal entry's head at p: its file address and its byte count (the
 * bytes follow the 16-byte head). */
static void entry_head(const unsigned char *p, uint64_t *addr, uint64_t *n)
{
    memcpy(addr, p, 8);
    memcpy(n, p + 8, 8);
}

/* ---- the helper process: only system calls (it is a fork of a process
 * that may run other threads, so no malloc, no stdio, no locks) ---- */

static void helper_main(int sock, int fd)
{
    static const int ignored[] = {SIGINT,  SIGTERM, SIGHUP,  SIGQUIT, SIGPIPE, SIGTSTP,
                                  SIGTTIN, SIGTTOU, SIGUSR1, SIGUSR2, SIGALRM};
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = SIG_IGN;
    for (size_t i = 0; i < sizeof ignored / sizeof ignored[0]; ++i)
        sigaction(ignored[i], &sa, NULL);
    sigset_t none;
    sigemptyset(&none);
    pthread_sigmask(SIG_SETMASK, &none, NULL);
    setpgid(0, 0);
    /* keep only the socket and the file: a pipe or socket of the program
     * held open here would keep its reader waiting for our end */
    unsigned lo = (unsigned)(sock < fd ? sock : fd), hi = (unsigned)(sock < fd ? fd : sock);
    int closed = (lo == 0 || close_range(0, lo - 1, 0) == 0) &&
                 (hi == lo + 1 || close_range(lo + 1, hi - 1, 0) == 0) &&
                 close_range(hi + 1, ~0u, 0) == 0;
    if (!closed) { /* no close_range (Linux < 5.9): the descriptors a program opens */
        struct rlimit rl;
        int top =
            getrlimit(RLIMIT_NOFILE, &rl) == 0 && rl.rlim_cur < 65536 ? (int)rl.rlim_cur : 65536;
        for (int i = 0; i < top; ++i)
            if (i != sock && i != fd)
                close(i);
    }

    unsigned char *buf = NULL;
    size_t cap = 0;
    for (;;) {
        uint64_t head[3]; /* magic, entries, bytes */
        if (!recv_all(sock, head, sizeof head) || head[0] != BATCH_MAGIC)
            _exit(0);
        size_t bytes = (size_t)head[2];
        if (bytes > cap) {
            size_t want = bytes + bytes / 2 + 4096;
            void *p =
                buf ? mremap(buf, cap, want, MREMAP_MAYMOVE)
                    : mmap(NULL, want, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
            if (p == MAP_FAILED)
                _exit(1); /* the writer sees the socket close and writes itself */
            buf = p;
            cap = want;
        }
        uint64_t tail;
        /* a writer killed while sending leaves a batch without its end:
         * nothing of it is applied */
        if (!recv_all(sock, buf, bytes) || !recv_all(sock, &tail, sizeof tail) || tail != BATCH_END)
            _exit(0);
        int32_t answer = 0;
        size_t at = 0;
        for (uint64_t e = 0; e < head[1] && answer == 0; ++e) {
            uint64_t addr, n;
            entry_head(buf + at, &addr, &n);
            if (write_at(fd, buf + at + 16, (size_t)n, (haddr_t)addr) != 0)
                answer = errno ? errno : EIO;
            at += 16 + (size_t)n;
        }
        if (send_all(sock, &answer, sizeof answer) != 0)
            _exit(0); /* the writer is gone; the batch is in the file */
    }
}

static void start_helper(atomic_file *f)
{
    int sv[2];
    f->helper = HELPER_UNAVAILABLE;
    if (socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, sv) != 0)
        return;
    pid_t pid = fork();
    if (pid == 0) {
        close(sv[0]);
        helper_main(sv[1], f->fd);
        _exit(0);
    }
    close(sv[1]);
    if (pid < 0) {
        close(sv[0]);
        return;
    }
    f->pid = pid;
    f->sock = sv[0];
    f->helper = HELPER_RUNNING;
}

static void stop_helper(atomic_file *f)
{
    if (f->helper != HELPER_RUNNING)
        return;
    close(f->sock);
    f->sock = -1;
    while (waitpid(f->pid, NULL, 0) < 0 && errno == EINTR)
        ;
    f->helper = HELPER_NONE;
}

/* ---- the journal ---- */

static int journal_add(atomic_file *f, haddr_t addr, size_t n, const void *buf)
{
    size_t need = f->journal_len + 16 + n;
    if (need > f->journal_cap) {
        size_t cap = need + need / 2 + 4096;
        unsigned char *p = ms_malloc(cap);
        if (!p)
            return -1;
        if (f->journal_len)
            memcpy(p, f->journal, f->journal_len);
        ms_free(f->journal);
        f->journal = p;
        f->journal_cap = cap;
    }
    uint64_t a = addr, s = n;
    memcpy(f->journal + f->journal_len, &a, 8);
    memcpy(f->journal + f->journal_len + 8, &s, 8);
    memcpy(f->journal + f->journal_len + 16, buf, n);
    f->journal_len = need;
    return 0;
}

static size_t journal_entries(const atomic_file *f)
{
    size_t count = 0;
    for (size_t at = 0; at < f->journal_len; ++count) {
        uint64_t addr, n;
        entry_head(f->journal + at, &addr, &n);
        at += 16 + (size_t)n;
    }
    return count;
}

/* The journal applied by this process (no helper). */
static int apply_here(atomic_file *f)
{
    size_t written = 0;
    for (size_t at = 0; at < f->journal_len;) {
        uint64_t addr, n;
        entry_head(f->journal + at, &addr, &n);
        size_t part = (size_t)n;
        written += 16; /* counted as in the journal: entry head, then bytes */
        if (test_die_after > 0 && written + part >= test_die_after)
            part = test_die_after > written ? test_die_after - written : 0;
        if (write_at(f->fd, f->journal + at + 16, part, (haddr_t)addr) != 0)
            return -1;
        written += part;
        if (test_die_after > 0 && written >= test_die_after)
            raise(SIGKILL);
        at += 16 + (size_t)n;
    }
    return 0;
}

/* send_all, or die part way when a test asks. */
static int send_batch_part(atomic_file *f, const void *buf, size_t n, size_t *sent)
{
    if (test_die_after > 0 && *sent + n >= test_die_after) {
        send_all(f->sock, buf, test_die_after - *sent);
        raise(SIGKILL);
    }
    *sent += n;
    return send_all(f->sock, buf, n);
}

/* The journal applied by the helper, all or nothing. */
static int apply_by_helper(atomic_file *f)
{
    uint64_t head[3] = {BATCH_MAGIC, journal_entries(f), f->journal_len};
    uint64_t tail = BATCH_END;
    int32_t answer = -1;
    size_t sent = 0;
    if (send_batch_part(f, head, sizeof head, &sent) == 0 &&
        send_batch_part(f, f->journal, f->journal_len, &sent) == 0 &&
        send_batch_part(f, &tail, sizeof tail, &sent) == 0 &&
        recv_all(f->sock, &answer, sizeof answer)) {
        if (answer == 0)
            return 0;
        errno = answer;
        return -1;
    }
    /* The helper is gone (killed, out of memory) before it answered; if it
     * applied the batch, applying it again writes the same bytes. */
    stop_helper(f);
    f->helper = HELPER_UNAVAILABLE;
    return apply_here(f);
}

/* Tests: the committed part of the file, [0, durable_end), copied to
 * <file>.before just before the batch the test kills. */
static void snapshot_for_test(const atomic_file *f)
{
    char path[4200];
    snprintf(path, sizeof path, "%s.before", f->name);
    int out = open(path, O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
    unsigned char buf[4096];
    for (haddr_t at = 0; out >= 0 && at < f->durable_end;) {
        size_t n = f->durable_end - at < sizeof buf ? (size_t)(f->durable_end - at) : sizeof buf;
        ssize_t k = pread(f->fd, buf, n, (off_t)at);
        if (k <= 0 || write_at(out, buf, (size_t)k, at) != 0)
            break;
        at += (haddr_t)k;
    }
    if (out >= 0)
        close(out);
}

/* Commit the journal; then the space below the end of the file may be
 * pointed to by the file's state. */
static int commit_journal(atomic_file *f)
{
    if (f->abandoned) {
        f->journal_len = 0;
        return 0;
    }
    struct stat sb;
    /* the superblock in the journal may name an end beyond the file */
    if (fstat(f->fd, &sb) != 0)
        return -1;
    haddr_t need = f->eoa > f->eof ? f->eoa : f->eof;
    if ((haddr_t)sb.st_size < need && ftruncate(f->fd, (off_t)need) != 0)
        return -1;
    if (f->journal_len > 0) {
        if (test_die_at != 0 && test_die_batch == 0) {
            /* this batch: bytes of the message to the helper (24 bytes of
             * head, the journal, 8 of tail) or of the journal written here */
            size_t whole = f->journal_len + (test_no_helper ? 0 : 32);
            long at = test_die_at > 0 ? test_die_at : (long)whole + test_die_at;
            test_die_after = at > 16 ? (size_t)at : 17;
            test_die_at = 0; /* once */
        } else
            test_die_after = 0;
        if (test_die_batch > 0)
            --test_die_batch;
        if (f->helper == HELPER_NONE && !test_no_helper)
            start_helper(f);
        if (test_die_after > 0)
            snapshot_for_test(f);
        int rc = f->helper == HELPER_RUNNING ? apply_by_helper(f) : apply_here(f);
        if (rc != 0)
            return -1;
        f->journal_len = 0;
    }
    if (f->shrink_to > 0) {
        if (ftruncate(f->fd, (off_t)f->shrink_to) != 0)
            return -1;
        f->shrink_to = 0;
    }
    f->durable_end = need > f->durable_end ? need : f->durable_end;
    return 0;
}

/* ---- the driver's callbacks ---- */

static H5FD_t *atomic_open(const char *name, unsigned flags, hid_t fapl, haddr_t maxaddr)
{
    (void)fapl;
    if (!name || !*name || maxaddr == 0 || maxaddr > ATOMIC_MAXADDR)
        return NULL;
    int o = (flags & H5F_ACC_RDWR) ? O_RDWR : O_RDONLY;
    if (flags & H5F_ACC_TRUNC)
        o |= O_TRUNC;
    if (flags & H5F_ACC_CREAT)
        o |= O_CREAT;
    if (flags & H5F_ACC_EXCL)
        o |= O_EXCL;
    int fd = open(name, o | O_CLOEXEC, 0666);
    if (fd < 0)
        return NULL;
    struct stat sb;
    atomic_file *f = NULL;
    if (fstat(fd, &sb) != 0 || !(f = ms_alloc(sizeof *f))) {
        close(fd);
        return NULL;
    }
    f->fd = fd;
    snprintf(f->name, sizeof f->name, "%s", name);
    f->dev = sb.st_dev;
    f->ino = sb.st_ino;
    f->eof = (haddr_t)sb.st_size;
    f->durable_end = f->eof; /* an existing file's state points anywhere in it */
    f->sock = -1;
    return &f->pub;
}

static herr_t atomic_close(H5FD_t *file)
{
    atomic_file *f = (atomic_file *)file;
    int rc = commit_journal(f);
    stop_helper(f);
    if (close(f->fd) != 0)
        rc = -1;
    ms_free(f->journal);
    ms_free(f);
    return rc == 0 ? 0 : -1;
}

static int atomic_cmp(const H5FD_t *a, const H5FD_t *b)
{
    const atomic_file *x = (const atomic_file *)a, *y = (const atomic_file *)b;
    if (x->dev != y->dev)
        return x->dev < y->dev ? -1 : 1;
    if (x->ino != y->ino)
        return x->ino < y->ino ? -1 : 1;
    return 0;
}

static herr_t atomic_query(const H5FD_t *file, unsigned long *flags)
{
    (void)file;
    if (flags)
        *flags = H5FD_FEAT_AGGREGATE_METADATA | H5FD_FEAT_ACCUMULATE_METADATA |
                 H5FD_FEAT_DATA_SIEVE | H5FD_FEAT_AGGREGATE_SMALLDATA |
                 H5FD_FEAT_POSIX_COMPAT_HANDLE | H5FD_FEAT_DEFAULT_VFD_COMPATIBLE;
    return 0;
}

static haddr_t atomic_get_eoa(const H5FD_t *file, H5FD_mem_t type)
{
    (void)type;
    return ((const atomic_file *)file)->eoa;
}

static herr_t atomic_set_eoa(H5FD_t *file, H5FD_mem_t type, haddr_t addr)
{
    (void)type;
    ((atomic_file *)file)->eoa = addr;
    return 0;
}

static haddr_t atomic_get_eof(const H5FD_t *file, H5FD_mem_t type)
{
    (void)type;
    return ((const atomic_file *)file)->eof;
}

static herr_t atomic_get_handle(H5FD_t *file, hid_t fapl, void **handle)
{
    (void)fapl;
    if (!handle)
        return -1;
    *handle = &((atomic_file *)file)->fd;
    return 0;
}

static herr_t atomic_read(H5FD_t *file, H5FD_mem_t type, hid_t dxpl, haddr_t addr, size_t size,
                          void *buf)
{
    (void)type;
    (void)dxpl;
    atomic_file *f = (atomic_file *)file;
    if (addr == HADDR_UNDEF || addr + size < addr || addr + size > ATOMIC_MAXADDR)
        return -1;
    unsigned char *p = buf;
    size_t left = size;
    haddr_t at = addr;
    while (left > 0) {
        ssize_t k = pread(f->fd, p, left, (off_t)at);
        if (k < 0 && errno == EINTR)
            continue;
        if (k < 0)
            return -1;
        if (k == 0) { /* past the end of the file: zeros */
            memset(p, 0, left);
            break;
        }
        p += k;
        left -= (size_t)k;
        at += (haddr_t)k;
    }
    /* lay the journal over it, in the order it was written */
    for (size_t j = 0; j < f->journal_len;) {
        uint64_t a, n;
        entry_head(f->journal + j, &a, &n);
        haddr_t lo = a > addr ? a : addr, hi = a + n < addr + size ? a + n : addr + size;
        if (lo < hi)
            memcpy((unsigned char *)buf + (lo - addr), f->journal + j + 16 + (lo - a),
                   (size_t)(hi - lo));
        j += 16 + (size_t)n;
    }
    return 0;
}

static herr_t atomic_write(H5FD_t *file, H5FD_mem_t type, hid_t dxpl, haddr_t addr, size_t size,
                           const void *buf)
{
    (void)type;
    (void)dxpl;
    atomic_file *f = (atomic_file *)file;
    if (addr == HADDR_UNDEF || addr + size < addr || addr + size > ATOMIC_MAXADDR)
        return -1;
    const unsigned char *p = buf;
    if (addr < f->durable_end) {
        size_t in_place = addr + size <= f->durable_end ? size : (size_t)(f->durable_end - addr);
        if (!f->abandoned && journal_add(f, addr, in_place, p) != 0)
            return -1;
        p += in_place;
        addr += in_place;
        size -= in_place;
    }
    if (size > 0 && test_die_direct > 0 && size >= test_die_direct) {
        write_at(f->fd, p, test_die_direct, addr);
        raise(SIGKILL);
    }
    if (size > 0 && test_die_direct > 0)
        test_die_direct -= size;
    if (size > 0 && write_at(f->fd, p, size, addr) != 0)
        return -1;
    if (addr + size > f->eof)
        f->eof = addr + size;
    return 0;
}

static herr_t atomic_flush(H5FD_t *file, hid_t dxpl, hbool_t closing)
{
    (void)dxpl;
    (void)closing;
    return commit_journal((atomic_file *)file) == 0 ? 0 : -1;
}

static herr_t atomic_truncate(H5FD_t *file, hid_t dxpl, hbool_t closing)
{
    (void)dxpl;
    (void)closing;
    atomic_file *f = (atomic_file *)file;
    if (f->eoa > f->eof) {
        if (ftruncate(f->fd, (off_t)f->eoa) != 0)
            return -1;
        f->eof = f->eoa;
    } else if (f->eoa < f->eof) {
        /* the superblock naming the smaller end is still in the journal */
        f->shrink_to = f->eoa;
        f->eof = f->eoa;
    }
    return 0;
}

static herr_t atomic_lock(H5FD_t *file, hbool_t rw)
{
    (void)file;
    (void)rw;
    return 0; /* a run is read while it is written (h5util.c: no flock) */
}

static herr_t atomic_unlock(H5FD_t *file)
{
    (void)file;
    return 0;
}

static const H5FD_class_t atomic_class = {
    .name = "modesplit_atomic",
    .maxaddr = ATOMIC_MAXADDR,
    .fc_degree = H5F_CLOSE_WEAK,
    .open = atomic_open,
    .close = atomic_close,
    .cmp = atomic_cmp,
    .query = atomic_query,
    .get_eoa = atomic_get_eoa,
    .set_eoa = atomic_set_eoa,
    .get_eof = atomic_get_eof,
    .get_handle = atomic_get_handle,
    .read = atomic_read,
    .write = atomic_write,
    .flush = atomic_flush,
    .truncate = atomic_truncate,
    .lock = atomic_lock,
    .unlock = atomic_unlock,
    .fl_map = H5FD_FLMAP_DICHOTOMY,
};

static void register_driver(void)
{
    driver_id = H5FDregister(&atomic_class);
}

hid_t ms_h5_fapl_atomic(void)
{
    hid_t fapl = ms_h5_fapl();
    if (fapl < 0)
        return fapl;
    pthread_once(&driver_once, register_driver);
    if (driver_id < 0 || H5Pset_driver(fapl, driver_id, NULL) < 0) {
        H5Pclose(fapl);
        return -1;
    }
    return fapl;
}

/* The driver's file behind an open file id, NULL for another driver. */
static atomic_file *atomic_of(hid_t file)
{
    if (driver_id < 0)
        return NULL;
    hid_t fapl = H5Fget_access_plist(file);
    if (fapl < 0) {
        H5Eclear2(H5E_DEFAULT);
        return NULL;
    }
    hid_t drv = H5Pget_driver(fapl);
    H5Pclose(fapl);
    int *fdp = NULL;
    if (drv != driver_id || H5Fget_vfd_handle(file, H5P_DEFAULT, (void **)&fdp) < 0 || !fdp) {
        H5Eclear2(H5E_DEFAULT);
        return NULL;
    }
    return (atomic_file *)((char *)fdp - offsetof(atomic_file, fd));
}

int ms_h5_atomic_active(hid_t file)
{
    const atomic_file *f = atomic_of(file);
    return f && f->helper != HELPER_UNAVAILABLE;
}

void ms_h5_atomic_abandon(hid_t file)
{
    atomic_file *f = atomic_of(file);
    if (f) {
        f->abandoned = 1;
        f->journal_len = 0;
    }
}

void ms_h5_atomic_renamed(hid_t file, const char *name)
{
    atomic_file *f = atomic_of(file);
    if (f)
        snprintf(f->name, sizeof f->name, "%s", name);
}

void ms_h5_atomic_test_die_writing(size_t bytes)
{
    test_die_direct = bytes;
}

void ms_h5_atomic_test_die(int batch, long at, int without_helper)
{
    test_die_batch = batch;
    test_die_at = at;
    test_die_after = 0;
    test_no_helper = without_helper;
}
