/* Scene files: defaults, every shipped scene loads, and every kind of bad
 * input is refused with file:line:col, the key and what is allowed. */
#include <check.h>
#include <dirent.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "core/core_internal.h"
#include "modesplit/modesplit.h"
#include "scene/scene_internal.h"
#include "support.h"

static ms_scene *parse_ok(const char *text)
{
    ms_scene *sc = NULL;
    ms_status st = ms_scene_parse(text, strlen(text), &sc);
    ck_assert_msg(st == MS_OK, "%s: %s", ms_status_name(st), ms_last_error());
    return sc;
}

#define REFUSED(text, status, word) \
    MS_ASSERT_REFUSED(ms_scene_parse((text), strlen(text), &sc), (status), (word))

START_TEST(minimal_scene_gets_documented_defaults)
{
    ms_scene *sc = parse_ok("{\"surface\": {}}");
    ck_assert_str_eq(ms_scene_name(sc), "scene");
    ck_assert_str_eq(ms_scene_path(sc), "");
    ck_assert_double_eq_tol(ms_scene_duration(sc), 5, 1e-12);
    ck_assert_float_eq_tol(ms_scene_frame_dt(sc), 1.0f / 60, 1e-7f);
    ck_assert_uint_eq(ms_scene_output_fields(sc), MS_FIELD_COMBINED);
    ck_assert_int_eq(ms_scene_output_every(sc), 1);
    ck_assert_int_eq(ms_scene_has_render(sc), 0);
    ck_assert_int_eq(sc->has_volume, 0);
    ck_assert_int_eq(sc->has_surface, 1);
    ck_assert_int_eq(sc->surface.nx, 256);
    ck_assert_int_eq(sc->surface.ny, 256);
    /* the default domain is 1 m x 1 m x 0.5 m: square cells of 1/256 m */
    ck_assert_float_eq_tol(sc->surface.dx, 1.0f / 256, 1e-9f);
    ck_assert_float_eq_tol(sc->level, 0.25f, 1e-7f);
    ck_assert_int_eq(sc->has_rain + sc->has_boat + sc->has_floaters + sc->has_drag +
                         sc->has_container + sc->nobstacles + sc->ndrops,
                     0);
    ck_assert_str_eq(ms_scene_text(sc), "{\"surface\": {}}");
    ms_scene_destroy(sc);
}
END_TEST

START_TEST(volume_level_is_the_fill_spread_over_the_domain)
{
    ms_scene *sc = parse_ok("{\"domain\": {\"min\": [0,0,0], \"max\": [2,1,1]},"
                            " \"volume\": {\"spacing\": 0.05,"
                            "   \"fill\": [{\"min\": [0,0,0], \"max\": [1,1,0.4]}]},"
                            " \"surface\": {\"cells\": [200, 100]}}");
    ck_assert_int_eq(sc->has_volume, 1);
    ck_assert_int_eq(sc->nfill, 1);
    /* 0.4 m^3 over 2 m^2 */
    ck_assert_float_eq_tol(sc->level, 0.2f, 1e-6f);
    ck_assert_float_eq_tol(sc->surface.dx, 0.01f, 1e-7f);
    /* h follows the spacing at the volume desc default's ratio h / spacing */
    ms_volume_desc def = ms_volume_desc_default();
    ck_assert_float_eq(sc->volume.smoothing_length, def.smoothing_length / def.spacing * 0.05f);
    ms_scene_destroy(sc);
}
END_TEST

/* Every scene shipped in data/scenes loads, names itself and says what it shows. */
START_TEST(every_shipped_scene_loads)
{
    DIR *d = opendir("data/scenes");
    ck_assert_msg(d != NULL, "run from the source root");
    struct dirent *e;
    int n = 0;
    while ((e = readdir(d)) != NULL) {
        size_t len = strlen(e->d_name);
        if (len < 6 || strcmp(e->d_name + len - 5, ".json") != 0)
            continue;
        char path[512];
        snprintf(path, sizeof path, "data/scenes/%s", e->d_name);
        ms_scene *sc = NULL;
        ms_status st = ms_scene_load(path, &sc);
        ck_assert_msg(st == MS_OK, "%s: %s", path, ms_last_error());
        ck_assert_str_eq(ms_scene_path(sc), path);
        ck_assert_msg(strstr(ms_scene_text(sc), "\"comment\"") != NULL,
                      "%s has no comment saying what it shows", path);
        ck_assert(ms_scene_duration(sc) > 0);
        ms_scene_destroy(sc);
        ++n;
    }
    closedir(d);
    /* the six scenes of DESIGN 8, their _x10 variants and the default */
    ck_assert_int_ge(n, 13);
}
END_TEST

