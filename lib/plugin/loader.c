/* Opening and checking one plugin file: the ELF header, dlopen, the entry
 * symbol, then the ABI and sizes before any other field is read (the
 * GStreamer/OBS habit), then the vtable. Every failure closes the library
 * and names the file and the symbol (SQLite's load_extension habit). */
#include <dlfcn.h>
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/core_internal.h"
#include "plugin/plugin_internal.h"

/* The smallest structs a plugin of ABI 1.0 may hand over: everything up to
 * and including the last field of 1.0. */
#define INFO_SIZE_1_0 (offsetof(ms_plugin_info, vtable) + sizeof(const void *))
#define SHAPE_VT_SIZE_1_0 (offsetof(ms_shape_vtable, height_at) + sizeof(void (*)(void)))
#define SHADER_VT_SIZE_1_0 (offsetof(ms_shader_vtable, set_uniforms) + sizeof(void (*)(void)))

/* The host's allocator for plugins (ABI 1.1): the library's own, which is
 * the engine's when it set one, so a plugin's blocks count among the
 * library's (ms_set_allocator refuses a change while they live). */
static void *host_alloc(size_t n)
{
    return ms_malloc(n);
}

static void host_free(void *p)
{
    ms_free(p);
}

static const ms_plugin_host host = {
    .size = sizeof(ms_plugin_host), .alloc_fn = host_alloc, .free_fn = host_free};

ms_status ms_plugin_status(int rc)
{
    switch (rc) {
    case MS_PLUGIN_OK:
        return MS_OK;
    case MS_PLUGIN_ERR_INVALID_ARGUMENT:
        return MS_ERR_INVALID_ARGUMENT;
    case MS_PLUGIN_ERR_OUT_OF_MEMORY:
        return MS_ERR_OUT_OF_MEMORY;
    case MS_PLUGIN_ERR_IO:
        return MS_ERR_IO;
    case MS_PLUGIN_ERR_PARSE:
        return MS_ERR_PARSE;
    default:
        return MS_ERR_PLUGIN;
    }
}

const char *ms_plugin_kind_name(uint32_t kind)
{
    switch (kind) {
    case MS_PLUGIN_SHAPE:
        return "shape";
    case MS_PLUGIN_SHADER:
        return "shader";
    default:
        return "unknown";
    }
}

/* A shared object is an ELF file of type ET_DYN; anything else is refused
 * before dlopen sees it (so a text file gets a clear sentence). */
/* Only a regular file is read, opened without blocking: a FIFO, device or
 * socket named *.so in a plugin folder would otherwise block every scan
 * (which holds the registry's lock) until someone writes to it. */
static ms_status check_elf(const char *path)
{
    int fd = open(path, O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0)
        return ms_fail(MS_ERR_IO, "plugin: cannot open %s: %s", path, strerror(errno));
    struct stat sb;
    if (fstat(fd, &sb) != 0 || !S_ISREG(sb.st_mode)) {
        close(fd);
        return ms_fail(MS_ERR_PLUGIN,
                       "plugin: %s is not a regular file (a FIFO, device or "
                       "socket is never loaded)",
                       path);
    }
    unsigned char h[18];
    ssize_t got = read(fd, h, sizeof h);
    close(fd);
    size_t n = got > 0 ? (size_t)got : 0;
    if (n < sizeof h || memcmp(h, "\177ELF", 4) != 0)
        return ms_fail(MS_ERR_PLUGIN, "plugin: %s is not a shared object (no ELF header)", path);
    unsigned type = h[5] == 2 ? (unsigned)h[16] << 8 | h[17] : (unsigned)h[17] << 8 | h[16];
    if (type != 3 /* ET_DYN */)
        return ms_fail(MS_ERR_PLUGIN,
                       "plugin: %s is not a shared object (ELF type %u, a shared object is 3)",
                       path, type);
    return MS_OK;
}

