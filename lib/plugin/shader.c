/* Shader plugins made ready for the renderer: find by name, create the
 * instance from its JSON parameters. The renderer compiles the sources and
 * calls set_uniforms (section 3.6 of the paper: reflection, refraction,
 * caustics). */
#include <string.h>

#include "core/core_internal.h"
#include "plugin/plugin_internal.h"

ms_status ms_shader_instance_create(const char *name, const char *params_json,
                                    ms_shader_instance *out)
{
    ms_status st = ms_check_not_null("shader", "out", out);
    if (st != MS_OK)
        return st;
    memset(out, 0, sizeof *out);
    if ((st = ms_check_not_null("shader", "name", name)) != MS_OK)
        return st;
    const ms_plugin_rec *rec;
    if ((st = ms_plugin_find("shader", name, MS_PLUGIN_SHADER, &rec)) != MS_OK)
        return st;
    const ms_shader_vtable *vt = &rec->vt.shader;
    void *self = NULL;
    if (vt->create) {
        char err[512] = "";
        int rc = vt->create(params_json, &self, err, sizeof err);
        if (rc != MS_PLUGIN_OK) {
            err[sizeof err - 1] = '\0';
            ms_status code = ms_plugin_status(rc);
            return ms_fail(code, "shader %s: %s", name,
                           err[0] ? err : "the plugin refused the parameters without a reason");
        }
    } else if (params_json && strspn(params_json, " \t\r\n{}") != strlen(params_json)) {
        return ms_fail(MS_ERR_INVALID_ARGUMENT, "shader %s: takes no parameters", name);
    }
    out->plugin = rec;
    out->vt = vt;
    out->self = self;
    return MS_OK;
}

void ms_shader_instance_destroy(ms_shader_instance *in)
{
    if (!in || !in->vt)
        return;
    if (in->vt->destroy)
        in->vt->destroy(in->self);
    memset(in, 0, sizeof *in);
}
