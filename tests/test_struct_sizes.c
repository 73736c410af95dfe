/* Struct sizes (core.h): every desc and every struct the library fills
 * leads with uint32_t size. Descs with size 0 or a size the library does
 * not know are refused, a smaller known size is read over the defaults;
 * structs the library fills are written up to their size only, and not at
 * all when the size is 0 or unknown. */
#include <check.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "core/core_internal.h"
#include "modesplit/modesplit.h"
#include "modesplit/plugin.h"
#include "support.h"

/* A struct as version 1 shipped it, and the same struct grown by one field
 * in version 2 (a double, so the alignment grows too). */
typedef struct v1 {
    uint32_t size;
    float a;
    int b;
} v1;
typedef struct v2 {
    uint32_t size;
    float a;
    int b;
    double c;
} v2;
#define V2_SIZES MS_STRUCT_SIZES(v2, b, "v2_default()")

static v2 v2_default(void)
{
    v2 d = {(uint32_t)sizeof(v2), 1.0f, 2, 3.0};
    return d;
}

START_TEST(an_older_smaller_desc_keeps_the_defaults_of_the_fields_it_lacks)
{
    v1 old = {(uint32_t)sizeof(v1), 10.0f, 20};
    v2 d = v2_default();
    ck_assert_int_eq(ms_struct_in(&old, &d, V2_SIZES, "test"), MS_OK);
    ck_assert(d.a == 10.0f);
    ck_assert_int_eq(d.b, 20);
    ck_assert(d.c == 3.0); /* not in v1: the default */
    ck_assert_uint_eq(d.size, sizeof(v2));
    /* a current caller: every field is read */
    v2 cur = {(uint32_t)sizeof(v2), 5.0f, 6, 7.0};
    d = v2_default();
    ck_assert_int_eq(ms_struct_in(&cur, &d, V2_SIZES, "test"), MS_OK);
    ck_assert(d.c == 7.0);
}
END_TEST

START_TEST(a_desc_of_size_zero_or_unknown_is_refused)
{
    v2 d = v2_default();
    v2 bad = v2_default();
    bad.size = 0;
    MS_ASSERT_REFUSED(ms_struct_in(&bad, &d, V2_SIZES, "test"), MS_ERR_INVALID_ARGUMENT,
                      "start from v2_default()");
    bad.size = (uint32_t)sizeof(v2) + 8; /* a newer caller than the library */
    MS_ASSERT_REFUSED(ms_struct_in(&bad, &d, V2_SIZES, "test"), MS_ERR_INVALID_ARGUMENT, "newer");
    bad.size = 8; /* smaller than the first released layout */
    MS_ASSERT_REFUSED(ms_struct_in(&bad, &d, V2_SIZES, "test"), MS_ERR_INVALID_ARGUMENT,
                      "not a size");
    bad.size = 14; /* inside the first layout's padding but not a multiple of 4 */
    MS_ASSERT_REFUSED(ms_struct_in(&bad, &d, V2_SIZES, "test"), MS_ERR_INVALID_ARGUMENT,
                      "not a size");
    MS_ASSERT_REFUSED(ms_struct_in(NULL, &d, V2_SIZES, "test"), MS_ERR_INVALID_ARGUMENT,
                      "desc is NULL");
    ck_assert(d.a == 1.0f && d.b == 2 && d.c == 3.0); /* nothing read */
}
END_TEST

START_TEST(a_filled_struct_is_written_up_to_its_size_only)
{
    unsigned char buf[sizeof(v2) + 8];
    memset(buf, 0xab, sizeof buf);
    uint32_t size = (uint32_t)sizeof(v1);
    memcpy(buf, &size, sizeof size);
    v2 full = v2_default();
    size_t n = ms_struct_out(buf, V2_SIZES, "test");
    ck_assert_uint_eq(n, sizeof(v1));
    ms_struct_write(buf, &full, n);
    v1 got;
    memcpy(&got, buf, sizeof got);
    ck_assert_uint_eq(got.size, sizeof(v1)); /* the caller's size stays */
    ck_assert(got.a == 1.0f && got.b == 2);
    for (size_t i = sizeof(v1); i < sizeof buf; ++i)
        ck_assert_uint_eq(buf[i], 0xab);
}
END_TEST