static int valid_name(const char *s)
{
    size_t n = 0;
    for (; s[n]; ++n) {
        char c = s[n];
        if (!((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || c == '-'))
            return 0;
        if (n >= MS_PLUGIN_NAME_MAX)
            return 0;
    }
    return n > 0;
}

/* Checks the fields after abi/size; `rec` holds the copies. */
static ms_status check_contents(const char *path, ms_plugin_rec *rec)
{
    const ms_plugin_info *in = &rec->info;
    const char *sym = MS_PLUGIN_ENTRY_SYMBOL;
    if (!in->name || !valid_name(in->name))
        return ms_fail(MS_ERR_PLUGIN,
                       "plugin: %s: %s gives an invalid name (1 to %d characters of "
                       "a-z, 0-9, '_', '-')",
                       path, sym, MS_PLUGIN_NAME_MAX);
    if (in->kind != MS_PLUGIN_SHAPE && in->kind != MS_PLUGIN_SHADER)
        return ms_fail(MS_ERR_PLUGIN,
                       "plugin: %s: %s gives kind %u for \"%s\"; known kinds are %u (shape) "
                       "and %u (shader)",
                       path, sym, (unsigned)in->kind, in->name, MS_PLUGIN_SHAPE, MS_PLUGIN_SHADER);
    if (!in->vtable)
        return ms_fail(MS_ERR_PLUGIN, "plugin: %s: %s gives no vtable for \"%s\"", path, sym,
                       in->name);
    uint32_t vsize = *(const uint32_t *)in->vtable;
    size_t need = in->kind == MS_PLUGIN_SHAPE ? SHAPE_VT_SIZE_1_0 : SHADER_VT_SIZE_1_0;
    size_t have = in->kind == MS_PLUGIN_SHAPE ? sizeof rec->vt.shape : sizeof rec->vt.shader;
    if (vsize < need)
        return ms_fail(MS_ERR_PLUGIN,
                       "plugin: %s: %s: the %s vtable of \"%s\" is %u bytes, smaller than "
                       "the %zu bytes of ABI 1.0 (truncated)",
                       path, sym, ms_plugin_kind_name(in->kind), in->name, (unsigned)vsize, need);
    memcpy(&rec->vt, in->vtable, MS_MIN((size_t)vsize, have));
    rec->info.vtable = &rec->vt;
    if (in->kind == MS_PLUGIN_SHAPE) {
        const ms_shape_vtable *v = &rec->vt.shape;
        const char *missing = !v->create     ? "create"
                              : !v->destroy  ? "destroy"
                              : !v->distance ? "distance"
                              : !v->bounds   ? "bounds"
                                             : NULL;
        if (missing)
            return ms_fail(MS_ERR_PLUGIN,
                           "plugin: %s: %s: the shape vtable of \"%s\" has no %s function", path,
                           sym, in->name, missing);
    } else {
        const ms_shader_vtable *v = &rec->vt.shader;
        const char *missing = !v->vertex_source               ? "vertex_source"
                              : !v->fragment_source           ? "fragment_source"
                              : (!v->create) != (!v->destroy) ? "create/destroy pair"
                                                              : NULL;
        if (missing)
            return ms_fail(MS_ERR_PLUGIN, "plugin: %s: %s: the shader vtable of \"%s\" has no %s",
                           path, sym, in->name, missing);
    }
    if (!rec->info.version)
        rec->info.version = "";
    if (!rec->info.description)
        rec->info.description = "";
    return MS_OK;
}

/* Everything after dlopen; the caller closes the handle on failure. */
static ms_status check_loaded(const char *path, void *handle, ms_plugin_rec *rec)
{
    const char *sym = MS_PLUGIN_ENTRY_SYMBOL;
    dlerror();
    void *p = dlsym(handle, sym);
    if (!p)
        return ms_fail(MS_ERR_PLUGIN,
                       "plugin: %s has no symbol %s; it is not a libmodesplit plugin", path, sym);
    ms_plugin_entry_fn entry;
    memcpy(&entry, &p, sizeof entry); /* object to function pointer, POSIX */
    const ms_plugin_info *in = entry();
    if (!in)
        return ms_fail(MS_ERR_PLUGIN, "plugin: %s: %s returned NULL", path, sym);
    /* abi and size first, nothing else before they pass */
    uint32_t abi = in->abi, size = in->size;
    if (abi >> 16 != MS_PLUGIN_ABI_MAJOR)
        return ms_fail(MS_ERR_PLUGIN,
                       "plugin: %s: %s gives ABI %u.%u; this libmodesplit loads ABI %u.x "
                       "(rebuild the plugin against its headers)",
                       path, sym, abi >> 16, abi & 0xffffu, MS_PLUGIN_ABI_MAJOR);
    if ((abi & 0xffffu) > MS_PLUGIN_ABI_MINOR)
        return ms_fail(MS_ERR_PLUGIN,
                       "plugin: %s: %s gives ABI %u.%u, newer than the %u.%u of this "
                       "libmodesplit",
                       path, sym, abi >> 16, abi & 0xffffu, MS_PLUGIN_ABI_MAJOR,
                       MS_PLUGIN_ABI_MINOR);
    if (size < INFO_SIZE_1_0)
        return ms_fail(MS_ERR_PLUGIN,
                       "plugin: %s: %s gives an ms_plugin_info of size %u bytes, smaller "
                       "than the %zu bytes of ABI 1.0 (truncated)",
                       path, sym, (unsigned)size, (size_t)INFO_SIZE_1_0);
    memset(&rec->info, 0, sizeof rec->info); /* fields past a 1.0 plugin's size: absent */
    memcpy(&rec->info, in, MS_MIN((size_t)size, sizeof rec->info));
    ms_status st = check_contents(path, rec);
    if (st == MS_OK && rec->info.set_host)
        rec->info.set_host(&host);
    return st;
}

ms_status ms_plugin_open(const char *path, ms_plugin_rec **out)
{
    *out = NULL;
    if (!path || !*path)
        return ms_fail(MS_ERR_INVALID_ARGUMENT, "plugin: the file path is empty");
    ms_status st = check_elf(path);
    if (st != MS_OK)
        return st;
    /* dlopen searches the library path for a name without a slash */
    char *full = ms_malloc(strlen(path) + 3);
    if (!full)
        return ms_fail(MS_ERR_OUT_OF_MEMORY, "plugin: out of memory loading %s", path);
    sprintf(full, "%s%s", strchr(path, '/') ? "" : "./", path);
    void *handle = dlopen(full, RTLD_NOW | RTLD_LOCAL);
    ms_free(full);
    if (!handle) {
        const char *why = dlerror();
        return ms_fail(MS_ERR_PLUGIN, "plugin: %s could not be loaded: %s", path,
                       why ? why : "unknown dlopen error");
    }
    ms_plugin_rec *rec = ms_alloc_array(1, sizeof *rec);
    char *copy = rec ? ms_malloc(strlen(path) + 1) : NULL;
    if (!copy) {
        ms_free(rec);
        dlclose(handle);
        return ms_fail(MS_ERR_OUT_OF_MEMORY, "plugin: out of memory loading %s", path);
    }
    strcpy(copy, path);
    st = check_loaded(path, handle, rec);
    if (st != MS_OK) {
        ms_free(copy);
        ms_free(rec);
        dlclose(handle);
        return st;
    }
    rec->handle = handle;
    rec->path = copy;
    *out = rec;
    return MS_OK;
}
