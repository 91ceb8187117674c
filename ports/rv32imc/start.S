/* RV32IMC start-up for qemu-riscv32 user mode (Linux system calls, no libc):
 * the kernel (qemu) has set up the stack; set the global pointer the linker
 * relaxes against, call main, exit with its status. */
    .section .text.start
    .globl _start
_start:
    .option push
    .option norelax
    la gp, __global_pointer$
    .option pop
    call main
    li a7, 93          /* exit */
    ecall
1:  j 1b
