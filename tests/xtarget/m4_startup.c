/* m4_startup.c - minimal bare-metal runtime for the Cortex-M4F of QEMU's mps2-an386 board,
   used by tests/xtarget/run.sh (link with mps2_an386.ld, -nostartfiles).

   - the vector table (initial stack pointer, reset and fault handlers);
   - reset: enable the FPU (CPACR: full access to CP10 and CP11) before any floating-point
     instruction runs, copy .data, zero .bss, call main(), exit with its status;
   - ARM semihosting (BKPT 0xAB; QEMU needs -semihosting): xt_write() writes to the host's
     stdout through a ":tt" handle, xt_exit() ends QEMU with an exit status
     (SYS_EXIT_EXTENDED);
   - memset/memcpy, which compilers may emit calls to (the -nostdlib builds have no libc);
   - faults print a message and exit with status 3, so a crash never hangs the test;
     xt_assert_fail() (FOV_ASSERT of render_test.c) exits with status 5.
   No interrupts, no heap, no C++ constructors. */

#include <stddef.h>
#include <stdint.h>

int main(void);
void xt_write(const void *buf, size_t n);
void xt_exit(int status) __attribute__((noreturn));
void xt_reset_handler(void) __attribute__((naked, noreturn));
void xt_fault_handler(void) __attribute__((noreturn));
void xt_assert_fail(const char *expr, int line) __attribute__((noreturn));
void xt_cstart(void) __attribute__((noreturn));
#ifndef XT_HAVE_LIBC
void *memset(void *d, int c, size_t n);
void *memcpy(void *d, const void *s, size_t n);
#endif

extern uint32_t xt_stack_top[];
extern uint32_t xt_data_start[], xt_data_end[], xt_data_load[];
extern uint32_t xt_bss_start[], xt_bss_end[];

/* ---- semihosting ---- */
#define XT_SYS_OPEN 0x01
#define XT_SYS_WRITE 0x05
#define XT_SYS_WRITE0 0x04
#define XT_SYS_EXIT 0x18
#define XT_SYS_EXIT_EXTENDED 0x20
#define XT_ADP_STOPPED_APPLICATION_EXIT 0x20026u
#define XT_ADP_STOPPED_RUNTIME_ERROR 0x20023u

static int xt_semihost(int op, const void *arg)
{
    register int r0 __asm__("r0") = op;
    register const void *r1 __asm__("r1") = arg;
    __asm__ volatile("bkpt 0xAB" : "+r"(r0) : "r"(r1) : "memory");
    return r0;
}

static int xt_stdout_handle = -1;

void xt_write(const void *buf, size_t n)
{
    const char *p = (const char *)buf;
    if (xt_stdout_handle < 0) {
        static const char tt[] = ":tt";
        uint32_t args[3];
        args[0] = (uint32_t)(uintptr_t)tt;
        args[1] = 4u;               /* mode "w" */
        args[2] = 3u;               /* strlen(":tt") */
        xt_stdout_handle = xt_semihost(XT_SYS_OPEN, args);
        if (xt_stdout_handle < 0) xt_exit(4);
    }
    while (n > 0) {
        uint32_t args[3];
        int left;
        args[0] = (uint32_t)xt_stdout_handle;
        args[1] = (uint32_t)(uintptr_t)p;
        args[2] = (uint32_t)n;
        left = xt_semihost(XT_SYS_WRITE, args);   /* returns the bytes NOT written */
        if (left < 0 || (size_t)left > n) xt_exit(4);
        if ((size_t)left == n) xt_exit(4);        /* no progress */
        p += n - (size_t)left;
        n = (size_t)left;
    }
}

