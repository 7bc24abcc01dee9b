@ Start-up code of the emulator's probe programs (ARM state): vectors, mode stacks, .data/.bss, static
@ constructors, main; main's return value goes to the test port (0xFFFE8010). IRQ entry reads AIC_IVR,
@ calls the handler (ARM or Thumb) and writes AIC_EOICR.
    .syntax unified
    .section .vectors, "ax"
    .arm
    .global _vectors
_vectors:
    ldr pc, reset_addr
    ldr pc, undef_addr
    ldr pc, swi_addr
    ldr pc, pabt_addr
    ldr pc, dabt_addr
    nop
    ldr pc, irq_addr
    ldr pc, fiq_addr
reset_addr: .word reset_handler
undef_addr: .word hang
swi_addr:   .word hang
pabt_addr:  .word hang
dabt_addr:  .word hang
    .word 0
irq_addr:   .word irq_entry
fiq_addr:   .word hang

    .text
    .arm
    .global reset_handler
    .type reset_handler, %function
reset_handler:
    msr cpsr_c, #0xD2
    ldr sp, =__irq_stack_top__
    msr cpsr_c, #0xD3
    ldr sp, =__svc_stack_top__
    ldr r0, =_sidata
    ldr r1, =_sdata
    ldr r2, =_edata
1:  cmp r1, r2
    ldrlo r3, [r0], #4
    strlo r3, [r1], #4
    blo 1b
    ldr r1, =_sbss
    ldr r2, =_ebss
    mov r3, #0
2:  cmp r1, r2
    strlo r3, [r1], #4
    blo 2b
    ldr r4, =__init_array_start
    ldr r5, =__init_array_end
3:  cmp r4, r5
    bhs 4f
    ldr r0, [r4], #4
    mov lr, pc
    bx r0
    b 3b
4:  ldr r0, =main
    mov lr, pc
    bx r0
    ldr r1, =0xFFFE8010
    str r0, [r1]
hang:
    b hang

    .type irq_entry, %function
irq_entry:
    sub lr, lr, #4
    stmfd sp!, {r0-r3, r12, lr}
    ldr r1, =0xFFFFF100
    ldr r0, [r1]
    mov lr, pc
    bx r0
    ldr r1, =0xFFFFF130
    str r1, [r1]
    ldmfd sp!, {r0-r3, r12, pc}^

    .global irq_enable
    .type irq_enable, %function
irq_enable:
    mrs r0, cpsr
    bic r0, r0, #0x80
    msr cpsr_c, r0
    bx lr

    .global irq_disable
    .type irq_disable, %function
irq_disable:
    mrs r0, cpsr
    orr r0, r0, #0x80
    msr cpsr_c, r0
    bx lr
