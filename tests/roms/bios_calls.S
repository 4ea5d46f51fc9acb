# BIOS call stubs as the SDK writes them: load the table address, jump, and set the function
# number in the jump's delay slot; the BIOS returns straight to the C caller.
        .set noreorder
        .text
#include "bios_call.inc"

        BIOS    bios_strlen, 0xA0, 0x1B
        BIOS    bios_memcpy, 0xA0, 0x2A
        BIOS    bios_memset, 0xA0, 0x2B
        BIOS    bios_putchar, 0xA0, 0x3C
        BIOS    bios_puts, 0xA0, 0x3E
        BIOS    bios_printf, 0xA0, 0x3F
        BIOS    bios_flush_cache, 0xA0, 0x44
        BIOS    std_out_putchar, 0xB0, 0x3D
        BIOS    std_out_puts, 0xB0, 0x3F

        .globl  enter_critical_section
enter_critical_section:
        li      $a0, 1
        syscall
        jr      $ra
        nop

        .globl  exit_critical_section
exit_critical_section:
        li      $a0, 2
        syscall
        jr      $ra
        nop

# Further kernel calls for the bios_* test programs (numbers from psx-spx "BIOS Function Summary").
        BIOS    bios_strtol, 0xA0, 0x0C
        BIOS    bios_abs, 0xA0, 0x0E
        BIOS    bios_atoi, 0xA0, 0x10
        BIOS    bios_setjmp, 0xA0, 0x13
        BIOS    bios_longjmp, 0xA0, 0x14
        BIOS    bios_strcat, 0xA0, 0x15
        BIOS    bios_strncat, 0xA0, 0x16
        BIOS    bios_strcmp, 0xA0, 0x17
        BIOS    bios_strncmp, 0xA0, 0x18
        BIOS    bios_strcpy, 0xA0, 0x19
        BIOS    bios_strncpy, 0xA0, 0x1A
        BIOS    bios_strchr, 0xA0, 0x1E
        BIOS    bios_strrchr, 0xA0, 0x1F
        BIOS    bios_strpbrk, 0xA0, 0x20
        BIOS    bios_strspn, 0xA0, 0x21
        BIOS    bios_strcspn, 0xA0, 0x22
        BIOS    bios_strtok, 0xA0, 0x23
        BIOS    bios_strstr, 0xA0, 0x24
        BIOS    bios_toupper, 0xA0, 0x25
        BIOS    bios_tolower, 0xA0, 0x26
        BIOS    bios_bcopy, 0xA0, 0x27
        BIOS    bios_bzero, 0xA0, 0x28
        BIOS    bios_memmove, 0xA0, 0x2C
        BIOS    bios_memcmp, 0xA0, 0x2D
        BIOS    bios_memchr, 0xA0, 0x2E
        BIOS    bios_rand, 0xA0, 0x2F
        BIOS    bios_srand, 0xA0, 0x30
        BIOS    bios_malloc, 0xA0, 0x33
        BIOS    bios_free, 0xA0, 0x34
        BIOS    bios_calloc, 0xA0, 0x37
        BIOS    bios_realloc, 0xA0, 0x38
        BIOS    bios_init_heap, 0xA0, 0x39
        BIOS    bios_get_system_info, 0xA0, 0xB4
        BIOS    alloc_kernel_memory, 0xB0, 0x00
        BIOS    free_kernel_memory, 0xB0, 0x01
        BIOS    set_rcnt, 0xB0, 0x02
        BIOS    start_rcnt, 0xB0, 0x04
        BIOS    stop_rcnt, 0xB0, 0x05
        BIOS    deliver_event, 0xB0, 0x07
        BIOS    open_event, 0xB0, 0x08
        BIOS    close_event, 0xB0, 0x09
        BIOS    wait_event, 0xB0, 0x0A
        BIOS    test_event, 0xB0, 0x0B
        BIOS    enable_event, 0xB0, 0x0C
        BIOS    disable_event, 0xB0, 0x0D
        BIOS    init_pad, 0xB0, 0x12
        BIOS    start_pad, 0xB0, 0x13
        BIOS    stop_pad, 0xB0, 0x14
        BIOS    return_from_exception, 0xB0, 0x17
        BIOS    reset_entry_int, 0xB0, 0x18
        BIOS    hook_entry_int, 0xB0, 0x19
        BIOS    undeliver_event, 0xB0, 0x20
        BIOS    change_clear_pad, 0xB0, 0x5B
        BIOS    sys_enq_int_rp, 0xC0, 0x02
        BIOS    sys_deq_int_rp, 0xC0, 0x03
        BIOS    change_clear_rcnt, 0xC0, 0x0A

# Kernel tables, threads and the C0h handler set-up (bios_kernel).
        BIOS    open_th, 0xB0, 0x0E
        BIOS    close_th, 0xB0, 0x0F
        BIOS    change_th, 0xB0, 0x10
        BIOS    krom2_raw_add, 0xB0, 0x51
        BIOS    get_c0_table, 0xB0, 0x56
        BIOS    get_b0_table, 0xB0, 0x57
        BIOS    enqueue_rcnt_irqs, 0xC0, 0x00
        BIOS    enqueue_syscall_handler, 0xC0, 0x01
        BIOS    init_def_int, 0xC0, 0x0C
        BIOS    set_irq_auto_ack, 0xC0, 0x0D
