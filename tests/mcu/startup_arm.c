/* SPDX-License-Identifier: MIT */
/* Bare-metal Cortex-M start-up for the MCU test harness: vector table, reset
 * handler (FPU on, .data copied, .bss zeroed, stack painted), and the
 * semihosting calls behind mcu.h.  No C library: the Q16.16-only build links
 * against libgcc alone. */
#include <stddef.h>
#include <stdint.h>
#include "mcu.h"

/* From arm.ld. */
extern uint32_t __c2d_stack_top[];
extern uint32_t __c2d_data_load[], __c2d_data_start[], __c2d_data_end[];
extern uint32_t __c2d_bss_start[], __c2d_bss_end[];

int main(void);
void c2d_mcu_reset(void) __attribute__((noreturn));
static void c2d_mcu_fault(void) __attribute__((noreturn));

/* ARM semihosting operations and stop reasons (ARM DUI 0471 / semihosting v2). */
enum { SYS_OPEN = 0x01, SYS_WRITE = 0x05, SYS_EXIT = 0x18, SYS_EXIT_EXTENDED = 0x20 };
#define ADP_STOPPED_APPLICATION_EXIT 0x20026u
#define ADP_STOPPED_RUNTIME_ERROR 0x20023u

#define CPACR (*(volatile uint32_t *)0xE000ED88u)
#define C2D_STACK_PAINT 0xC2D0C2D0u
/* Room left unpainted below the reset handler's own frame. */
#define C2D_PAINT_GAP 64u

typedef void (*c2d_vector)(void);

/* SP, reset, NMI, HardFault, then the configurable faults (M3 and up; reserved
 * on M0), SVC, PendSV and SysTick.  No interrupt is ever enabled. */
__attribute__((section(".vectors"), used)) static const c2d_vector c2d_vector_table[16] = {
    (c2d_vector)(uintptr_t)__c2d_stack_top, c2d_mcu_reset, c2d_mcu_fault, c2d_mcu_fault,
    c2d_mcu_fault, c2d_mcu_fault, c2d_mcu_fault, 0, 0, 0, 0,
    c2d_mcu_fault, c2d_mcu_fault, 0, c2d_mcu_fault, c2d_mcu_fault,
};

static uintptr_t c2d_semihost(uint32_t op, const void *arg)
{
    register uintptr_t r0 __asm__("r0") = op;
    register const void *r1 __asm__("r1") = arg;
    __asm__ volatile("bkpt 0xab" : "+r"(r0) : "r"(r1) : "memory");
    return r0;
}

static size_t c2d_strlen(const char *s)
{
    size_t n = 0;
    while (s[n] != '\0') n++;
    return n;
}

void c2d_mcu_puts(const char *s)
{
    /* ":tt" opened for writing is the host's stdout. */
    static intptr_t console = -1;
    uintptr_t block[3];
    if (console < 0) {
        block[0] = (uintptr_t)":tt";
        block[1] = 4; /* mode "w" */
        block[2] = 3;
        console = (intptr_t)c2d_semihost(SYS_OPEN, block);
    }
    block[0] = (uintptr_t)console;
    block[1] = (uintptr_t)s;
    block[2] = c2d_strlen(s);
    (void)c2d_semihost(SYS_WRITE, block);
}

void c2d_mcu_exit(int status)
{
    /* SYS_EXIT_EXTENDED carries the status as QEMU's exit code; plain SYS_EXIT
     * (if a host lacks the extension) still tells 0 from non-zero. */
    uintptr_t block[2];
    block[0] = ADP_STOPPED_APPLICATION_EXIT;
    block[1] = (uintptr_t)(uint32_t)status;
    (void)c2d_semihost(SYS_EXIT_EXTENDED, block);
    (void)c2d_semihost(SYS_EXIT, (const void *)(uintptr_t)(status == 0 ? ADP_STOPPED_APPLICATION_EXIT
                                                                         : ADP_STOPPED_RUNTIME_ERROR));
    for (;;) {
    }
}

static void c2d_mcu_fault(void)
{
    c2d_mcu_puts("fault: the core took an exception\n");
    c2d_mcu_exit(3);
}

long c2d_mcu_stack_peak(void)
{
    const volatile uint32_t *p = __c2d_bss_end;
    while (p < __c2d_stack_top && *p == C2D_STACK_PAINT) p++;
    return (long)((uintptr_t)__c2d_stack_top - (uintptr_t)p);
}

/* Volatile stores: an optimiser must not turn these loops into calls to
 * memcpy/memset, which a -nostdlib link does not have. */
static void c2d_init_memory(void)
{
    volatile uint32_t *dst = __c2d_data_start;
    const uint32_t *src = __c2d_data_load;
    uintptr_t sp;
    while (dst < __c2d_data_end) *dst++ = *src++;
    for (dst = __c2d_bss_start; dst < __c2d_bss_end; dst++) *dst = 0;
    __asm__ volatile("mov %0, sp" : "=r"(sp));
    for (dst = __c2d_bss_end; (uintptr_t)dst < sp - C2D_PAINT_GAP; dst++) *dst = C2D_STACK_PAINT;
}

void c2d_mcu_reset(void)
{
#ifdef __ARM_FP
    /* CP10 and CP11 (the FPU) to full access before any floating-point
     * instruction runs; the barriers make it take effect now. */
    CPACR |= 0xFu << 20;
    __asm__ volatile("dsb\n\tisb" ::: "memory");
#endif
    c2d_init_memory();
    c2d_mcu_exit(main());
}