START_TEST(name_defaults_to_the_file_name)
{
    char path[] = "/tmp/ms_scene_XXXXXX";
    int fd = mkstemp(path);
    ck_assert_int_ge(fd, 0);
    const char *text = "{\"surface\": {}}";
    ck_assert_int_eq(write(fd, text, strlen(text)), (int)strlen(text));
    close(fd);
    ms_scene *sc = NULL;
    ck_assert_int_eq(ms_scene_load(path, &sc), MS_OK);
    ck_assert_str_eq(ms_scene_name(sc), strrchr(path, '/') + 1);
    ms_scene_destroy(sc);
    unlink(path);
}
END_TEST

START_TEST(syntax_error_names_line_and_column)
{
    ms_scene *sc = NULL;
    REFUSED("{\n  \"surface\": {\n    \"cells\": [10, 10],,\n  }\n}", MS_ERR_PARSE, "<scene>:3:");
    ck_assert_ptr_null(sc);
    REFUSED("", MS_ERR_PARSE, "syntax");
    REFUSED("[1, 2]", MS_ERR_PARSE, "not a JSON object");
    REFUSED("{\"surface\": {}} trailing", MS_ERR_PARSE, "syntax");
    /* JSON has no NaN or infinity; an overflowing number is a syntax error */
    REFUSED("{\"surface\": {\"wave_speed\": 1e999}}", MS_ERR_PARSE, "1:");
    REFUSED("{\"surface\": {\"wave_speed\": NaN}}", MS_ERR_PARSE, "syntax");
}
END_TEST

START_TEST(unknown_key_names_place_and_allowed_keys)
{
    ms_scene *sc = NULL;
    const char *text = "{\n"
                       "  \"surface\": {},\n"
                       "  \"effects\": {\n"
                       "    \"rian\": {}\n"
                       "  }\n"
                       "}";
    REFUSED(text, MS_ERR_PARSE, "<scene>:4:5: effects.rian is an unknown key");
    ck_assert_ptr_nonnull(strstr(ms_last_error(), "allowed: rain, boat"));
    REFUSED("{\"surface\": {}, \"colour\": 1}", MS_ERR_PARSE, "1:17: colour");
    /* "comment" is allowed everywhere, but must be a string */
    sc = parse_ok("{\"comment\": \"x\", \"surface\": {\"comment\": \"waves\"}}");
    ms_scene_destroy(sc);
    REFUSED("{\"surface\": {\"comment\": 3}}", MS_ERR_PARSE, "surface.comment is an integer");
}
END_TEST

START_TEST(wrong_type_names_key_and_allowed_type)
{
    ms_scene *sc = NULL;
    REFUSED("{\"surface\": {\"wave_speed\": \"fast\"}}", MS_ERR_PARSE,
            "1:14: surface.wave_speed is a string; allowed: a number (m/s)");
    REFUSED("{\"surface\": {\"cells\": [10.5, 10]}}", MS_ERR_PARSE,
            "surface.cells[0] is a number; allowed: a 32-bit integer");
    REFUSED("{\"surface\": {\"cells\": [10]}}", MS_ERR_PARSE, "of another length");
    REFUSED("{\"surface\": 3}", MS_ERR_PARSE, "allowed: an object");
    REFUSED("{\"surface\": {\"boundary\": 1}}", MS_ERR_PARSE, "\"reflect\", \"absorb\"");
    REFUSED("{\"surface\": {}, \"effects\": {\"rain\": {\"rate\": true}}}", MS_ERR_PARSE,
            "effects.rain.rate is a boolean");
    REFUSED("{\"surface\": {}, \"obstacles\": [3]}", MS_ERR_PARSE, "obstacles[0] is not an object");
}
END_TEST

START_TEST(out_of_range_names_value_and_range)
{
    ms_scene *sc = NULL;
    REFUSED("{\"surface\": {\"wave_speed\": -1}}", MS_ERR_INVALID_ARGUMENT,
            "surface.wave_speed is refused: surface: wave_speed -1 m/s must be finite and > 0");
    REFUSED("{\"surface\": {\"damping\": 0}}", MS_ERR_INVALID_ARGUMENT,
            "damping 0 is outside (0, 1]");
    REFUSED("{\"surface\": {\"cells\": [1, 10]}}", MS_ERR_INVALID_ARGUMENT,
            "surface.cells is refused: surface: nx 1 is outside [2, 16384]");
    REFUSED("{\"surface\": {\"cells\": [100, 50]}}", MS_ERR_INVALID_ARGUMENT, "square cells");
    REFUSED("{\"frame_dt\": 0, \"surface\": {}}", MS_ERR_INVALID_ARGUMENT, "frame_dt 0 s");
    REFUSED("{\"threads\": 3, \"surface\": {}}", MS_ERR_INVALID_ARGUMENT, "[1, 2]");
    REFUSED("{\"domain\": {\"max\": [1, 0, 1]}, \"surface\": {}}", MS_ERR_INVALID_ARGUMENT,
            "domain.max [1] = 0 m is not above min[1]");
    REFUSED("{\"volume\": {\"fill\": [{\"min\": [0,0,0], \"max\": [2,1,0.2]}]}}",
            MS_ERR_INVALID_ARGUMENT, "volume.fill[0].max [0] = 2 m lies outside the domain");
    REFUSED("{\"volume\": {\"spacing\": 0.0001, \"fill\": [{\"min\": [0,0,0], "
            "\"max\": [1,1,0.5]}]}}",
            MS_ERR_INVALID_ARGUMENT, "volume.spacing is refused: volume: the domain holds");
    REFUSED("{\"volume\": {\"max_particles\": 10, \"fill\": [{\"min\": [0,0,0], "
            "\"max\": [1,1,0.5]}]}}",
            MS_ERR_INVALID_ARGUMENT, "max_particles 10 is below");
    REFUSED("{\"volume\": {\"spacing\": 0.02, \"smoothing_length\": 0.01}}",
            MS_ERR_INVALID_ARGUMENT, "smoothing_length");
}
END_TEST

