/* nxtmapFlashCommand: one command of the embedded flash controller, run from RAM.
 * The NXT's flash has one plane: while a command programs it (MC_FSR.FRDY 0) no instruction may be
 * fetched from flash, so this routine lives in .ramfunc (copied to RAM with .data) and holds IRQ and FIQ
 * off (their handlers are in flash) until FRDY is 1 again: about 6 ms for a page.
 * In: r0 = the MC_FCR word (key, page, command). Out: r0 = every MC_FSR bit read meanwhile, ORed
 * (LOCKE and PROGE clear when FSR is read, so they are kept from the read that saw them). */
        .syntax unified
        .section .ramfunc,"ax",%progbits
        .arm
        .align 2
        .global nxtmapFlashCommand
        .type nxtmapFlashCommand, %function
nxtmapFlashCommand:
        mrs r2, cpsr
        orr r3, r2, #0xC0          /* I and F */
        msr cpsr_c, r3
        ldr r1, =0xFFFFFF00        /* MC base: FCR at 0x64, FSR at 0x68 */
        str r0, [r1, #0x64]
        mov r0, #0
1:      ldr r3, [r1, #0x68]
        orr r0, r0, r3
        tst r3, #1                 /* FRDY */
        beq 1b
        msr cpsr_c, r2
        bx lr
        .ltorg
        .size nxtmapFlashCommand, . - nxtmapFlashCommand
