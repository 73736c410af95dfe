/* Opening a file named by untrusted input (a scene's PNG, a cubemap face):
 * only a regular file is read. A FIFO blocks the open until a writer comes
 * (check and run would hang), a device such as /dev/zero or /dev/stdin
 * never ends or reads the terminal, so both are refused before anything is
 * read: the open does not block (O_NONBLOCK) and the kind is taken from
 * the open descriptor, so a file swapped after a stat cannot slip in. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <fcntl.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/core_internal.h"

const char *ms_file_kind(mode_t mode)
{
    return S_ISREG(mode)    ? "a regular file"
           : S_ISDIR(mode)  ? "a directory"
           : S_ISFIFO(mode) ? "a FIFO (named pipe)"
           : S_ISCHR(mode)  ? "a character device"
           : S_ISBLK(mode)  ? "a block device"
           : S_ISSOCK(mode) ? "a socket"
                            : "not a regular file";
}

FILE *ms_fopen_regular(const char *path, const char **why)
{
    *why = NULL;
    int fd = open(path, O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
    if (fd < 0) {
        *why = strerror(errno);
        return NULL;
    }
    struct stat sb;
    int known = fstat(fd, &sb) == 0;
    if (!known || !S_ISREG(sb.st_mode)) {
        *why = known ? ms_file_kind(sb.st_mode) : strerror(errno);
        close(fd);
        return NULL;
    }
    int fl = fcntl(fd, F_GETFL);
    if (fl >= 0)
        (void)fcntl(fd, F_SETFL, fl & ~O_NONBLOCK);
    FILE *f = fdopen(fd, "rb");
    if (!f) {
        *why = strerror(errno);
        close(fd);
    }
    return f;
}