/* DFSPH's stop rule and caps: absent, the volume desc's defaults;
 * present, checked by the desc's check (its sentence at the key); and
 * under a weakly compressible law, where they would do nothing, refused. */
START_TEST(dfsph_limits_are_read_in_the_solvers_ranges)
{
    ms_scene *sc = parse_ok("{\"volume\": {\"pressure\": \"dfsph\"}}");
    ms_volume_desc def = ms_volume_desc_default();
    ck_assert_float_eq(sc->volume.max_density_error, def.max_density_error);
    ck_assert_float_eq(sc->volume.max_divergence_error, def.max_divergence_error);
    ck_assert_int_eq(sc->volume.max_density_iterations, def.max_density_iterations);
    ck_assert_int_eq(sc->volume.max_divergence_iterations, def.max_divergence_iterations);
    ms_scene_destroy(sc);
    sc = parse_ok("{\"volume\": {\"pressure\": \"dfsph\", \"max_density_error\": 0.0005,"
                  " \"max_divergence_error\": 0.01, \"max_density_iterations\": 7,"
                  " \"max_divergence_iterations\": 0}}");
    ck_assert_float_eq(sc->volume.max_density_error, 0.0005f);
    ck_assert_float_eq(sc->volume.max_divergence_error, 0.01f);
    ck_assert_int_eq(sc->volume.max_density_iterations, 7);
    ck_assert_int_eq(sc->volume.max_divergence_iterations, 0);
    ms_scene_destroy(sc);
    sc = NULL;
    REFUSED("{\"volume\": {\"pressure\": \"dfsph\", \"max_density_error\": 0}}",
            MS_ERR_INVALID_ARGUMENT,
            "volume.max_density_error is refused: volume: max_density_error 0 is outside (0, 0.1]");
    REFUSED(
        "{\"volume\": {\"pressure\": \"dfsph\", \"max_divergence_error\": 0.2}}",
        MS_ERR_INVALID_ARGUMENT,
        "volume.max_divergence_error is refused: volume: max_divergence_error 0.2 is outside (0, "
        "0.1]");
    REFUSED("{\"volume\": {\"pressure\": \"dfsph\", \"max_density_iterations\": 0}}",
            MS_ERR_INVALID_ARGUMENT,
            "volume.max_density_iterations is refused: volume: max_density_iterations 0 is "
            "outside [1, 10000]");
    REFUSED("{\"volume\": {\"pressure\": \"dfsph\", \"max_divergence_iterations\": 10001}}",
            MS_ERR_INVALID_ARGUMENT, "volume.max_divergence_iterations is refused");
    REFUSED("{\"volume\": {\"pressure\": \"dfsph\", \"max_density_iterations\": 2.5}}",
            MS_ERR_PARSE, "volume.max_density_iterations");
    REFUSED("{\"volume\": {\"max_density_error\": 0.001}}", MS_ERR_INVALID_ARGUMENT,
            "volume.max_density_error is a limit of the \"dfsph\" pressure solver; allowed "
            "only with volume.pressure \"dfsph\"");
    REFUSED("{\"volume\": {\"pressure\": \"tait\", \"max_divergence_iterations\": 3}}",
            MS_ERR_INVALID_ARGUMENT, "volume.max_divergence_iterations is a limit of the");
}
END_TEST

