# Building PlayStation (guest) programs with Debian's MIPS cross compiler. Programs link only the
# project's own runtime (guest/): the Debian toolchain's libraries are MIPS32r2/PIC/hard-float.
# psx_add_exe(<target> SOURCES <files...> [INCLUDES <dirs...>] [DEFINES <defs...>] [NO_RUNTIME]
#             [LINKER_SCRIPT <file>])  (LINKER_SCRIPT replaces guest/psx.ld, e.g. to fix addresses)
# produces ${CMAKE_CURRENT_BINARY_DIR}/<target>.exe (a PS-X EXE) and <target>.elf.
find_program(PSX_CC mipsel-linux-gnu-gcc REQUIRED)

set(PSX_GUEST_DIR ${PROJECT_SOURCE_DIR}/guest)
set(PSX_CFLAGS -march=r3000 -mabi=32 -mno-abicalls -fno-pic -G0 -msoft-float -ffreestanding
    -nostdlib -fno-builtin -fno-stack-protector -O2 -Wall -Wno-main -std=gnu11)
set(PSX_LDFLAGS -nostdlib -static -Wl,--build-id=none)
set(PSX_RUNTIME_SOURCES ${PSX_GUEST_DIR}/crt0.S ${PSX_GUEST_DIR}/runtime.c)

function(psx_add_exe target)
  cmake_parse_arguments(ARG "NO_RUNTIME" "LINKER_SCRIPT" "SOURCES;INCLUDES;DEFINES;DEPENDS" ${ARGN})
  set(ldscript ${PSX_GUEST_DIR}/psx.ld)
  if(ARG_LINKER_SCRIPT)
    set(ldscript ${ARG_LINKER_SCRIPT})
  endif()
  set(srcs ${ARG_SOURCES})
  if(NOT ARG_NO_RUNTIME)
    list(PREPEND srcs ${PSX_RUNTIME_SOURCES})
  endif()
  set(incs -I${PSX_GUEST_DIR}/include)
  foreach(dir ${ARG_INCLUDES})
    list(APPEND incs -I${dir})
  endforeach()
  set(defs)
  foreach(def ${ARG_DEFINES})
    list(APPEND defs -D${def})
  endforeach()
  set(objs)
  # Each object's header dependencies come from the compiler's -MMD depfile, so editing a header
  # (e.g. Tumble's contract.h) rebuilds every object that includes it; IMPLICIT_DEPENDS would
  # only work with Makefile generators, and the build uses Ninja.
  foreach(src ${srcs})
    get_filename_component(name ${src} NAME)
    set(obj ${CMAKE_CURRENT_BINARY_DIR}/${target}.dir/${name}.o)
    add_custom_command(OUTPUT ${obj}
      COMMAND ${CMAKE_COMMAND} -E make_directory ${CMAKE_CURRENT_BINARY_DIR}/${target}.dir
      COMMAND ${PSX_CC} ${PSX_CFLAGS} ${incs} ${defs} -MMD -MF ${obj}.d -c ${src} -o ${obj}
      DEPENDS ${src} ${ARG_DEPENDS}
      DEPFILE ${obj}.d
      COMMENT "PSX cc ${name}" VERBATIM)
    list(APPEND objs ${obj})
  endforeach()
  set(elf ${CMAKE_CURRENT_BINARY_DIR}/${target}.elf)
  set(exe ${CMAKE_CURRENT_BINARY_DIR}/${target}.exe)
  add_custom_command(OUTPUT ${exe}
    COMMAND ${PSX_CC} ${PSX_CFLAGS} ${PSX_LDFLAGS} -Wl,-T,${ldscript} ${objs} -o ${elf}
    COMMAND psxexe ${elf} ${exe}
    DEPENDS ${objs} psxexe ${ldscript}
    COMMENT "PSX link ${target}.exe" VERBATIM)
  add_custom_target(${target} ALL DEPENDS ${exe})
endfunction()

# psx_add_rom_image(<target> SOURCES <files...> LINKER_SCRIPT <ld> [DEPENDS <headers...>]) builds
# a 512 KiB raw ROM image ${CMAKE_CURRENT_BINARY_DIR}/<target>.bin (code linked at 0xBFC00000,
# padded with zeros). The linker script places .data/.bss; the ROM's start-up code copies .data
# from its load address in the ROM to RAM and clears .bss (e.g. tests/roms/cdboot/).
find_program(PSX_OBJCOPY mipsel-linux-gnu-objcopy REQUIRED)
function(psx_add_rom_image target)
  cmake_parse_arguments(ARG "" "LINKER_SCRIPT" "SOURCES;DEPENDS" ${ARGN})
  set(elf ${CMAKE_CURRENT_BINARY_DIR}/${target}.elf)
  set(bin ${CMAKE_CURRENT_BINARY_DIR}/${target}.bin)
  add_custom_command(OUTPUT ${bin}
    COMMAND ${PSX_CC} ${PSX_CFLAGS} -I${PSX_GUEST_DIR}/include -nostdlib -static -Wl,--build-id=none
            -Wl,-T,${ARG_LINKER_SCRIPT} ${ARG_SOURCES} -o ${elf}
    COMMAND ${PSX_OBJCOPY} -O binary ${elf} ${bin}
    COMMAND truncate -s 524288 ${bin}
    DEPENDS ${ARG_SOURCES} ${ARG_LINKER_SCRIPT} ${ARG_DEPENDS}
    COMMENT "PSX ROM ${target}.bin" VERBATIM)
  add_custom_target(${target} ALL DEPENDS ${bin})
endfunction()
