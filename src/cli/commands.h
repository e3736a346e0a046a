// Subcommands of `bestiary`. Each returns the process exit code: 0 on
// success, 2 on bad input (after printing one error line to stderr).
#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace bx {

/// Arguments of `bestiary simulate`.
struct SimulateArgs {
  std::string genome;
  std::string config;
  std::optional<double> seconds;
  std::uint64_t seed = 1;
  std::string replay;
  bool json = false;
};

int cmd_simulate(const SimulateArgs& a);
int cmd_config(const std::string& dialect, const std::string& config_file);

}  // namespace bx
