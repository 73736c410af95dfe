/* Fast Fourier and cosine transforms of one length (lib/surface/ only):
 * the spectral operator of the dispersive surface model (dispersive.c)
 * applies its symbol in the basis of the grid's boundary: cosines (DCT-II,
 * the eigenvectors of the reflecting, cell-centred grid) or complex
 * exponentials (the periodic grid). Any length >= 1: mixed radix, with
 * radices 4, 2 and 5 written out and a generic butterfly for the other
 * prime factors (a length with a large prime factor p costs ~p operations
 * a point).
 * Single precision data, twiddles computed in double; the same operations
 * in the same order on every call, so the same bits. */
#ifndef MS_SURFACE_FFT_H
#define MS_SURFACE_FFT_H

#include <stddef.h>

typedef struct ms_cpx {
    float re, im;
} ms_cpx;

typedef struct ms_fft ms_fft;

/* A plan for length n; NULL when out of memory. */
ms_fft *ms_fft_create(int n);
void ms_fft_destroy(ms_fft *p);
/* Bytes the plan holds. */
size_t ms_fft_bytes(const ms_fft *p);
/* In place: x[k] <- sum_j x[j] e^{-2 pi i jk/n} (inverse: e^{+...}, no 1/n). */
void ms_fft_forward(ms_fft *p, ms_cpx *x);
void ms_fft_inverse(ms_fft *p, ms_cpx *x);
/* DCT-II of n reals in place, X[k] = sum_j x[j] cos(pi k (2j + 1) / (2n)),
 * and its inverse (x from X, the 2/n and the half weight of X[0]
 * included), by Makhoul's reordering and one complex FFT of length n. */
void ms_dct_forward(ms_fft *p, float *x);
void ms_dct_inverse(ms_fft *p, float *x);
/* The same for two sequences x and y at the cost of one (both in place). */
void ms_dct_forward2(ms_fft *p, float *x, float *y);
void ms_dct_inverse2(ms_fft *p, float *x, float *y);

#endif /* MS_SURFACE_FFT_H */
