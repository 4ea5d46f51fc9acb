# CPU, bus, exception and boot test programs.
psx_add_rom_test(hello SOURCES hello.c)