START_TEST(every_desc_default_sets_its_size)
{
    ck_assert_uint_eq(ms_surface_desc_default().size, sizeof(ms_surface_desc));
    ck_assert_uint_eq(ms_volume_desc_default().size, sizeof(ms_volume_desc));
    ck_assert_uint_eq(ms_sim_desc_default().size, sizeof(ms_sim_desc));
    ck_assert_uint_eq(ms_renderer_desc_default().size, sizeof(ms_renderer_desc));
    ck_assert_uint_eq(ms_preview_desc_default().size, sizeof(ms_preview_desc));
    ck_assert_uint_eq(ms_rain_default().size, sizeof(ms_rain));
    ck_assert_uint_eq(ms_disturber_desc_default().size, sizeof(ms_disturber_desc));
    ck_assert_uint_eq(ms_stats_init().size, sizeof(ms_stats));
    ck_assert_uint_eq(ms_surface_info_init().size, sizeof(ms_surface_info));
    ck_assert_uint_eq(ms_volume_info_init().size, sizeof(ms_volume_info));
    ck_assert_uint_eq(ms_sim_info_init().size, sizeof(ms_sim_info));
    ck_assert_uint_eq(ms_render_stats_init().size, sizeof(ms_render_stats));
    ck_assert_uint_eq(ms_plugin_description_init().size, sizeof(ms_plugin_description));
    /* a desc read back from a handle carries the current size */
    ms_surface_desc sd = ms_surface_desc_default();
    ms_surface *s = NULL;
    ck_assert_int_eq(ms_surface_create(&sd, &s), MS_OK);
    ck_assert_uint_eq(ms_surface_get_desc(s).size, sizeof(ms_surface_desc));
    ms_surface_destroy(s);
}
END_TEST

START_TEST(creates_refuse_a_desc_of_size_zero)
{
    ms_surface *s = NULL;
    ms_volume *v = NULL;
    ms_sim *sim = NULL;
    ms_renderer *r = NULL;
    ms_surface_desc sd = ms_surface_desc_default();
    sd.size = 0;
    MS_ASSERT_REFUSED(ms_surface_create(&sd, &s), MS_ERR_INVALID_ARGUMENT,
                      "start from ms_surface_desc_default()");
    ck_assert_ptr_null(s);
    ms_volume_desc vd = ms_volume_desc_default();
    vd.size = 0;
    MS_ASSERT_REFUSED(ms_volume_create(&vd, &v), MS_ERR_INVALID_ARGUMENT,
                      "start from ms_volume_desc_default()");
    ck_assert_ptr_null(v);
    ms_sim_desc d = ms_sim_desc_default();
    d.size = 0;
    MS_ASSERT_REFUSED(ms_sim_create(&d, &sim), MS_ERR_INVALID_ARGUMENT,
                      "start from ms_sim_desc_default()");
    /* the nested descs are read by their own sizes */
    d = ms_sim_desc_default();
    vd = ms_volume_desc_default();
    sd = ms_surface_desc_default();
    d.volume = &vd;
    vd.size = 0;
    MS_ASSERT_REFUSED(ms_sim_create(&d, &sim), MS_ERR_INVALID_ARGUMENT, "ms_volume_desc.size");
    d.volume = NULL;
    d.surface = &sd;
    sd.size = 0;
    MS_ASSERT_REFUSED(ms_sim_create(&d, &sim), MS_ERR_INVALID_ARGUMENT, "ms_surface_desc.size");
    ck_assert_ptr_null(sim);
    ms_renderer_desc rd = ms_renderer_desc_default();
    rd.size = 0;
    MS_ASSERT_REFUSED(ms_renderer_create_desc(&rd, &r), MS_ERR_INVALID_ARGUMENT,
                      "start from ms_renderer_desc_default()");
    ck_assert_ptr_null(r);
    float h[4] = {0, 0, 0, 0};
    unsigned char rgb[12];
    ms_preview_desc pd = ms_preview_desc_default();
    pd.size = 0;
    MS_ASSERT_REFUSED(ms_field_shade(h, 2, 2, &pd, rgb, sizeof rgb), MS_ERR_INVALID_ARGUMENT,
                      "start from ms_preview_desc_default()");

    sd = ms_surface_desc_default();
    ck_assert_int_eq(ms_surface_create(&sd, &s), MS_OK);
    ms_rain rain = ms_rain_default();
    rain.rate = 10;
    rain.size = 0;
    MS_ASSERT_REFUSED(ms_surface_set_rain(s, &rain), MS_ERR_INVALID_ARGUMENT,
                      "start from ms_rain_default()");
    ms_disturber_desc dd = ms_disturber_desc_default();
    dd.x = dd.y = 1.0f;
    dd.size = 0;
    int id = -1;
    MS_ASSERT_REFUSED(ms_surface_add_disturber(s, &dd, &id), MS_ERR_INVALID_ARGUMENT,
                      "start from ms_disturber_desc_default()");
    dd.size = (uint32_t)sizeof dd;
    ck_assert_int_eq(ms_surface_add_disturber(s, &dd, &id), MS_OK);
    rain.size = (uint32_t)sizeof rain;
    ck_assert_int_eq(ms_surface_set_rain(s, &rain), MS_OK);
    ms_surface_destroy(s);
}
END_TEST