START_TEST(inconsistent_sections_are_refused)
{
    ms_scene *sc = NULL;
    REFUSED("{}", MS_ERR_INVALID_ARGUMENT, "neither a \"volume\" nor a \"surface\"");
    REFUSED("{\"volume\": {}, \"effects\": {\"rain\": {}}}", MS_ERR_INVALID_ARGUMENT,
            "effects.rain needs a \"surface\" section");
    REFUSED("{\"surface\": {}, \"output\": {\"fields\": [\"particles\"]}}", MS_ERR_INVALID_ARGUMENT,
            "\"particles\" needs a \"volume\" section");
    REFUSED("{\"volume\": {}, \"output\": {\"fields\": [\"surface\"]}}", MS_ERR_INVALID_ARGUMENT,
            "\"surface\" needs a \"surface\" section");
    REFUSED("{\"surface\": {}, \"output\": {\"fields\": [\"pressure\"]}}", MS_ERR_INVALID_ARGUMENT,
            "not a field name");
    REFUSED("{\"surface\": {}, \"effects\": {\"boat\": {\"radius\": 0.1}}}",
            MS_ERR_INVALID_ARGUMENT, "effects.boat lacks the required key \"path\"");
    REFUSED("{\"surface\": {}, \"obstacles\": [{\"position\": [0,0,0]}]}", MS_ERR_INVALID_ARGUMENT,
            "obstacles[0] lacks the required key \"shape\"");
    REFUSED("{\"surface\": {}, \"render\": {\"camera\": {\"eye\": [1,1,1], "
            "\"target\": [1,1,1]}}}",
            MS_ERR_INVALID_ARGUMENT,
            "render.camera.target is refused: render: target [1, 1, 1] m equals eye");
    /* the renderer's ranges, named at the scene's keys */
    REFUSED("{\"surface\": {}, \"render\": {\"caustics\": {\"resolution\": 8}}}",
            MS_ERR_INVALID_ARGUMENT,
            ":1:41: render.caustics.resolution is refused: render: caustics_resolution 8 is "
            "outside [16, 4096]");
    REFUSED("{\"surface\": {}, \"render\": {\"caustics\": {\"light\": [0, 0, 0]}}}",
            MS_ERR_INVALID_ARGUMENT,
            "render.caustics.light is refused: render: light_dir [0, 0, 0] is the zero vector");
    REFUSED("{\"surface\": {}, \"render\": {\"camera\": {\"eye\": [0, 2e6, 1]}}}",
            MS_ERR_INVALID_ARGUMENT,
            "render.camera.eye is refused: render: eye[1] 2e+06 m is outside [-1e+06, 1e+06]");
    REFUSED("{\"surface\": {}, \"render\": {\"camera\": {\"fov\": 180}}}", MS_ERR_INVALID_ARGUMENT,
            "render.camera.fov is refused: render: fov 180 degrees is outside [1, 179]");
}
END_TEST

START_TEST(missing_files_are_refused)
{
    ms_scene *sc = NULL;
    MS_ASSERT_REFUSED(ms_scene_load("/nonexistent/scene.json", &sc), MS_ERR_IO,
                      "/nonexistent/scene.json: cannot open");
    REFUSED("{\"surface\": {},\n \"render\": {\"cubemap\": \"/nonexistent/sky\"}}",
            MS_ERR_INVALID_ARGUMENT, "<scene>:2:13: render.cubemap \"/nonexistent/sky\"");
    ck_assert_ptr_nonnull(strstr(ms_last_error(), "\"builtin\""));
    /* what the renderer would refuse (a folder without the six faces, a
     * device, a FIFO) is refused here, so check agrees with run */
    REFUSED("{\"surface\": {}, \"render\": {\"cubemap\": \"/etc\"}}", MS_ERR_INVALID_ARGUMENT,
            "has no px.png");
    REFUSED("{\"surface\": {}, \"render\": {\"cubemap\": \"/dev/zero\"}}", MS_ERR_INVALID_ARGUMENT,
            "is a character device");
    char dir[] = "/tmp/ms_scene_sky_XXXXXX";
    ck_assert_ptr_nonnull(mkdtemp(dir));
    static const char *const faces[6] = {"px", "nx", "py", "ny", "posz", "negz"};
    char path[512], json[700];
    for (int f = 0; f < 6; ++f) {
        snprintf(path, sizeof path, "%s/%s.png", dir, faces[f]);
        FILE *fp = fopen(path, "w");
        ck_assert_ptr_nonnull(fp);
        fclose(fp);
    }
    snprintf(json, sizeof json, "{\"surface\": {}, \"render\": {\"cubemap\": \"%s\"}}", dir);
    sc = parse_ok(json);
    ck_assert_int_eq(ms_scene_has_render(sc), 1);
    ms_scene_destroy(sc);
    for (int f = 0; f < 6; ++f) {
        snprintf(path, sizeof path, "%s/%s.png", dir, faces[f]);
        remove(path);
    }
    rmdir(dir);
    MS_ASSERT_REFUSED(ms_scene_load(NULL, &sc), MS_ERR_INVALID_ARGUMENT, "path");
    MS_ASSERT_REFUSED(ms_scene_parse(NULL, 3, &sc), MS_ERR_INVALID_ARGUMENT, "NULL");
    MS_ASSERT_REFUSED(ms_scene_parse("{}", 2, NULL), MS_ERR_INVALID_ARGUMENT, "NULL");
}
END_TEST

