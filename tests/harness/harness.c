/* SPDX-License-Identifier: MIT */
/* harness.c - the type-independent half of the shared test helper
 * (harness.h): exact printing of numbers without a C library, the pass/fail
 * tally, byte comparison. */
#include "harness.h"

/* -------------------------------------------------------------- output */

void c2d_put_int(long v)
{
    char buf[24];
    size_t i = sizeof buf - 1;
    unsigned long u = v < 0 ? 0ul - (unsigned long)v : (unsigned long)v;
    buf[i] = '\0';
    do {
        buf[--i] = (char)('0' + u % 10u);
        u /= 10u;
    } while (u != 0u);
    if (v < 0) buf[--i] = '-';
    c2d_put(&buf[i]);
}

#if !defined(C2D_NO_DOUBLE) || !defined(C2D_NO_FLOAT)
/* An IEEE value from its bits (mant_bits fraction bits below exp_bits
 * exponent bits) in C99 %a form (0x1.8p+1), so a failure shows the exact
 * bits in the notation tests/vectors/vectors.c is written in, with no
 * printf on the target. */
static void c2d_put_ieee(uint64_t bits, int mant_bits, int exp_bits)
{
    static const char hex[] = "0123456789abcdef";
    const int bias = (1 << (exp_bits - 1)) - 1;
    const int neg = (int)(bits >> (mant_bits + exp_bits)) & 1;
    const int bexp = (int)(bits >> mant_bits) & ((1 << exp_bits) - 1);
    const uint64_t mant = bits & (((uint64_t)1 << mant_bits) - 1u);
    char buf[40];
    size_t n = 0;
    int digits = (mant_bits + 3) / 4, e;
    uint64_t m = mant << (digits * 4 - mant_bits);
    if (neg) buf[n++] = '-';
    if (bexp == 2 * bias + 1) {
        c2d_put(neg ? "-" : "");
        c2d_put(mant == 0 ? "inf" : "nan");
        return;
    }
    buf[n++] = '0';
    buf[n++] = 'x';
    buf[n++] = bexp == 0 ? '0' : '1';
    e = bexp == 0 ? (mant == 0 ? 0 : 1 - bias) : bexp - bias;
    while (digits > 0 && (m & 0xFu) == 0u) {
        m >>= 4;
        digits--;
    }
    if (digits > 0) {
        int i;
        buf[n++] = '.';
        for (i = digits - 1; i >= 0; i--) buf[n++] = hex[(m >> (4 * i)) & 0xFu];
    }
    buf[n++] = 'p';
    buf[n++] = e < 0 ? '-' : '+';
    buf[n] = '\0';
    c2d_put(buf);
    c2d_put_int(e < 0 ? -e : e);
}
#endif

#ifndef C2D_NO_DOUBLE
void c2d_put_double(double x)
{
    union { double f; uint64_t u; } p;
    p.f = x;
    c2d_put_ieee(p.u, 52, 11);
}
#endif

#ifndef C2D_NO_FLOAT
void c2d_put_float(float x)
{
    union { float f; uint32_t u; } p;
    p.f = x;
    c2d_put_ieee(p.u, 23, 8);
}
#endif

#ifndef C2D_NO_FIXED
void c2d_put_fixed(c2d_fixed x)
{
    c2d_put_int((long)x);
    c2d_put("/65536");
}
#endif

int c2d_same_bytes(const void *x, const void *y, size_t n)
{
    const unsigned char *p = (const unsigned char *)x, *q = (const unsigned char *)y;
    size_t i;
    for (i = 0; i < n; i++)
        if (p[i] != q[i]) return 0;
    return 1;
}

/* ----------------------------------------------------------- pass/fail */

int c2d_tally_add(c2d_tally *t, int ok)
{
    if (ok) {
        t->passed++;
    } else {
        t->failed++;
    }
    return ok;
}

void c2d_put_tally(const char *name, const c2d_tally *t)
{
    if (name != NULL) {
        c2d_put(name);
        c2d_put(": ");
    }
    c2d_put_int(t->passed);
    c2d_put(" passed, ");
    c2d_put_int(t->failed);
    c2d_put(" failed\n");
}

int c2d_tally_status(const c2d_tally *t) { return t->failed == 0 ? 0 : 1; }
