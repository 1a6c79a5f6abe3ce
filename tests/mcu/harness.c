/* MCU test harness: runs the library's shared test vectors (tests/vectors/vectors.c,
 * the table the host cmocka tests use) on a bare-metal target.  For each
 * variant compiled in it calls the function, compares the status, each
 * output within the vector's tolerance, and that nothing was written that
 * may not be (bodies bit-for-bit untouched on any refusal).  Each failure is
 * printed; the last line is "<target>: N passed, N failed" and the exit
 * status (through semihosting, so QEMU's own) is non-zero on any failure.
 * No C library, no allocation: the platform supplies mcu.h. */
#include <stddef.h>
#include <stdint.h>
#include "collide2d.h"
#include "vectors.h"
#include "mcu.h"

#ifndef C2D_MCU_NAME
#define C2D_MCU_NAME "mcu"
#endif

typedef struct c2d_tally { int passed, failed; } c2d_tally;

/* ------------------------------------------------------------ printing */

static void c2d_put(const char *s) { c2d_mcu_puts(s); }

static void c2d_put_int(long v)
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
/* An IEEE value from its fields in C99 %a form (0x1.8p+1), so a failure
 * shows the exact bits in the notation tests/vectors/vectors.c is written in. */
static void c2d_put_hexfloat(int neg, int bexp, uint64_t mant, int mant_bits, int bias)
{
    static const char hex[] = "0123456789abcdef";
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
static void c2d_put_d(double x)
{
    union { double f; uint64_t u; } p;
    p.f = x;
    c2d_put_hexfloat((int)(p.u >> 63), (int)((p.u >> 52) & 0x7FFu), p.u & 0xFFFFFFFFFFFFFull, 52, 1023);
}
#endif

#ifndef C2D_NO_FLOAT
static void c2d_put_f(float x)
{
    union { float f; uint32_t u; } p;
    p.f = x;
    c2d_put_hexfloat((int)(p.u >> 31), (int)((p.u >> 23) & 0xFFu), p.u & 0x7FFFFFu, 23, 127);
}
#endif

#ifndef C2D_NO_FIXED
static void c2d_put_x(c2d_fixed x)
{
    c2d_put_int((long)x);
    c2d_put("/65536");
}
#endif

static void c2d_fail_begin(const char *variant, const char *name)
{
    c2d_put("FAIL ");
    c2d_put(variant);
    c2d_put(" ");
    c2d_put(name);
    c2d_put(": ");
}

/* ------------------------------------------------------------ comparing */

static int c2d_same_bytes(const void *x, const void *y, size_t n)
{
    const unsigned char *p = (const unsigned char *)x, *q = (const unsigned char *)y;
    size_t i;
    for (i = 0; i < n; i++)
        if (p[i] != q[i]) return 0;
    return 1;
}

#define C2D_ABS(x) ((x) < 0 ? -(x) : (x))
/* Equal first: also accepts two equal infinities. */
#define C2D_WITHIN_REAL(got, want, tol) ((got) == (want) || C2D_ABS((got) - (want)) <= (tol))

/* ------------------------------------------------------------ variants */

#ifndef C2D_NO_DOUBLE
#define R double
#define VECTOR c2d_vector_d
#define BODY c2d_body
#define VEC2 c2d_vec2
#define TABLE c2d_vectors_d
#define COUNT c2d_vector_count_d
#define NAME "double"
#define SFX(name) name##_d
#define PUT_R c2d_put_d
#define WITHIN C2D_WITHIN_REAL
#define COLLIDE c2d_collide
#define COLLIDE_NORMAL c2d_collide_normal
#define TOI c2d_time_of_impact
#define PAIRS c2d_pairs
#define BATCH c2d_collide_batch
#include "harness_variant.h"
#endif

#ifndef C2D_NO_FLOAT
#define R float
#define VECTOR c2d_vector_f
#define BODY c2d_bodyf
#define VEC2 c2d_vec2f
#define TABLE c2d_vectors_f
#define COUNT c2d_vector_count_f
#define NAME "float"
#define SFX(name) name##_f
#define PUT_R c2d_put_f
#define WITHIN C2D_WITHIN_REAL
#define COLLIDE c2d_collidef
#define COLLIDE_NORMAL c2d_collide_normalf
#define TOI c2d_time_of_impactf
#define PAIRS c2d_pairsf
#define BATCH c2d_collide_batchf
#include "harness_variant.h"
#endif

#ifndef C2D_NO_FIXED
/* In int64: the difference of two Q16.16 values can exceed int32. */
#define C2D_WITHIN_FIXED(got, want, tol) (C2D_ABS((int64_t)(got) - (int64_t)(want)) <= (int64_t)(tol))
#define R c2d_fixed
#define VECTOR c2d_vector_x
#define BODY c2d_bodyx
#define VEC2 c2d_vec2x
#define TABLE c2d_vectors_x
#define COUNT c2d_vector_count_x
#define NAME "Q16.16"
#define SFX(name) name##_x
#define PUT_R c2d_put_x
#define WITHIN C2D_WITHIN_FIXED
#define COLLIDE c2d_collidex
#define COLLIDE_NORMAL c2d_collide_normalx
#define TOI c2d_time_of_impactx
#include "harness_variant.h"
#endif

int main(void)
{
    c2d_tally tally = {0, 0};
    long peak;
    c2d_put(C2D_MCU_NAME ": collide2d ");
    c2d_put_int(c2d_version());
    c2d_put(", vectors:");
#ifndef C2D_NO_DOUBLE
    c2d_put(" double");
#endif
#ifndef C2D_NO_FLOAT
    c2d_put(" float");
#endif
#ifndef C2D_NO_FIXED
    c2d_put(" Q16.16");
#endif
    c2d_put("\n");
#ifndef C2D_NO_DOUBLE
    run_table_d(&tally);
#endif
#ifndef C2D_NO_FLOAT
    run_table_f(&tally);
#endif
#ifndef C2D_NO_FIXED
    run_table_x(&tally);
#endif
    if (tally.passed + tally.failed == 0) {
        c2d_put("FAIL no vectors compiled in\n");
        tally.failed = 1;
    }
    peak = c2d_mcu_stack_peak();
    if (peak >= 0) {
        c2d_put(C2D_MCU_NAME ": stack peak ");
        c2d_put_int(peak);
        c2d_put(" bytes (harness included)\n");
    }
    c2d_put(C2D_MCU_NAME ": ");
    c2d_put_int(tally.passed);
    c2d_put(" passed, ");
    c2d_put_int(tally.failed);
    c2d_put(" failed\n");
    c2d_mcu_exit(tally.failed == 0 ? 0 : 1);
}