START_TEST(shapes_are_checked_by_their_plugins)
{
    ms_scene *sc = NULL;
    REFUSED("{\"surface\": {}, \"obstacles\": [{\"shape\": \"teapot\"}]}", MS_ERR_INVALID_ARGUMENT,
            "1:32: obstacles[0].shape \"teapot\" is not a shape plugin");
    /* the registry's sentence lists what is available */
    ck_assert_ptr_nonnull(strstr(ms_last_error(), "sphere"));
    REFUSED("{\"surface\": {}, \"obstacles\": [{\"shape\": \"sphere\",\n"
            "  \"params\": {\"radius\": -1}}]}",
            MS_ERR_INVALID_ARGUMENT, "2:3: obstacles[0].params is refused by the sphere plugin");
    sc = parse_ok("{\"surface\": {}, \"obstacles\": [{\"shape\": \"sphere\", "
                  "\"params\": {\"radius\": 0.1}, \"position\": [0.5, 0.5, 0.25]}]}");
    ck_assert_int_eq(sc->nobstacles, 1);
    ck_assert_str_eq(sc->obstacles[0].kind, "sphere");
    ck_assert_ptr_nonnull(strstr(sc->obstacles[0].params_json, "\"radius\":0.1"));
    ck_assert_int_eq(sc->obstacles[0].surface_mask, 1);
    ck_assert_float_eq(sc->obstacles[0].orientation[0], 1.0f); /* unturned */
    ck_assert_float_eq(sc->obstacles[0].orientation[3], 0.0f);
    ck_assert_float_eq(sc->obstacles[0].spin[2], 0.0f);
    ms_scene_destroy(sc);
    sc = parse_ok("{\"surface\": {}, \"obstacles\": [{\"shape\": \"box\", "
                  "\"orientation\": [0, 0, 0, 2], \"spin\": [0, -1.5, 0]}]}");
    ck_assert_float_eq(sc->obstacles[0].orientation[3], 2.0f); /* normalised by the shape */
    ck_assert_float_eq(sc->obstacles[0].spin[1], -1.5f);
    ms_scene_destroy(sc);
}
END_TEST

START_TEST(shader_names_are_checked_against_the_registry)
{
    ms_scene *sc = NULL;
    REFUSED("{\"surface\": {},\n \"render\": {\"shader\": \"lava\"}}", MS_ERR_INVALID_ARGUMENT,
            "<scene>:2:13: render.shader \"lava\" is not a shader plugin");
    /* the sentence lists the shaders there are */
    ck_assert_ptr_nonnull(strstr(ms_last_error(), "water"));
    ck_assert_ptr_nonnull(strstr(ms_last_error(), "milk"));
    REFUSED("{\"surface\": {}, \"render\": {\"shader\": \"sphere\"}}", MS_ERR_INVALID_ARGUMENT,
            "is not a shader plugin");
    sc = parse_ok("{\"surface\": {}, \"render\": {\"shader\": \"milk\", \"width\": 64}}");
    ck_assert_str_eq(sc->render.shader, "milk");
    ck_assert_int_eq(sc->render.width, 64);
    ck_assert_int_eq(sc->render.height, 950);
    ck_assert_int_eq(sc->render.caustics, 0);
    ck_assert_ptr_null(sc->render.shader_params);
    ms_scene_destroy(sc);
}
END_TEST

/* render.shader_params is checked by the shader itself when the scene is
 * read, so `check` refuses what the renderer would, at the key's place;
 * what passes reaches the renderer's desc as JSON text. */
START_TEST(shader_params_are_checked_by_their_shader)
{
    ms_scene *sc = NULL;
    REFUSED("{\"surface\": {},\n \"render\": {\"shader_params\": {\"parallax\": 2}}}",
            MS_ERR_INVALID_ARGUMENT,
            "<scene>:2:13: render.shader_params shader water: parallax 2 is outside [0, 1]");
    REFUSED("{\"surface\": {}, \"render\": {\"shader\": \"milk\", \"shader_params\": "
            "{\"parallax\": 1}}}",
            MS_ERR_INVALID_ARGUMENT, "shader milk: unknown key \"parallax\"");
    REFUSED("{\"surface\": {}, \"render\": {\"shader_params\": [1]}}", MS_ERR_PARSE,
            "render.shader_params");
    sc = parse_ok("{\"surface\": {}, \"render\": {\"shader_params\": {\"parallax\": 1, "
                  "\"ior\": 1.5}}}");
    ck_assert_str_eq(sc->render.shader_params, "{\"ior\":1.5,\"parallax\":1}");
    ms_renderer_desc d = ms_renderer_desc_default();
    ck_assert_int_eq(ms_renderer_desc_from_scene(sc, &d), MS_OK);
    ck_assert_str_eq(d.shader_params, sc->render.shader_params);
    ms_scene_destroy(sc);
}
END_TEST

START_TEST(duplicate_keys_are_refused)
{
    ms_scene *sc = NULL;
    REFUSED("{\"surface\": {}, \"surface\": {}}", MS_ERR_PARSE, "duplicate");
}
END_TEST

/* The position is found by scanning the text: keys with escapes, keys
 * that also occur deeper, arrays of objects, multi-byte characters. */
