// ISO 9660 file lookup on a disc (psx-spx "CDROM ISO Volume Descriptors", "CDROM ISO File and
// Directory Descriptors"): the primary volume descriptor at logical block 16, then directory
// records from the root down. Used by the HLE disc boot to find SYSTEM.CNF and the boot EXE.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "core/disc/disc.h"

namespace psx::disc {

struct IsoEntry {
  std::string name;  // without the ";1" version suffix
  u32 lba = 0;       // logical block (0 = absolute sector 00:02:00)
  u32 size = 0;      // bytes
  bool directory = false;
};

class IsoFilesystem {
 public:
  // Reads the primary volume descriptor; throws DiscError when the disc has no valid one.
  explicit IsoFilesystem(Disc& disc);

  const std::string& volume_id() const { return volume_id_; }
  const IsoEntry& root() const { return root_; }

  // Finds "cdrom:\DIR\NAME.EXT;1", "\NAME.EXT" or "DIR/NAME.EXT" (case-insensitive, version
  // suffix optional). Returns nothing when a component does not exist.
  std::optional<IsoEntry> find(const std::string& path);
  // The records of a directory, "." and ".." left out. Throws DiscError on a malformed record.
  std::vector<IsoEntry> list(const IsoEntry& dir);
  // A file's contents; throws DiscError when a sector cannot be read or the file exceeds max_size.
  std::vector<u8> read(const IsoEntry& file, u32 max_size);

 private:
  // The 2048 user-data bytes of logical block `lba` (Mode 1 or Mode 2 Form 1).
  void read_block(u32 lba, u8* out);

  Disc& disc_;
  IsoEntry root_;
  std::string volume_id_;
};

}  // namespace psx::disc
