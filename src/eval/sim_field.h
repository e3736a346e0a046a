// A config key that a row of the creature or task table brings with it: where
// it lives in SimConfig and what it accepts. The config reader (io/config.h)
// reads, writes and documents these beside its own keys, so a new system's
// keys live with its row, not in the reader.
#pragma once

#include <functional>
#include <string_view>
#include <vector>

#include "eval/sim_config.h"

namespace bx {

struct SimField {
  std::string_view section;
  std::string_view key;
  enum Kind {
    Real,    ///< double
    Int,     ///< int
    Choice,  ///< an enum (int-sized) named by `choices`
    Triple,  ///< std::array<double, 3>
    Text,    ///< std::string, one line without control characters
    Reals,   ///< std::vector<double>: an array of any length
  } kind;
  double lo, hi;                          ///< inclusive range (Real, Int, each of a Triple's or Reals')
  std::vector<std::string_view> choices;  ///< Choice: names, by enum value
  std::function<void*(SimConfig&)> at;    ///< the field's address
  std::string_view doc;                   ///< one line for docs/config.md
};

}  // namespace bx