START_TEST(positions_survive_escapes_nesting_and_utf8)
{
    ms_scene *sc = NULL;
    REFUSED("{\"name\": \"\\u00e9t\\u00e9 \\\"x\\\"\", \"surface\": {\"damping\": 2}}",
            MS_ERR_INVALID_ARGUMENT, "1:45: surface.damping");
    /* "é" is one column, not two bytes */
    REFUSED("{\"name\": \"\xc3\xa9\", \"surface\": {\"damping\": 2}}", MS_ERR_INVALID_ARGUMENT,
            "1:27: surface.damping");
    const char *deep = "{\"surface\": {},\n"
                       " \"obstacles\": [\n"
                       "  {\"shape\": \"sphere\", \"path\": {\"points\": [[0,0,0]]}},\n"
                       "  {\"shape\": \"sphere\", \"path\": {\"points\": [[0,0,0], [1, 2, 3e5]]}}\n"
                       " ]}";
    REFUSED(deep, MS_ERR_INVALID_ARGUMENT, "<scene>:4:59: obstacles[1].path.points[1][2]");
    /* an unknown key whose name needs escapes */
    REFUSED("{\"surface\": {}, \"a\\nb\": 1}", MS_ERR_PARSE, "1:17:");
}
END_TEST

/* A misspelt key or value names the one it is closest to (edit distance,
 * lib/core/spell.c); a key far from every allowed one gets no guess. */
START_TEST(misspelt_key_names_the_closest_allowed_one)
{
    ms_scene *sc = NULL;
    REFUSED("{\"surface\": {}, \"effects\": {\"rian\": {}}}", MS_ERR_PARSE,
            "effects.rian is an unknown key \"rian\" (did you mean \"rain\"?)");
    REFUSED("{\"surface\": {\"wavespeed\": 2}}", MS_ERR_PARSE, "(did you mean \"wave_speed\"?)");
    REFUSED("{\"surface\": {}, \"obstacels\": []}", MS_ERR_PARSE, "(did you mean \"obstacles\"?)");
    REFUSED("{\"surface\": {\"commnet\": \"x\"}}", MS_ERR_PARSE, "(did you mean \"comment\"?)");
    /* an enum value too */
    REFUSED("{\"surface\": {\"boundary\": \"absorbs\"}}", MS_ERR_INVALID_ARGUMENT,
            "\"absorbs\" is unknown (did you mean \"absorb\"?)");
    /* nothing close: the list of allowed keys only */
    REFUSED("{\"surface\": {}, \"colour\": 1}", MS_ERR_PARSE, "colour");
    ck_assert_ptr_null(strstr(ms_last_error(), "did you mean"));
    REFUSED("{\"surface\": {\"boundary\": \"bounce\"}}", MS_ERR_INVALID_ARGUMENT, "bounce");
    ck_assert_ptr_null(strstr(ms_last_error(), "did you mean"));
}
END_TEST

START_TEST(output_section_sets_fields_and_every)
{
    ms_scene *sc =
        parse_ok("{\"volume\": {}, \"surface\": {}, \"output\": {\"fields\": "
                 "[\"combined\", \"surface\", \"volume\", \"particles\"], \"every\": 3}}");
    ck_assert_uint_eq(ms_scene_output_fields(sc),
                      MS_FIELD_COMBINED | MS_FIELD_SURFACE | MS_FIELD_VOLUME | MS_FIELD_PARTICLES);
    ck_assert_int_eq(ms_scene_output_every(sc), 3);
    ck_assert_int_eq(ms_scene_output_deflate(sc), 1); /* the default */
    ms_scene_destroy(sc);
    sc = parse_ok("{\"surface\": {}, \"output\": {\"deflate\": 0}}");
    ck_assert_int_eq(ms_scene_output_deflate(sc), 0);
    ms_scene_destroy(sc);
}
END_TEST

START_TEST(motion_follows_polyline_at_speed)
{
    float pts[] = {0, 0, 1, 0, 1, 1};
    ms_scene_motion p = {.npoints = 3, .dim = 2, .points = pts, .speed = 0.5f, .start = 1};
    float pos[2], vel[2];
    ms_scene_motion_eval(&p, 0.5, pos, vel); /* before start: waits at the first point */
    ck_assert_float_eq(pos[0], 0);
    ck_assert_float_eq(vel[0], 0);
    ms_scene_motion_eval(&p, 2.0, pos, vel); /* 0.5 m along the first segment */
    ck_assert_float_eq_tol(pos[0], 0.5f, 1e-6f);
    ck_assert_float_eq_tol(vel[0], 0.5f, 1e-6f);
    ms_scene_motion_eval(&p, 4.0, pos, vel); /* 1.5 m: half way up the second */
    ck_assert_float_eq_tol(pos[0], 1.0f, 1e-6f);
    ck_assert_float_eq_tol(pos[1], 0.5f, 1e-6f);
    ck_assert_float_eq_tol(vel[1], 0.5f, 1e-6f);
    ms_scene_motion_eval(&p, 100.0, pos, vel); /* stops at the end */
    ck_assert_float_eq(pos[1], 1);
    ck_assert_float_eq(vel[1], 0);
    p.loop = 1; /* closed: 2 + sqrt(2) m long */
    ms_scene_motion_eval(&p, 1 + (2 + sqrt(2.0) + 0.25) / 0.5, pos, vel);
    ck_assert_float_eq_tol(pos[0], 0.25f, 1e-5f);
    ck_assert_float_eq_tol(pos[1], 0, 1e-5f);
}
END_TEST

