/* The registry of loaded plugins: the library's only global mutable state
 * (besides the thread-local error sentence). A mutex guards it; the first
 * scan of the search path runs once, on first use, under pthread_once.
 * Records are never freed: a shape or shader made from a plugin keeps
 * pointers into it until the process ends. */
#define _DEFAULT_SOURCE /* realpath */
#include <dirent.h>
#include <dlfcn.h>
#include <limits.h>
#include <stdio.h>
#include <pthread.h>
#include <stdlib.h>
#include <string.h>

#include "core/core_internal.h"
#include "plugin/plugin_sizes.h"
#include "plugin/plugin_internal.h"

static pthread_once_t scan_once = PTHREAD_ONCE_INIT;
static pthread_mutex_t lock = PTHREAD_MUTEX_INITIALIZER;
static ms_plugin_rec **plugins; /* sorted by kind, then name */
static int n_plugins, cap_plugins;
static char **problems;
static int n_problems, cap_problems;
static char *search_path;

#define dup_str ms_strdup /* lib/core */

static void add_problem(const char *sentence)
{
    if (n_problems == cap_problems) {
        int cap = cap_problems ? 2 * cap_problems : 8;
        char **t = ms_realloc(problems, (size_t)cap * sizeof *t);
        if (!t)
            return;
        problems = t;
        cap_problems = cap;
    }
    char *d = dup_str(sentence);
    if (d)
        problems[n_problems++] = d;
}

static int order(const ms_plugin_rec *a, const ms_plugin_rec *b)
{
    if (a->info.kind != b->info.kind)
        return a->info.kind < b->info.kind ? -1 : 1;
    return strcmp(a->info.name, b->info.name);
}

static const ms_plugin_rec *find_name(const char *name)
{
    for (int i = 0; i < n_plugins; ++i)
        if (strcmp(plugins[i]->info.name, name) == 0)
            return plugins[i];
    return NULL;
}

/* Takes ownership of rec: registers it, or closes and frees it on a
 * duplicate name. Called with the lock held. */
static ms_status add_plugin(ms_plugin_rec *rec)
{
    const ms_plugin_rec *old = find_name(rec->info.name);
    ms_status st = MS_OK;
    if (old)
        st = ms_fail(MS_ERR_PLUGIN,
                     "plugin: %s: %s gives the name \"%s\", already registered from %s", rec->path,
                     MS_PLUGIN_ENTRY_SYMBOL, rec->info.name, old->path);
    else if (n_plugins == cap_plugins) {
        int cap = cap_plugins ? 2 * cap_plugins : 16;
        ms_plugin_rec **t = ms_realloc(plugins, (size_t)cap * sizeof *t);
        if (!t)
            st = ms_fail(MS_ERR_OUT_OF_MEMORY, "plugin: out of memory registering %s", rec->path);
        else {
            plugins = t;
            cap_plugins = cap;
        }
    }
    if (st != MS_OK) {
        dlclose(rec->handle);
        ms_free(rec->path);
        ms_free(rec);
        return st;
    }
    int at = n_plugins;
    while (at > 0 && order(plugins[at - 1], rec) > 0) {
        plugins[at] = plugins[at - 1];
        --at;
    }
    plugins[at] = rec;
    ++n_plugins;
    return MS_OK;
}

