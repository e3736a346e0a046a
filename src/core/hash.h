// A content hash for provenance: which text a run or a genome file was made
// from (an edited config, genome or motif file shows as another hash). Not a
// security measure.
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>

namespace bx {

/// FNV-1a, 64 bits, of `text`, as 16 lower-case hex digits.
inline std::string fnv1a64_hex(std::string_view text) {
  std::uint64_t h = 14695981039346656037ull;
  for (unsigned char c : text) h = (h ^ c) * 1099511628211ull;
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
  return buf;
}

}  // namespace bx
