/* LoadExec of a file that is no PS-X EXE (DATA.BIN, letters): the HLE kernel stops the run with
   a message naming the file and what its header lacks, instead of starting garbage. */
#include "bios_exec_calls.h"

int main(void) {
  load_exec("cdrom:\\data.bin", 0, 0);
  return 1;
}
