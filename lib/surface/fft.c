/* Mixed-radix FFT and the DCT-II built on it (fft.h). The recursion is
 * the classic decimation in time over the factors of n (as kissfft): each
 * level splits the sequence into p interleaved subsequences of length
 * m = n / p, transforms them, and joins them with a radix-p butterfly
 * (4, 2 and 5 written out, other primes by the definition). */
#include <math.h>
#include <string.h>

#include "core/core_internal.h"
#include "surface/fft.h"

#define MAX_FACTORS 32

struct ms_fft {
    int n;
    int factors[2 * MAX_FACTORS]; /* (p, m) pairs, p the radix of each level */
    int maxp;                     /* largest radix: the generic butterfly's scratch */
    ms_cpx *tw;                   /* e^{-2 pi i j/n}, j < n */
    ms_cpx *dtw;                  /* e^{-i pi k/(2n)}, k < n (the DCT's shift) */
    ms_cpx *buf, *buf2, *scratch; /* n, n, maxp */
};

static void factorise(ms_fft *p)
{
    int n = p->n, f = 4, k = 0;
    p->maxp = 1;
    while (n > 1) {
        while (n % f)
            f = f == 4 ? 2 : f == 2 ? 3 : (f * f > n ? n : f + 2);
        n /= f;
        p->factors[k++] = f;
        p->factors[k++] = n;
        p->maxp = MS_MAX(p->maxp, f);
    }
    if (k == 0) { /* n = 1 */
        p->factors[k++] = 1;
        p->factors[k++] = 1;
    }
}

ms_fft *ms_fft_create(int n)
{
    if (n < 1)
        return NULL;
    ms_fft *p = ms_alloc_array(1, sizeof *p);
    if (!p)
        return NULL;
    p->n = n;
    factorise(p);
    p->tw = ms_alloc_array((size_t)n, sizeof *p->tw);
    p->dtw = ms_alloc_array((size_t)n, sizeof *p->dtw);
    p->buf = ms_alloc_array((size_t)n, sizeof *p->buf);
    p->buf2 = ms_alloc_array((size_t)n, sizeof *p->buf2);
    p->scratch = ms_alloc_array((size_t)p->maxp, sizeof *p->scratch);
    if (!p->tw || !p->dtw || !p->buf || !p->buf2 || !p->scratch) {
        ms_fft_destroy(p);
        return NULL;
    }
    const double pi = 3.14159265358979323846;
    for (int j = 0; j < n; ++j) {
        p->tw[j].re = (float)cos(-2 * pi * j / n);
        p->tw[j].im = (float)sin(-2 * pi * j / n);
        p->dtw[j].re = (float)cos(-pi * j / (2.0 * n));
        p->dtw[j].im = (float)sin(-pi * j / (2.0 * n));
    }
    return p;
}

void ms_fft_destroy(ms_fft *p)
{
    if (!p)
        return;
    ms_free(p->tw);
    ms_free(p->dtw);
    ms_free(p->buf);
    ms_free(p->buf2);
    ms_free(p->scratch);
    ms_free(p);
}

size_t ms_fft_bytes(const ms_fft *p)
{
    return sizeof *p + (4 * (size_t)p->n + (size_t)p->maxp) * sizeof(ms_cpx);
}

static inline ms_cpx cmul(ms_cpx a, ms_cpx b)
{
    ms_cpx r = {a.re * b.re - a.im * b.im, a.re * b.im + a.im * b.re};
    return r;
}

static void bfly2(ms_cpx *out, int fstride, const ms_fft *p, int m)
{
    ms_cpx *o2 = out + m;
    for (int k = 0; k < m; ++k) {
        const ms_cpx t = cmul(o2[k], p->tw[(size_t)k * fstride]);
        o2[k].re = out[k].re - t.re;
        o2[k].im = out[k].im - t.im;
        out[k].re += t.re;
        out[k].im += t.im;
    }
}

static void bfly4(ms_cpx *out, int fstride, const ms_fft *p, int m)
{
    for (int k = 0; k < m; ++k) {
        const ms_cpx s0 = cmul(out[k + m], p->tw[(size_t)k * fstride]);
        const ms_cpx s1 = cmul(out[k + 2 * m], p->tw[(size_t)2 * k * fstride]);
        const ms_cpx s2 = cmul(out[k + 3 * m], p->tw[(size_t)3 * k * fstride]);
        const ms_cpx f0 = out[k];
        const ms_cpx s5 = {f0.re - s1.re, f0.im - s1.im}, a = {f0.re + s1.re, f0.im + s1.im};
        const ms_cpx s3 = {s0.re + s2.re, s0.im + s2.im}, s4 = {s0.re - s2.re, s0.im - s2.im};
        out[k + 2 * m].re = a.re - s3.re;
        out[k + 2 * m].im = a.im - s3.im;
        out[k].re = a.re + s3.re;
        out[k].im = a.im + s3.im;
        out[k + m].re = s5.re + s4.im;
        out[k + m].im = s5.im - s4.re;
        out[k + 3 * m].re = s5.re - s4.im;
        out[k + 3 * m].im = s5.im + s4.re;
    }
}