static int by_name(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

static int ends_with_so(const char *s)
{
    size_t n = strlen(s);
    return n > 3 && strcmp(s + n - 3, ".so") == 0;
}

/* Loads every *.so of one directory, in name order. Lock held. */
static void scan_dir(const char *dir)
{
    DIR *d = opendir(dir);
    if (!d)
        return;
    char **names = NULL;
    int n = 0, cap = 0;
    for (struct dirent *e; (e = readdir(d));) {
        if (!ends_with_so(e->d_name))
            continue;
        if (n == cap) {
            cap = cap ? 2 * cap : 16;
            char **t = ms_realloc(names, (size_t)cap * sizeof *t);
            if (!t)
                break;
            names = t;
        }
        if (!(names[n] = dup_str(e->d_name)))
            break;
        ++n;
    }
    closedir(d);
    if (n > 1)
        qsort(names, (size_t)n, sizeof *names, by_name);
    for (int i = 0; i < n; ++i) {
        char *path = ms_malloc(strlen(dir) + strlen(names[i]) + 2);
        if (path) {
            strcpy(path, dir);
            strcat(path, "/");
            strcat(path, names[i]);
            ms_plugin_rec *rec;
            ms_status st = ms_plugin_open(path, &rec);
            if (st == MS_OK)
                st = add_plugin(rec);
            if (st != MS_OK)
                add_problem(ms_last_error());
            ms_free(path);
        }
        ms_free(names[i]);
    }
    ms_free(names);
}

static void scan(void)
{
    /* the scan must not leave its problems as the caller's error */
    char saved[1024];
    snprintf(saved, sizeof saved, "%s", ms_last_error());
    pthread_mutex_lock(&lock);
    search_path = ms_plugin_default_search_path();
    char **seen = NULL; /* canonical directories already scanned */
    int n_seen = 0;
    /* the first n_env directories are the user's: say if one is missing */
    int n_env = 0;
    for (const char *e = getenv("MODESPLIT_PLUGIN_PATH"); e && *e;) {
        size_t n = strcspn(e, ":");
        n_env += n > 0;
        e += n + (e[n] == ':');
    }
    for (const char *p = search_path; p && *p; --n_env) {
        const char *colon = strchr(p, ':');
        size_t n = colon ? (size_t)(colon - p) : strlen(p);
        char *dir = ms_malloc(n + 1);
        if (dir) {
            memcpy(dir, p, n);
            dir[n] = '\0';
            char real[PATH_MAX];
            char *canon = realpath(dir, real) ? ms_strdup(real) : NULL;
            if (!canon && n_env > 0) {
                char msg[1200];
                snprintf(msg, sizeof msg,
                         "plugin: directory %s of MODESPLIT_PLUGIN_PATH does not exist", dir);
                add_problem(msg);
            }
            int dup = 0;
            for (int i = 0; canon && i < n_seen; ++i)
                dup |= strcmp(seen[i], canon) == 0;
            if (canon && !dup) {
                char **t = ms_realloc(seen, (size_t)(n_seen + 1) * sizeof *t);
                if (t) {
                    seen = t;
                    seen[n_seen++] = canon;
                    canon = NULL;
                    scan_dir(dir);
                }
            }
            ms_free(canon);
            ms_free(dir);
        }
        p += n + (colon != NULL);
    }
    for (int i = 0; i < n_seen; ++i)
        ms_free(seen[i]);
    ms_free(seen);
    pthread_mutex_unlock(&lock);
    ms_fail(MS_OK, "%s", saved);
}

static void ensure_scanned(void)
{
    pthread_once(&scan_once, scan);
}

int ms_plugin_count(void)
{
    ensure_scanned();
    pthread_mutex_lock(&lock);
    int n = n_plugins;
    pthread_mutex_unlock(&lock);
    return n;
}

ms_status ms_plugin_describe(int i, ms_plugin_description *user)
{
    if (!user)
        return ms_fail(MS_ERR_INVALID_ARGUMENT, "plugin: describe: out is NULL");
    size_t size = ms_struct_out(user, MS_SIZES_PLUGIN_DESCRIPTION, "plugin");
    if (!size)
        return MS_ERR_INVALID_ARGUMENT; /* the sentence is set */
    ms_plugin_description full = ms_plugin_description_init(), *out = &full;
    ensure_scanned();
    pthread_mutex_lock(&lock);
    if (i < 0 || i >= n_plugins) {
        int n = n_plugins;
        pthread_mutex_unlock(&lock);
        return ms_fail(MS_ERR_INVALID_ARGUMENT, "plugin: index %d is outside [0, %d)", i, n);
    }
    const ms_plugin_rec *r = plugins[i];
    pthread_mutex_unlock(&lock);
    out->name = r->info.name;
    out->kind = ms_plugin_kind_name(r->info.kind);
    out->version = r->info.version;
    out->description = r->info.description;
    out->path = r->path;
    out->abi = r->info.abi;
    ms_struct_write(user, &full, size);
    return MS_OK;
}

ms_status ms_plugin_load(const char *path)
{
    if (!path)
        return ms_fail(MS_ERR_INVALID_ARGUMENT, "plugin: load: path is NULL");
    ensure_scanned();
    pthread_mutex_lock(&lock);
    ms_plugin_rec *rec;
    ms_status st = ms_plugin_open(path, &rec);
    if (st == MS_OK)
        st = add_plugin(rec);
    pthread_mutex_unlock(&lock);
    return st;
}

int ms_plugin_problem_count(void)
{
    ensure_scanned();
    pthread_mutex_lock(&lock);
    int n = n_problems;
    pthread_mutex_unlock(&lock);
    return n;
}

const char *ms_plugin_problem(int i)
{
    ensure_scanned();
    pthread_mutex_lock(&lock);
    const char *s = i >= 0 && i < n_problems ? problems[i] : NULL;
    pthread_mutex_unlock(&lock);
    return s;
}

const char *ms_plugin_search_path(void)
{
    ensure_scanned();
    return search_path ? search_path : "";
}

ms_status ms_plugin_find(const char *part, const char *name, uint32_t kind,
                         const ms_plugin_rec **out)
{
    *out = NULL;
    const char *kname = ms_plugin_kind_name(kind);
    if (!name || !*name)
        return ms_fail(MS_ERR_INVALID_ARGUMENT, "%s: the %s kind name is empty", part, kname);
    ensure_scanned();
    pthread_mutex_lock(&lock);
    const ms_plugin_rec *r = find_name(name);
    if (r && r->info.kind == kind) {
        pthread_mutex_unlock(&lock);
        *out = r;
        return MS_OK;
    }
    char list[512] = "";
    size_t len = 0;
    int count = 0;
    for (int i = 0; i < n_plugins && len + 40 < sizeof list; ++i) {
        if (plugins[i]->info.kind != kind)
            continue;
        len += (size_t)snprintf(list + len, sizeof list - len, "%s%s", count ? ", " : "",
                                plugins[i]->info.name);
        ++count;
    }
    const char *other = r ? ms_plugin_kind_name(r->info.kind) : NULL;
    pthread_mutex_unlock(&lock);
    if (other)
        return ms_fail(MS_ERR_PLUGIN, "%s: \"%s\" is a %s plugin, not a %s; available %ss: %s",
                       part, name, other, kname, kname, count ? list : "none");
    if (count)
        return ms_fail(MS_ERR_PLUGIN, "%s: no %s plugin named \"%s\"; available %ss: %s", part,
                       kname, name, kname, list);
    return ms_fail(MS_ERR_PLUGIN,
                   "%s: no %s plugin named \"%s\"; available %ss: none (no %s plugin found in "
                   "%s; set MODESPLIT_PLUGIN_PATH)",
                   part, kname, name, kname, kname, search_path ? search_path : "");
}
