/* Shared helpers of the benchmark programs (tools/bench/<name>.c): a clock,
 * median and spread, the machine and commit for each CSV row, a memory
 * bandwidth measured in the same run, and the --csv-dir option.
 * Header-only (static inline) because each tools/bench source file is a program of
 * its own. Benchmarks skip a warm-up, repeat, and report the median. */
#ifndef MS_BENCH_COMMON_H
#define MS_BENCH_COMMON_H

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

static inline double bench_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static inline int bench_cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* Sorts v; median, and the spread as the 10th and 90th percentiles (with
 * few repeats these are the min and max). */
typedef struct {
    double median, p10, p90;
} bench_stats;

static inline bench_stats bench_summarise(double *v, int n)
{
    bench_stats s = {0, 0, 0};
    if (n <= 0)
        return s;
    qsort(v, (size_t)n, sizeof *v, bench_cmp_double);
    s.median = n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
    s.p10 = v[(int)(0.1 * (n - 1))];
    s.p90 = v[(int)(0.9 * (n - 1) + 0.999)];
    return s;
}

/* "Intel(R) Xeon(R) Processor, 2 cores" */
static inline void bench_machine(char *buf, size_t n)
{
    char model[256] = "unknown CPU";
    FILE *f = fopen("/proc/cpuinfo", "r");
    if (f) {
        char line[512];
        while (fgets(line, sizeof line, f)) {
            if (strncmp(line, "model name", 10) == 0) {
                char *c = strchr(line, ':');
                if (c) {
                    c += 2;
                    c[strcspn(c, "\n")] = 0;
                    snprintf(model, sizeof model, "%s", c);
                }
                break;
            }
        }
        fclose(f);
    }
    /* commas would split the CSV field */
    for (char *c = model; *c; ++c)
        if (*c == ',')
            *c = ';';
    snprintf(buf, n, "%s; %ld cores", model, sysconf(_SC_NPROCESSORS_ONLN));
}

static inline void bench_commit(char *buf, size_t n)
{
    snprintf(buf, n, "unknown");
    FILE *p = popen("git rev-parse --short HEAD 2>/dev/null", "r");
    if (!p)
        return;
    char line[64];
    if (fgets(line, sizeof line, p)) {
        line[strcspn(line, "\n")] = 0;
        if (line[0])
            snprintf(buf, n, "%s", line);
    }
    pclose(p);
}

/* Memory bandwidth in GB/s (bytes read + bytes written per second) of
 * memcpy over a buffer larger than the caches, median of `reps`. */
static inline double bench_memcpy_gbps(size_t bytes, int reps)
{
    char *a = malloc(bytes), *b = malloc(bytes);
    if (!a || !b) {
        free(a);
        free(b);
        return 0;
    }
    memset(a, 1, bytes);
    memset(b, 2, bytes);
    double t[64];
    if (reps > 64)
        reps = 64;
    for (int r = 0; r < reps; ++r) {
        double t0 = bench_now();
        memcpy(r % 2 ? a : b, r % 2 ? b : a, bytes);
        t[r] = bench_now() - t0;
    }
    volatile char sink = a[bytes / 2] + b[bytes / 3];
    (void)sink;
    free(a);
    free(b);
    bench_stats s = bench_summarise(t, reps);
    return 2.0 * (double)bytes / s.median * 1e-9;
}

/* --csv-dir DIR (default "bench"); --quick for a short smoke run. */
static inline const char *bench_csv_dir(int argc, char **argv)
{
    for (int i = 1; i + 1 < argc; ++i)
        if (strcmp(argv[i], "--csv-dir") == 0)
            return argv[i + 1];
    return "bench";
}

/* --help or -h: prints the usage and what the program measures, and says
 * so (the caller exits 0 without measuring anything). */
static inline int bench_help(int argc, char **argv, const char *usage)
{
    for (int i = 1; i < argc; ++i)
        if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0) {
            fputs(usage, stdout);
            return 1;
        }
    return 0;
}

static inline int bench_quick(int argc, char **argv)
{
    for (int i = 1; i < argc; ++i)
        if (strcmp(argv[i], "--quick") == 0)
            return 1;
    return 0;
}

/* The value after `key` on the command line, def when it is absent. */
static inline const char *bench_arg_value(int argc, char **argv, const char *key, const char *def)
{
    for (int i = 1; i + 1 < argc; ++i)
        if (strcmp(argv[i], key) == 0)
            return argv[i + 1];
    return def;
}

/* 1 when name is in the comma-separated list (--scenes a,b), or no list. */
static inline int bench_wanted(const char *list, const char *name)
{
    if (!list)
        return 1;
    size_t n = strlen(name);
    for (const char *p = list; *p;) {
        const char *e = strchr(p, ',');
        size_t len = e ? (size_t)(e - p) : strlen(p);
        if (len == n && strncmp(p, name, n) == 0)
            return 1;
        p += len + (e ? 1 : 0);
    }
    return 0;
}

/* Opens DIR/NAME for writing (creating DIR) and writes the header line. */
static inline FILE *bench_csv_open(const char *dir, const char *name, const char *header)
{
    if (mkdir(dir, 0777) != 0 && errno != EEXIST) {
        fprintf(stderr, "bench: cannot create %s: %s\n", dir, strerror(errno));
        return NULL;
    }
    char path[1024];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    FILE *f = fopen(path, "w");
    if (!f) {
        fprintf(stderr, "bench: cannot write %s: %s\n", path, strerror(errno));
        return NULL;
    }
    fprintf(f, "%s\n", header);
    return f;
}

#endif /* MS_BENCH_COMMON_H */