void xt_exit(int status)
{
    uint32_t args[2];
    args[0] = XT_ADP_STOPPED_APPLICATION_EXIT;
    args[1] = (uint32_t)status;
    (void)xt_semihost(XT_SYS_EXIT_EXTENDED, args);
    /* a debugger without SYS_EXIT_EXTENDED: plain SYS_EXIT (status 0 or 1 only) */
    (void)xt_semihost(XT_SYS_EXIT, (const void *)(uintptr_t)(status == 0
        ? XT_ADP_STOPPED_APPLICATION_EXIT : XT_ADP_STOPPED_RUNTIME_ERROR));
    for (;;) { }
}

void xt_fault_handler(void)
{
    static const char msg[] = "\nxt: fault (HardFault/MemManage/BusFault/UsageFault/NMI)\n";
    (void)xt_semihost(XT_SYS_WRITE0, msg);
    xt_exit(3);
}

/* FOV_ASSERT failures of render_test.c: print the expression and line, exit with status 5 */
void xt_assert_fail(const char *expr, int line)
{
    char num[16];
    int n = 0, i;
    unsigned v = line < 0 ? 0u : (unsigned)line;
    static const char head[] = "\nxt: FOV_ASSERT failed: ";
    xt_write(head, sizeof head - 1);
    {   /* volatile: keeps the compiler from calling strlen (there is no libc) */
        const volatile char *e = expr;
        for (i = 0; e[i]; i++) { }
    }
    xt_write(expr, (size_t)i);
    do { num[n++] = (char)('0' + (int)(v % 10u)); v /= 10u; } while (v > 0u && n < 12);
    xt_write(" at fovsdf.h line ", 18);
    while (n > 0) xt_write(&num[--n], 1);
    xt_write("\n", 1);
    xt_exit(5);
}

/* ---- reset ---- */
void xt_reset_handler(void)
{
    /* SCB->CPACR (0xE000ED88) |= CP10 and CP11 full access; then DSB, ISB. Done in assembly
       so that no compiler-generated FPU instruction can run before it. */
    __asm__ volatile(
        "ldr r0, =0xE000ED88\n"
        "ldr r1, [r0]\n"
        "orr r1, r1, #(0xF << 20)\n"
        "str r1, [r0]\n"
        "dsb\n"
        "isb\n"
        "b xt_cstart\n"
        ".ltorg\n");
}

void xt_cstart(void)
{
    uint32_t *src = xt_data_load, *dst = xt_data_start;
    while (dst < xt_data_end) *dst++ = *src++;
    for (dst = xt_bss_start; dst < xt_bss_end; ) *dst++ = 0u;
    xt_exit(main());
}

#ifndef XT_HAVE_LIBC
/* volatile stores keep the compiler from turning these loops into calls to themselves */
void *memset(void *d, int c, size_t n)
{
    volatile unsigned char *p = (volatile unsigned char *)d;
    while (n--) *p++ = (unsigned char)c;
    return d;
}

void *memcpy(void *d, const void *s, size_t n)
{
    volatile unsigned char *p = (volatile unsigned char *)d;
    const unsigned char *q = (const unsigned char *)s;
    while (n--) *p++ = *q++;
    return d;
}
#endif

/* ---- vector table (ARMv7-M: 16 system entries; no external interrupts are enabled) ---- */
typedef void (*xt_vector)(void);
__attribute__((section(".xt_vectors"), used))
static const xt_vector xt_vectors[16] = {
    (xt_vector)(uintptr_t)xt_stack_top, /* initial SP */
    xt_reset_handler,                   /* reset */
    xt_fault_handler,                   /* NMI */
    xt_fault_handler,                   /* HardFault */
    xt_fault_handler,                   /* MemManage */
    xt_fault_handler,                   /* BusFault */
    xt_fault_handler,                   /* UsageFault */
    0, 0, 0, 0,                         /* reserved */
    xt_fault_handler,                   /* SVCall */
    xt_fault_handler,                   /* DebugMonitor */
    0,                                  /* reserved */
    xt_fault_handler,                   /* PendSV */
    xt_fault_handler                    /* SysTick */
};
