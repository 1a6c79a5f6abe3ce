/* SPDX-License-Identifier: MIT */
/* tsan_main.c - a program linking the library, for tests/build/tsan.sh:
 * built with -fsanitize=thread, it must reach main (gcc's ifunc resolver of
 * the batch kernel, instrumented, used to crash in the loader) and run the
 * batch kernels, double and float, from two threads on their own data
 * without a report.  Exit status 0 when every pair resolved as expected. */
#include "collide2d.h"

#include <pthread.h>
#include <stdio.h>

enum { N = 64 };

static void *work(void *arg)
{
    int *bad = (int *)arg;
    double pax[N], pay[N], pbx[N], pby[N], vax[N], vay[N], vbx[N], vby[N], ma[N], mb[N];
    float fpax[N], fpay[N], fpbx[N], fpby[N], fvax[N], fvay[N], fvbx[N], fvby[N], fma_[N], fmb[N];
    c2d_pairs p = {pax, pay, pbx, pby, vax, vay, vbx, vby, ma, mb};
    c2d_pairsf pf = {fpax, fpay, fpbx, fpby, fvax, fvay, fvbx, fvby, fma_, fmb};
    int i;
    for (i = 0; i < N; i++) { /* the README's example: (1, 0) hits (0, 0) at 45 degrees */
        pax[i] = pay[i] = vay[i] = vbx[i] = vby[i] = 0, pbx[i] = pby[i] = vax[i] = ma[i] = mb[i] = 1;
        fpax[i] = fpay[i] = fvay[i] = fvbx[i] = fvby[i] = 0, fpbx[i] = fpby[i] = fvax[i] = fma_[i] = fmb[i] = 1;
    }
    if (c2d_collide_batch(&p, N, 1.0, NULL) != N || c2d_collide_batchf(&pf, N, 1.0f, NULL) != N) *bad = 1;
    for (i = 0; i < N; i++)
        if (vax[i] != 0.5 || vay[i] != -0.5 || vbx[i] != 0.5 || vby[i] != 0.5 || fvax[i] != 0.5f ||
            fvay[i] != -0.5f || fvbx[i] != 0.5f || fvby[i] != 0.5f)
            *bad = 1;
    return NULL;
}

int main(void)
{
    pthread_t t[2];
    int bad[2] = {0, 0}, i;
    for (i = 0; i < 2; i++)
        if (pthread_create(&t[i], NULL, work, &bad[i]) != 0) return 2;
    for (i = 0; i < 2; i++) pthread_join(t[i], NULL);
    if (bad[0] || bad[1]) {
        fprintf(stderr, "tsan_main: wrong results\n");
        return 1;
    }
    return 0;
}