/* Mutated scene texts (byte flips, cuts, inserted tokens) never crash and
 * fail only with the documented statuses. Fork mode turns a crash into a
 * failure of this case. */
START_TEST(mutated_scenes_never_crash)
{
    FILE *f = fopen("data/scenes/fig10.json", "rb");
    ck_assert_ptr_nonnull(f);
    static char base[65536];
    size_t n = fread(base, 1, sizeof base - 1, f);
    fclose(f);
    static const char *const tokens[] = {"-1",          "1e308", "\"x\"", "[]",     "{}",
                                         "null",        "true",  "0",     "1e-300", "[[",
                                         "\"\\u0000\"", ",",     ":"};
    ms_rng r;
    ms_rng_seed(&r, 42);
    static char buf[70000];
    int ok = 0;
    for (int it = 0; it < 3000; ++it) {
        memcpy(buf, base, n);
        size_t len = n;
        int kind = (int)(ms_rng_u32(&r) % 3);
        size_t at = ms_rng_u32(&r) % n;
        if (kind == 0) {
            buf[at] = (char)ms_rng_u32(&r);
        } else if (kind == 1) {
            len = at;
        } else {
            const char *t = tokens[ms_rng_u32(&r) % (sizeof tokens / sizeof *tokens)];
            size_t tl = strlen(t);
            memmove(buf + at + tl, buf + at, n - at);
            memcpy(buf + at, t, tl);
            len = n + tl;
        }
        ms_scene *sc = NULL;
        ms_status st = ms_scene_parse(buf, len, &sc);
        ck_assert_msg(st == MS_OK || st == MS_ERR_PARSE || st == MS_ERR_INVALID_ARGUMENT, "%s: %s",
                      ms_status_name(st), ms_last_error());
        if (st == MS_OK) {
            ++ok;
            ms_scene_destroy(sc);
        } else {
            ck_assert_ptr_null(sc);
            ck_assert_ptr_nonnull(strstr(ms_last_error(), "<scene>:"));
        }
    }
    ck_assert_int_gt(ok, 0);
}
END_TEST

/* The scene's keys set the parts' real descs: what ms_scene_*_desc give
 * is the part's default where the file is silent, the file's value where
 * it speaks, and it is what the sim is made from. */
START_TEST(scene_gives_the_parts_descs)
{
    ms_scene *sc = parse_ok("{\"domain\": {\"max\": [2, 1, 0.5]},"
                            " \"volume\": {\"spacing\": 0.05, \"courant\": 0.3,"
                            "   \"fill\": [{\"min\": [0,0,0], \"max\": [1,1,0.2]}]},"
                            " \"surface\": {\"cells\": [200, 100], \"damping\": 0.5},"
                            " \"coupling\": {\"n_time\": 3}, \"threads\": 1}");
    ms_volume_desc v = ms_volume_desc_default(), def = ms_volume_desc_default();
    ck_assert_int_eq(ms_scene_volume_desc(sc, &v), MS_OK);
    ck_assert_float_eq(v.spacing, 0.05f);
    ck_assert_float_eq(v.courant, 0.3f);
    ck_assert_float_eq(v.rest_density, def.rest_density);
    ck_assert_float_eq(v.gas_constant, def.gas_constant);
    ck_assert_float_eq(v.domain_max[0], 2.0f);
    ck_assert_int_eq(ms_volume_desc_check(&v), MS_OK);
    ms_surface_desc s = ms_surface_desc_default();
    ck_assert_int_eq(ms_scene_surface_desc(sc, &s), MS_OK);
    ck_assert_int_eq(s.nx, 200);
    ck_assert_int_eq(s.ny, 100);
    ck_assert_float_eq_tol(s.dx, 0.01f, 1e-7f);
    ck_assert_float_eq(s.damping, 0.5f);
    ck_assert_float_eq(s.wave_speed, ms_surface_desc_default().wave_speed);
    ms_sim_desc d = ms_sim_desc_default();
    ck_assert_int_eq(ms_scene_sim_desc(sc, &d), MS_OK);
    ck_assert_int_eq(d.surface_substeps, 3);
    ck_assert_int_eq(d.threads, 1);
    ck_assert_ptr_nonnull(d.volume);
    ck_assert_float_eq(d.volume->spacing, 0.05f);
    ck_assert_int_eq(d.surface->nx, 200);
    /* an engine makes the same parts from them */
    ms_sim *sim = NULL;
    ck_assert_int_eq(ms_sim_create(&d, &sim), MS_OK);
    ms_sim_info in = ms_sim_info_init();
    ms_sim_get_info(sim, &in);
    ck_assert_float_eq(in.spacing, 0.05f);
    ck_assert_int_eq(in.surface_nx, 200);
    ms_sim_destroy(sim);
    /* the renderer's: its pool is the domain, the still water the level */
    ms_renderer_desc rd = ms_renderer_desc_default();
    ck_assert_int_eq(ms_scene_renderer_desc(sc, &rd), MS_OK);
    ck_assert_float_eq(rd.pool_max[0], 2.0f);
    ck_assert_float_eq_tol(rd.water_level, sc->level, 1e-7f);
    ck_assert_int_eq(rd.caustics, 0); /* no render section: no caustics */
    ck_assert_int_eq(ms_renderer_desc_check(&rd), MS_OK);
    ms_scene_destroy(sc);
    /* a section the scene lacks */
    sc = parse_ok("{\"surface\": {}}");
    MS_ASSERT_REFUSED(ms_scene_volume_desc(sc, &v), MS_ERR_STATE, "has no \"volume\" section");
    ms_scene_destroy(sc);
}
END_TEST

