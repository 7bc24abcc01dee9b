/* nxtmap start-up for the AT91SAM7S256 (ARM7TDMI, ARMv4T): vectors, mode stacks, clocks, .data/.bss,
 * vector copy + remap, static constructors, main. ARM code; calls into Thumb with `mov lr, pc; bx rN`
 * (v4T has no blx). Symbols come from the linker script (firmware/board/nxt-*.ld). */
        .syntax unified
        .arm

        .equ MODE_FIQ, 0x11
        .equ MODE_IRQ, 0x12
        .equ MODE_SVC, 0x13
        .equ MODE_ABT, 0x17
        .equ MODE_UND, 0x1B
        .equ I_BIT, 0x80
        .equ F_BIT, 0x40
        .equ MC_RCR, 0xFFFFFF00

        .section .vectors, "ax"
        .global _vectors
        .global _start
_start:
_vectors:
        ldr pc, _reset_addr
        ldr pc, _undef_addr
        ldr pc, _swi_addr
        ldr pc, _pabt_addr
        ldr pc, _dabt_addr
        ldr pc, _reserved_addr
        ldr pc, [pc, #-0xF20]          /* IRQ: jump to AIC_IVR */
        ldr pc, [pc, #-0xF20]          /* FIQ: jump to AIC_FVR */
_reset_addr:    .word reset_handler
_undef_addr:    .word fault_handler
_swi_addr:      .word fault_handler
_pabt_addr:     .word fault_handler
_dabt_addr:     .word fault_handler
_reserved_addr: .word fault_handler
                .word 0
                .word 0

        .text
        .arm
        .global reset_handler
        .type reset_handler, %function
reset_handler:
        /* One stack per mode, interrupts masked. */
        msr cpsr_c, #MODE_UND | I_BIT | F_BIT
        ldr sp, =__und_stack_top
        msr cpsr_c, #MODE_ABT | I_BIT | F_BIT
        ldr sp, =__abt_stack_top
        msr cpsr_c, #MODE_FIQ | I_BIT | F_BIT
        ldr sp, =__fiq_stack_top
        msr cpsr_c, #MODE_IRQ | I_BIT | F_BIT
        ldr sp, =__irq_stack_top
        msr cpsr_c, #MODE_SVC | I_BIT | F_BIT
        ldr sp, =__svc_stack_top

        /* Flash wait states, watchdog, clocks to 48 MHz (C++, touches no RAM variables). */
        ldr r0, =nxtmapLowLevelInit
        mov lr, pc
        bx r0

        /* Vectors (8 instructions + 8 literal words) to the bottom of RAM. */
        ldr r0, =_vectors
        ldr r1, =__ram_vectors
        ldmia r0!, {r2-r9}
        stmia r1!, {r2-r9}
        ldmia r0!, {r2-r9}
        stmia r1!, {r2-r9}

        /* Remap RAM to 0 unless it is there already (a write of RCB toggles the mapping). */
        ldr r0, =__ram_vectors
        ldr r1, [r0, #0x40]            /* keep the word under the probe */
        mvn r2, r1
        str r2, [r0, #0x40]
        mov r3, #0x40
        ldr r3, [r3]
        str r1, [r0, #0x40]
        cmp r3, r2
        beq 1f
        ldr r0, =MC_RCR
        mov r1, #1
        str r1, [r0]
1:
        /* .data from its load address (flash build) and .bss to zero. */
        ldr r0, =__data_load
        ldr r1, =__data_start
        ldr r2, =__data_end
        cmp r0, r1
        beq 3f
2:      cmp r1, r2
        ldrlo r3, [r0], #4
        strlo r3, [r1], #4
        blo 2b
3:      ldr r1, =__bss_start
        ldr r2, =_ebss
        mov r3, #0
4:      cmp r1, r2
        strlo r3, [r1], #4
        blo 4b

        /* Static constructors. */
        ldr r4, =__init_array_start
        ldr r5, =__init_array_end
5:      cmp r4, r5
        bhs 6f
        ldr r0, [r4], #4
        mov lr, pc
        bx r0
        b 5b
6:
        ldr r0, =main
        mov lr, pc
        bx r0
7:      b 7b

        /* Undefined instruction, SWI, aborts: stop here with interrupts masked. The watchdog then
         * resets the chip, and the new boot sends the AVR zero motor power. */
        .global fault_handler
        .type fault_handler, %function
fault_handler:
        b fault_handler

        /* CPSR helpers for Thumb code (Thumb-1 has no MSR/MRS). */
        .global nxtmapIrqEnable
        .type nxtmapIrqEnable, %function
nxtmapIrqEnable:
        mrs r0, cpsr
        bic r0, r0, #I_BIT
        msr cpsr_c, r0
        bx lr

        .global nxtmapIrqDisable
        .type nxtmapIrqDisable, %function
nxtmapIrqDisable:
        mrs r0, cpsr
        orr r1, r0, #I_BIT
        msr cpsr_c, r1
        bx lr

        .ltorg