static void bfly5(ms_cpx *out, int fstride, const ms_fft *p, int m)
{
    const ms_cpx ya = p->tw[(size_t)fstride * m], yb = p->tw[(size_t)fstride * 2 * m];
    ms_cpx *f0 = out, *f1 = out + m, *f2 = out + 2 * m, *f3 = out + 3 * m, *f4 = out + 4 * m;
    for (int u = 0; u < m; ++u) {
        const ms_cpx s0 = f0[u];
        const ms_cpx s1 = cmul(f1[u], p->tw[(size_t)u * fstride]);
        const ms_cpx s2 = cmul(f2[u], p->tw[(size_t)2 * u * fstride]);
        const ms_cpx s3 = cmul(f3[u], p->tw[(size_t)3 * u * fstride]);
        const ms_cpx s4 = cmul(f4[u], p->tw[(size_t)4 * u * fstride]);
        const ms_cpx s7 = {s1.re + s4.re, s1.im + s4.im}, s10 = {s1.re - s4.re, s1.im - s4.im};
        const ms_cpx s8 = {s2.re + s3.re, s2.im + s3.im}, s9 = {s2.re - s3.re, s2.im - s3.im};
        f0[u].re = s0.re + s7.re + s8.re;
        f0[u].im = s0.im + s7.im + s8.im;
        const ms_cpx s5 = {s0.re + s7.re * ya.re + s8.re * yb.re,
                           s0.im + s7.im * ya.re + s8.im * yb.re};
        const ms_cpx s6 = {s10.im * ya.im + s9.im * yb.im, -s10.re * ya.im - s9.re * yb.im};
        f1[u].re = s5.re - s6.re;
        f1[u].im = s5.im - s6.im;
        f4[u].re = s5.re + s6.re;
        f4[u].im = s5.im + s6.im;
        const ms_cpx s11 = {s0.re + s7.re * yb.re + s8.re * ya.re,
                            s0.im + s7.im * yb.re + s8.im * ya.re};
        const ms_cpx s12 = {-s10.im * yb.im + s9.im * ya.im, s10.re * yb.im - s9.re * ya.im};
        f2[u].re = s11.re + s12.re;
        f2[u].im = s11.im + s12.im;
        f3[u].re = s11.re - s12.re;
        f3[u].im = s11.im - s12.im;
    }
}

/* Radix q by the definition: q twiddled inputs summed into each of q outputs. */
static void bfly_generic(ms_cpx *out, int fstride, ms_fft *p, int m, int q)
{
    ms_cpx *s = p->scratch;
    const int n = p->n;
    for (int u = 0; u < m; ++u) {
        for (int q1 = 0, k = u; q1 < q; ++q1, k += m)
            s[q1] = out[k];
        for (int q1 = 0, k = u; q1 < q; ++q1, k += m) {
            int idx = 0;
            ms_cpx acc = s[0];
            for (int j = 1; j < q; ++j) {
                idx += fstride * k;
                if (idx >= n)
                    idx %= n;
                const ms_cpx t = cmul(s[j], p->tw[idx]);
                acc.re += t.re;
                acc.im += t.im;
            }
            out[k] = acc;
        }
    }
}

static void work(ms_cpx *out, const ms_cpx *in, int fstride, const int *factors, ms_fft *p)
{
    const int q = factors[0], m = factors[1];
    ms_cpx *const beg = out, *const end = out + (size_t)q * m;
    if (m == 1) {
        for (; out != end; ++out, in += fstride)
            *out = *in;
    } else {
        for (; out != end; out += m, in += fstride)
            work(out, in, fstride * q, factors + 2, p);
    }
    if (q == 2)
        bfly2(beg, fstride, p, m);
    else if (q == 4)
        bfly4(beg, fstride, p, m);
    else if (q == 5)
        bfly5(beg, fstride, p, m);
    else if (q > 2)
        bfly_generic(beg, fstride, p, m, q);
}

void ms_fft_forward(ms_fft *p, ms_cpx *x)
{
    memcpy(p->buf2, x, (size_t)p->n * sizeof *x);
    work(x, p->buf2, 1, p->factors, p);
}