START_TEST(creates_refuse_a_size_they_do_not_know)
{
    ms_surface *s = NULL;
    ms_volume *v = NULL;
    ms_surface_desc sd = ms_surface_desc_default();
    sd.size += 8;
    MS_ASSERT_REFUSED(ms_surface_create(&sd, &s), MS_ERR_INVALID_ARGUMENT,
                      "header newer than the library");
    sd.size = 12;
    MS_ASSERT_REFUSED(ms_surface_create(&sd, &s), MS_ERR_INVALID_ARGUMENT, "not a size");
    ms_volume_desc vd = ms_volume_desc_default();
    vd.size = 4;
    MS_ASSERT_REFUSED(ms_volume_create(&vd, &v), MS_ERR_INVALID_ARGUMENT, "ms_volume_desc.size 4");
    /* the 0.1 layout's end without the tail padding of an 8-byte-aligned
     * compiler is the size a 4-byte-aligned compiler gives: known */
    sd = ms_surface_desc_default();
    sd.size = (uint32_t)(offsetof(ms_surface_desc, max_substeps) + sizeof(int));
    ck_assert_int_eq(ms_surface_create(&sd, &s), MS_OK);
    ck_assert_uint_eq(ms_surface_get_desc(s).size, sizeof(ms_surface_desc));
    ms_surface_destroy(s);
}
END_TEST

