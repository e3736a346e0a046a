// Whole-file reads and atomic writes: a reader never sees half a file, and a
// failed write leaves any earlier file untouched.
#pragma once

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>

#include "core/result.h"

namespace bx {

/// The whole content of a file, or an error naming the path and the reason.
inline Result<std::string> read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return Error{path + ": cannot open: " + std::strerror(errno)};
  std::ostringstream ss;
  ss << in.rdbuf();
  if (in.bad()) return Error{path + ": read failed"};
  return ss.str();
}

/// Writes `content` to `path.tmp.<pid>`, flushes it, then renames it over `path`.
inline Status write_file_atomic(const std::string& path, const std::string& content) {
  std::string tmp = path + ".tmp." + std::to_string(::getpid());
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) return Error{path + ": cannot write: " + std::strerror(errno)};
    out << content;
    out.flush();
    if (!out) {
      std::remove(tmp.c_str());
      return Error{path + ": write failed"};
    }
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    int e = errno;
    std::remove(tmp.c_str());
    return Error{path + ": cannot write: " + std::strerror(e)};
  }
  return Ok{};
}

}  // namespace bx
