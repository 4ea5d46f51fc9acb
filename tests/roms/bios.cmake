# HLE kernel test programs: BIOS calls through the A0h/B0h/C0h vectors and SYSCALL.
# CHECKS: one per CHECK_EQ call site, each run once.
psx_add_rom_test(bios_string SOURCES bios_string.c bios_calls.S CHECKS 52)
psx_add_rom_test(bios_heap SOURCES bios_heap.c bios_calls.S CHECKS 20)
psx_add_rom_test(bios_interrupts SOURCES bios_interrupts.c bios_calls.S CHECKS 31)
psx_add_rom_test(bios_kernel SOURCES bios_kernel.c bios_calls.S CHECKS 43)
psx_add_rom_test(bios_entry SOURCES bios_entry.c CHECKS 9)
psx_add_rom_test(bios_load_delay SOURCES bios_load_delay.c bios_calls.S CHECKS 6)
psx_add_rom_test(bios_exceptions SOURCES bios_exceptions.c bios_calls.S CHECKS 5)
psx_add_rom_test(bios_pad_vblank SOURCES bios_pad_vblank.c bios_calls.S CHECKS 8)
# Run by both CPUs too: the recompiler keeps a load in flight in a host register and hands the
# kernel the CPU's pending-load fields only on its way out of a block.
psx_add_run_test(rom.bios_load_delay_recompiler CODE 0 CHECKS 6
  RUN --exe ${CMAKE_CURRENT_BINARY_DIR}/bios_load_delay.exe --frames 600 --expect-exit --cpu recompiler)
