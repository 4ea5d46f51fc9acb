// The last step of a memory search: the addresses found, written out as the variables of a new
// game integration (games/<name>/game.toml), with the rest of the manifest filled in with the
// seed's defaults to edit, ready for the Lua parts (docs/integrating-a-game.md).
#pragma once
#include <string>
#include <vector>

#include "memsearch/search.h"
#include "memsearch/session.h"

namespace psxrl::memsearch {

struct FoundVariable {
  std::string name;
  psx::u32 address = 0;
  Encoding encoding = Encoding::U32;
};

// Parses NAME=ADDRESS:ENCODING (e.g. score=0x8001000C:u32). Throws QueryError.
FoundVariable parse_found_variable(const std::string& text);

// The manifest text. Throws QueryError for a variable the integration format cannot read (big
// endian, BCD or outside main RAM: those need a Lua getter) or a name it does not allow.
std::string integration_skeleton(const std::string& name, const SessionSource& source,
                                 const std::vector<FoundVariable>& vars);

// Writes <dir>/game.toml (atomically); refuses to overwrite an existing manifest.
void write_integration_skeleton(const std::string& dir, const std::string& name, const SessionSource& source,
                                const std::vector<FoundVariable>& vars);

}  // namespace psxrl::memsearch
