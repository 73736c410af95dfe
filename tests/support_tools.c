/* Helpers of the suites that run the tools and check the files they write
 * (with outside tools such as h5dump): a scratch directory, reading a
 * file whole. */
#include "support.h"

#include <dirent.h>
#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

int ms_test_tmp_dir(char *buf, size_t size, const char *prefix)
{
    const char *base = getenv("TMPDIR");
    int n = snprintf(buf, size, "%s/%s_XXXXXX", base && base[0] ? base : "/tmp", prefix);
    if (n < 0 || (size_t)n >= size)
        return -1;
    return mkdtemp(buf) ? 0 : -1;
}

void ms_test_remove_tree(const char *dir)
{
    DIR *d = opendir(dir);
    if (!d)
        return;
    struct dirent *e;
    while ((e = readdir(d)) != NULL) {
        if (!strcmp(e->d_name, ".") || !strcmp(e->d_name, ".."))
            continue;
        char p[1024];
        snprintf(p, sizeof p, "%s/%s", dir, e->d_name);
        struct stat sb;
        if (lstat(p, &sb) == 0 && S_ISDIR(sb.st_mode))
            ms_test_remove_tree(p);
        else
            remove(p);
    }
    closedir(d);
    rmdir(dir);
}

char *ms_test_slurp(const char *path)
{
    return ms_test_slurp_n(path, NULL);
}

char *ms_test_slurp_n(const char *path, size_t *size)
{
    if (size)
        *size = 0;
    FILE *f = fopen(path, "rb");
    if (!f)
        return strdup("");
    fseek(f, 0, SEEK_END);
    long n = ftell(f);
    fseek(f, 0, SEEK_SET);
    char *s = n >= 0 ? malloc((size_t)n + 1) : NULL;
    if (!s) {
        fclose(f);
        return strdup("");
    }
    size_t got = fread(s, 1, (size_t)n, f);
    s[got] = '\0';
    fclose(f);
    if (size)
        *size = got;
    return s;
}

char *ms_test_scene_variant(const char *path, const char *from, const char *to)
{
    char *text = ms_test_slurp(path);
    if (!from)
        return text;
    char *at = strstr(text, from);
    size_t len = strlen(text) + strlen(to) + 1;
    char *v = at ? malloc(len) : NULL;
    if (v)
        snprintf(v, len, "%.*s%s%s", (int)(at - text), text, to, at + strlen(from));
    free(text);
    return v;
}

const char *ms_test_tool_path(void)
{
    static char p[512];
    const char *b = getenv("MS_TEST_BUILD");
    snprintf(p, sizeof p, "%s/bin/modesplit", b && b[0] ? b : "build");
    return p;
}

/* In the child: fd onto `to` (NULL: /dev/null) for writing. */
static void redirect(int fd, const char *to)
{
    int f = open(to ? to : "/dev/null", O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (f >= 0 && f != fd) {
        dup2(f, fd);
        close(f);
    }
}

pid_t ms_test_spawn_tool(const char *const *args, const char *out, const char *err)
{
    const char *argv[32];
    int n = 0;
    argv[n++] = ms_test_tool_path();
    for (int i = 0; args[i] && n < 31; ++i)
        argv[n++] = args[i];
    argv[n] = NULL;
    pid_t pid = fork();
    ck_assert_int_ge(pid, 0);
    if (pid == 0) {
        int in = open("/dev/null", O_RDONLY);
        if (in >= 0 && in != 0) {
            dup2(in, 0);
            close(in);
        }
        redirect(1, out);
        if (out && err && strcmp(out, err) == 0)
            dup2(1, 2); /* one file, in the order written */
        else
            redirect(2, err);
        signal(SIGINT, SIG_DFL);
        signal(SIGTERM, SIG_DFL);
        execv(argv[0], (char *const *)argv);
        _exit(127);
    }
    return pid;
}

int ms_test_run_tool(const char *const *args, const char *out, const char *err)
{
    pid_t pid = ms_test_spawn_tool(args, out, err);
    int status = 0;
    ck_assert_int_eq(waitpid(pid, &status, 0), pid);
    return status;
}

int ms_test_h5dump(const char *path)
{
    if (system("command -v h5dump > /dev/null 2>&1") != 0)
        return -1;
    char cmd[1024];
    snprintf(cmd, sizeof cmd, "h5dump '%s' > /dev/null 2>&1", path);
    return system(cmd) == 0;
}

int ms_test_wait_unused(const char *path, double seconds)
{
    struct stat want;
    if (stat(path, &want) != 0)
        return 1;
    for (double waited = 0; waited <= seconds; waited += 0.01) {
        int open_here = 0;
        DIR *procs = opendir("/proc");
        if (!procs)
            return 1; /* no /proc: nothing to wait for that we could see */
        struct dirent *p;
        while (!open_here && (p = readdir(procs)))
            if (p->d_name[0] >= '1' && p->d_name[0] <= '9') {
                char dir[288];
                snprintf(dir, sizeof dir, "/proc/%s/fd", p->d_name);
                DIR *fds = opendir(dir);
                struct dirent *f;
                while (fds && !open_here && (f = readdir(fds))) {
                    char link[576];
                    struct stat got;
                    snprintf(link, sizeof link, "%s/%s", dir, f->d_name);
                    open_here = f->d_name[0] != '.' && stat(link, &got) == 0 &&
                                got.st_dev == want.st_dev && got.st_ino == want.st_ino;
                }
                if (fds)
                    closedir(fds);
            }
        closedir(procs);
        if (!open_here)
            return 1;
        struct timespec ts = {0, 10000000L};
        nanosleep(&ts, NULL);
    }
    return 0;
}
