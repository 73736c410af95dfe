/* The camera matrices of the GL side: look-at views, a view along any
 * basis (the cube map faces), the perspective projection. Column-major, as
 * glLoadMatrixf takes them. */
#include <math.h>
#include <string.h>

#include "render/gl_internal.h"

static void normalize3(float v[3])
{
    float l = sqrtf(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    if (l > 0)
        v[0] /= l, v[1] /= l, v[2] /= l;
}

static void cross3(const float a[3], const float b[3], float out[3])
{
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

void ms_mat4_basis_view(const float eye[3], const float right[3], const float up[3],
                        const float forward[3], float m[16])
{
    /* rows: right, up, -forward; then the eye moved to the origin */
    memset(m, 0, 16 * sizeof *m);
    for (int k = 0; k < 3; ++k) {
        m[4 * k + 0] = right[k];
        m[4 * k + 1] = up[k];
        m[4 * k + 2] = -forward[k];
    }
    m[12] = -(right[0] * eye[0] + right[1] * eye[1] + right[2] * eye[2]);
    m[13] = -(up[0] * eye[0] + up[1] * eye[1] + up[2] * eye[2]);
    m[14] = forward[0] * eye[0] + forward[1] * eye[1] + forward[2] * eye[2];
    m[15] = 1;
}

void ms_mat4_look_at(const float eye[3], const float target[3], const float up[3], float m[16])
{
    float f[3] = {target[0] - eye[0], target[1] - eye[1], target[2] - eye[2]}, s[3], u[3];
    normalize3(f);
    cross3(f, up, s);
    normalize3(s);
    cross3(s, f, u);
    ms_mat4_basis_view(eye, s, u, f, m);
}

void ms_mat4_perspective(float fov_y_deg, float aspect, float znear, float zfar, float m[16])
{
    float f = 1.0f / tanf(0.5f * fov_y_deg * 3.14159265358979f / 180.0f);
    memset(m, 0, 16 * sizeof *m);
    m[0] = f / aspect;
    m[5] = f;
    m[10] = (zfar + znear) / (znear - zfar);
    m[11] = -1;
    m[14] = 2 * zfar * znear / (znear - zfar);
}