START_TEST(getters_write_nothing_for_size_zero_or_unknown)
{
    ms_surface_desc sd = ms_surface_desc_default();
    ms_sim_desc d = ms_sim_desc_default();
    d.surface = &sd;
    ms_sim *sim = NULL;
    ck_assert_int_eq(ms_sim_create(&d, &sim), MS_OK);
    ck_assert_int_eq(ms_sim_step(sim, 1.0f / 60), MS_OK);

    ms_stats st;
    memset(&st, 0xab, sizeof st);
    st.size = 0;
    ms_sim_get_stats(sim, &st);
    ck_assert_uint_eq(st.size, 0);
    ck_assert_uint_eq(((unsigned char *)&st)[sizeof st - 1], 0xab);
    ck_assert_ptr_nonnull(strstr(ms_last_error(), "ms_stats.size is 0"));
    st.size = 6;
    ms_sim_get_stats(sim, &st);
    ck_assert_uint_eq(((unsigned char *)&st)[offsetof(ms_stats, frames)], 0xab);
    ck_assert_ptr_nonnull(strstr(ms_last_error(), "not a size"));
    st = ms_stats_init();
    ms_sim_get_stats(sim, &st);
    ck_assert_int_eq(st.frames, 1);

    ms_sim_info info;
    memset(&info, 0xab, sizeof info);
    info.size = 0;
    ms_sim_get_info(sim, &info);
    ck_assert_uint_eq(((unsigned char *)&info)[offsetof(ms_sim_info, has_surface)], 0xab);
    info = ms_sim_info_init();
    ms_sim_get_info(sim, &info);
    ck_assert_int_eq(info.has_surface, 1);

    ms_surface_info si;
    memset(&si, 0xab, sizeof si);
    si.size = 0;
    ms_surface_get_info(ms_sim_surface(sim), &si);
    ck_assert_uint_eq(((unsigned char *)&si)[offsetof(ms_surface_info, substeps)], 0xab);
    si = ms_surface_info_init();
    ms_surface_get_info(ms_sim_surface(sim), &si);
    ck_assert(si.max_dt > 0);
    ms_sim_destroy(sim);

    ms_volume_desc vd = ms_volume_desc_default();
    ms_volume *v = NULL;
    ck_assert_int_eq(ms_volume_create(&vd, &v), MS_OK);
    ms_volume_info vi;
    memset(&vi, 0xab, sizeof vi);
    vi.size = 0;
    ms_volume_get_info(v, &vi);
    ck_assert_uint_eq(((unsigned char *)&vi)[offsetof(ms_volume_info, count)], 0xab);
    vi = ms_volume_info_init();
    ms_volume_get_info(v, &vi);
    ck_assert(vi.particle_mass > 0);
    ms_volume_destroy(v);

    ms_render_stats rs;
    memset(&rs, 0xab, sizeof rs);
    rs.size = 0;
    ms_renderer_get_stats(NULL, &rs);
    ck_assert_uint_eq(((unsigned char *)&rs)[offsetof(ms_render_stats, frames)], 0xab);
    rs = ms_render_stats_init();
    rs.frames = 5;
    ms_renderer_get_stats(NULL, &rs); /* no renderer: zeros */
    ck_assert_int_eq(rs.frames, 0);
}
END_TEST

START_TEST(status_getters_refuse_size_zero)
{
    ms_plugin_description pd = ms_plugin_description_init();
    pd.size = 0;
    if (ms_plugin_count() < 1)
        MS_SKIP("no plugins were found on the search path");
    MS_ASSERT_REFUSED(ms_plugin_describe(0, &pd), MS_ERR_INVALID_ARGUMENT,
                      "ms_plugin_description.size is 0");
    pd = ms_plugin_description_init();
    ck_assert_int_eq(ms_plugin_describe(0, &pd), MS_OK);
    ck_assert_ptr_nonnull(pd.name);

    const char *text = "{\"name\": \"t\", \"surface\": {}}";
    ms_scene *sc = NULL;
    ck_assert_int_eq(ms_scene_parse(text, strlen(text), &sc), MS_OK);
    ms_renderer_desc rd;
    memset(&rd, 0, sizeof rd);
    MS_ASSERT_REFUSED(ms_renderer_desc_from_scene(sc, &rd), MS_ERR_INVALID_ARGUMENT,
                      "ms_renderer_desc.size is 0");
    ck_assert_ptr_null(rd.shader);
    rd = ms_renderer_desc_default();
    ck_assert_int_eq(ms_renderer_desc_from_scene(sc, &rd), MS_OK);
    ck_assert_ptr_nonnull(rd.shader);
    ms_scene_destroy(sc);
}
END_TEST

static Suite *struct_sizes_suite(void)
{
    Suite *s = suite_create("struct_sizes");
    TCase *tc = tcase_create("struct_sizes");
    tcase_set_timeout(tc, 30);
    tcase_add_test(tc, an_older_smaller_desc_keeps_the_defaults_of_the_fields_it_lacks);
    tcase_add_test(tc, a_desc_of_size_zero_or_unknown_is_refused);
    tcase_add_test(tc, a_filled_struct_is_written_up_to_its_size_only);
    tcase_add_test(tc, every_desc_default_sets_its_size);
    tcase_add_test(tc, creates_refuse_a_desc_of_size_zero);
    tcase_add_test(tc, creates_refuse_a_size_they_do_not_know);
    tcase_add_test(tc, getters_write_nothing_for_size_zero_or_unknown);
    tcase_add_test(tc, status_getters_refuse_size_zero);
    suite_add_tcase(s, tc);
    return s;
}

int main(void)
{
    return ms_test_run(struct_sizes_suite());
}
