/* The tool's one open of a file it reads from a user's path (a viewer's
 * input log, accuracy's part files): a regular file only. Its own file,
 * so that tests/test_view links it with the viewer's parts. */
#include <errno.h>
#include <fcntl.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "tool.h"

FILE *tool_fopen_regular(const char *path, const char **why)
{
    int fd = open(path, O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
    struct stat sb;
    if (fd < 0 || fstat(fd, &sb) != 0) {
        int e = errno;
        *why = strerror(e);
        if (fd >= 0)
            close(fd);
        errno = e;
        return NULL;
    }
    if (!S_ISREG(sb.st_mode)) {
        close(fd);
        *why = "not a regular file (a FIFO or a device is never read)";
        errno = 0;
        return NULL;
    }
    FILE *f = fdopen(fd, "r");
    if (!f) {
        int e = errno;
        *why = strerror(e);
        close(fd);
        errno = e;
    }
    return f;
}