void ms_fft_inverse(ms_fft *p, ms_cpx *x)
{
    /* conj(FFT(conj(x))) */
    for (int j = 0; j < p->n; ++j)
        x[j].im = -x[j].im;
    ms_fft_forward(p, x);
    for (int j = 0; j < p->n; ++j)
        x[j].im = -x[j].im;
}

void ms_dct_forward(ms_fft *p, float *x)
{
    const int n = p->n, h = (n + 1) / 2;
    ms_cpx *v = p->buf;
    /* v = x[0], x[2], ..., then the odd entries backwards */
    for (int j = 0; j < h; ++j) {
        v[j].re = x[2 * j];
        v[j].im = 0.0f;
    }
    for (int j = 0; 2 * j + 1 < n; ++j) {
        v[n - 1 - j].re = x[2 * j + 1];
        v[n - 1 - j].im = 0.0f;
    }
    ms_fft_forward(p, v);
    for (int k = 0; k < n; ++k)
        x[k] = v[k].re * p->dtw[k].re - v[k].im * p->dtw[k].im; /* Re(e^{-i pi k/2n} V_k) */
}

void ms_dct_inverse(ms_fft *p, float *x)
{
    const int n = p->n, h = (n + 1) / 2;
    ms_cpx *v = p->buf;
    const float inv = 1.0f / (float)n;
    /* V_k = e^{+i pi k/2n} (X_k - i X_{n-k}), X_n = 0 */
    for (int k = 0; k < n; ++k) {
        const float a = x[k], b = k ? -x[n - k] : 0.0f;
        const float c = p->dtw[k].re, s = -p->dtw[k].im;
        v[k].re = a * c - b * s;
        v[k].im = a * s + b * c;
    }
    ms_fft_inverse(p, v);
    for (int j = 0; j < h; ++j)
        x[2 * j] = v[j].re * inv;
    for (int j = 0; 2 * j + 1 < n; ++j)
        x[2 * j + 1] = v[n - 1 - j].re * inv;
}

/* Two DCT-IIs at once: x in the real part, y in the imaginary part of one
 * complex FFT, split by the symmetry of real transforms,
 * V_x[k] = (Z_k + conj Z_{n-k}) / 2, V_y[k] = (Z_k - conj Z_{n-k}) / 2i. */
void ms_dct_forward2(ms_fft *p, float *x, float *y)
{
    const int n = p->n, h = (n + 1) / 2;
    ms_cpx *v = p->buf;
    for (int j = 0; j < h; ++j) {
        v[j].re = x[2 * j];
        v[j].im = y[2 * j];
    }
    for (int j = 0; 2 * j + 1 < n; ++j) {
        v[n - 1 - j].re = x[2 * j + 1];
        v[n - 1 - j].im = y[2 * j + 1];
    }
    ms_fft_forward(p, v);
    for (int k = 0; k < n; ++k) {
        const ms_cpx zk = v[k], zn = v[k ? n - k : 0];
        const float ar = 0.5f * (zk.re + zn.re), ai = 0.5f * (zk.im - zn.im);
        const float br = 0.5f * (zk.im + zn.im), bi = -0.5f * (zk.re - zn.re);
        x[k] = ar * p->dtw[k].re - ai * p->dtw[k].im;
        y[k] = br * p->dtw[k].re - bi * p->dtw[k].im;
    }
}

/* The inverse of ms_dct_forward2: both spectra into one complex FFT, x
 * back from the real part and y from the imaginary part. */
void ms_dct_inverse2(ms_fft *p, float *x, float *y)
{
    const int n = p->n, h = (n + 1) / 2;
    ms_cpx *v = p->buf;
    const float inv = 1.0f / (float)n;
    for (int k = 0; k < n; ++k) {
        const float c = p->dtw[k].re, s = -p->dtw[k].im;
        const float xa = x[k], xb = k ? -x[n - k] : 0.0f;
        const float ya = y[k], yb = k ? -y[n - k] : 0.0f;
        const float ar = xa * c - xb * s, ai = xa * s + xb * c; /* V_x */
        const float br = ya * c - yb * s, bi = ya * s + yb * c; /* V_y */
        v[k].re = ar - bi;                                      /* V_x + i V_y */
        v[k].im = ai + br;
    }
    ms_fft_inverse(p, v);
    for (int j = 0; j < h; ++j) {
        x[2 * j] = v[j].re * inv;
        y[2 * j] = v[j].im * inv;
    }
    for (int j = 0; 2 * j + 1 < n; ++j) {
        x[2 * j + 1] = v[n - 1 - j].re * inv;
        y[2 * j + 1] = v[n - 1 - j].im * inv;
    }
}