/* One rule for a desc field the chosen law does not read: range-checked
 * all the same, so -5 m/s is refused under the ideal gas as NaN is. */
START_TEST(unused_desc_fields_are_range_checked)
{
    ms_volume_desc v = ms_volume_desc_default();
    ck_assert_int_eq(v.pressure, MS_PRESSURE_IDEAL_GAS);
    v.sound_speed = -5;
    MS_ASSERT_REFUSED(ms_volume_desc_check(&v), MS_ERR_INVALID_ARGUMENT, "sound_speed -5 m/s");
    v.sound_speed = NAN;
    MS_ASSERT_REFUSED(ms_volume_desc_check(&v), MS_ERR_INVALID_ARGUMENT, "sound_speed nan");
    v = ms_volume_desc_default();
    v.pressure = MS_PRESSURE_TAIT;
    v.gas_constant = -1;
    MS_ASSERT_REFUSED(ms_volume_desc_check(&v), MS_ERR_INVALID_ARGUMENT, "gas_constant -1");
    ms_scene *sc = NULL;
    REFUSED("{\"volume\": {\"sound_speed\": -5}}", MS_ERR_INVALID_ARGUMENT,
            "volume.sound_speed is refused: volume: sound_speed -5 m/s");
}
END_TEST

/* A domain too small for the wave grid is named as the domain, not
 * through an effect it spoils (the rain's radius range came out inverted). */
START_TEST(tiny_domain_is_named_as_the_domain)
{
    ms_scene *sc = NULL;
    REFUSED("{\"domain\": {\"max\": [1e-30, 1e-30, 0.2]}, \"surface\": {\"cells\": [300, 300]},"
            " \"effects\": {\"rain\": {\"rate\": 10}}}",
            MS_ERR_INVALID_ARGUMENT, "domain.max is refused: surface: dx 3.33333e-33 m is below");
}
END_TEST

static Suite *scene_suite(void)
{
    Suite *s = suite_create("scene");
    TCase *tc = tcase_create("parse");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, minimal_scene_gets_documented_defaults);
    tcase_add_test(tc, scene_gives_the_parts_descs);
    tcase_add_test(tc, unused_desc_fields_are_range_checked);
    tcase_add_test(tc, tiny_domain_is_named_as_the_domain);
    tcase_add_test(tc, volume_level_is_the_fill_spread_over_the_domain);
    tcase_add_test(tc, dfsph_limits_are_read_in_the_solvers_ranges);
    tcase_add_test(tc, every_shipped_scene_loads);
    tcase_add_test(tc, name_defaults_to_the_file_name);
    tcase_add_test(tc, syntax_error_names_line_and_column);
    tcase_add_test(tc, unknown_key_names_place_and_allowed_keys);
    tcase_add_test(tc, misspelt_key_names_the_closest_allowed_one);
    tcase_add_test(tc, wrong_type_names_key_and_allowed_type);
    tcase_add_test(tc, out_of_range_names_value_and_range);
    tcase_add_test(tc, inconsistent_sections_are_refused);
    tcase_add_test(tc, missing_files_are_refused);
    tcase_add_test(tc, shapes_are_checked_by_their_plugins);
    tcase_add_test(tc, shader_names_are_checked_against_the_registry);
    tcase_add_test(tc, shader_params_are_checked_by_their_shader);
    tcase_add_test(tc, duplicate_keys_are_refused);
    tcase_add_test(tc, positions_survive_escapes_nesting_and_utf8);
    tcase_add_test(tc, output_section_sets_fields_and_every);
    tcase_add_test(tc, motion_follows_polyline_at_speed);
    tcase_add_test(tc, mutated_scenes_never_crash);
    suite_add_tcase(s, tc);
    return s;
}

int main(void)
{
    return ms_test_run(scene_suite());
}
