/* Start-up and the port interface for Cortex-M under qemu-system-arm:
 * vector table, reset (copy .data, clear .bss, enable the FPU where there
 * is one, call main), and Arm semihosting (BKPT 0xAB) for text and exit.
 * Used by ports/cortex-m0 (qemu -M microbit, a Cortex-M0),
 * ports/cortex-m4f (qemu -M mps2-an386, a Cortex-M4F) and ports/cortex-m55
 * (qemu -M mps3-an547, a Cortex-M55 with Helium); each has its own linker
 * script with the memory map. */
#include <stdint.h>

#include "port.h"

extern uint32_t __stack_top, __data_load, __data_start, __data_end, __bss_start, __bss_end;
int main(void);

/* Semihosting: operation in r0, argument block in r1, result in r0. */
static uint32_t semihost(uint32_t op, const void *arg)
{
    register uint32_t r0 __asm__("r0") = op;
    register const void *r1 __asm__("r1") = arg;
    __asm__ volatile("bkpt 0xab" : "+r"(r0) : "r"(r1) : "memory");
    return r0;
}

#define SYS_WRITE0 0x04u
#define SYS_EXIT 0x18u
#define ADP_STOPPED_APPLICATION_EXIT 0x20026u
#define ADP_STOPPED_RUN_TIME_ERROR 0x20023u

void port_puts(const char *s) { semihost(SYS_WRITE0, s); }

void port_exit(int status)
{
    /* AArch32 SYS_EXIT takes the reason itself: qemu exits 0 for
     * ApplicationExit and 1 otherwise. */
    semihost(SYS_EXIT, (const void *)(uintptr_t)(status == 0 ? ADP_STOPPED_APPLICATION_EXIT
                                                                : ADP_STOPPED_RUN_TIME_ERROR));
    for (;;)
        ;
}

__attribute__((noinline)) void port_mark(uint32_t id)
{
    __asm__ volatile("" : : "r"(id) : "memory");
}

void reset_handler(void);
void reset_handler(void)
{
    uint32_t *src = &__data_load, *dst = &__data_start;
    while (dst < &__data_end)
        *dst++ = *src++;
    for (dst = &__bss_start; dst < &__bss_end;)
        *dst++ = 0;
#if defined(__ARM_FP) || defined(__ARM_FEATURE_MVE)
    /* CPACR: full access to CP10 and CP11 (the FPU and Helium), then wait for it */
    *(volatile uint32_t *)0xE000ED88u |= 0xFu << 20;
    __asm__ volatile("dsb\n\tisb" ::: "memory");
#endif
    port_exit(main());
}

static void fault_handler(void)
{
    port_puts("FAIL fault: hard fault or unhandled exception\n");
    port_exit(1);
}

/* Initial stack pointer, then reset and the fault vectors; nothing here
 * uses interrupts. (A union: ISO C has no conversion between object and
 * function pointers.) */
typedef union vector {
    void *stack;
    void (*handler)(void);
} vector;
__attribute__((section(".vectors"), used)) static const vector vectors[16] = {
    {.stack = &__stack_top},     {.handler = reset_handler}, {.handler = fault_handler}, {.handler = fault_handler},
    {.handler = fault_handler},  {.handler = fault_handler}, {.handler = fault_handler}, {0},
    {0},                         {0},                        {0},                        {.handler = fault_handler},
    {.handler = fault_handler},  {0},                        {.handler = fault_handler}, {.handler = fault_handler},
};
