// Whole-file reads and atomic writes: a reader never sees half a file, and a
// failed write leaves any earlier file untouched.
#pragma once

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>

#include "core/result.h"

namespace bx {

/// The whole content of a file, or an error naming the path and the reason.
inline Result<std::string> read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return Error{path + ": cannot open file (" + std::strerror(errno) + ")"};
  std::ostringstream ss;
  ss << in.rdbuf();
  if (in.bad()) return Error{path + ": cannot read file (" + std::strerror(errno) + ")"};
  return ss.str();
}

/// Writes `content` to `path.tmp`, flushes it to disk, then renames it over
/// `path`. On failure nothing is left behind and any old `path` is intact.
inline Status write_file_atomic(const std::string& path, const std::string& content) {
  std::string tmp = path + ".tmp";
  std::FILE* f = std::fopen(tmp.c_str(), "wb");
  if (!f) return Error{path + ": cannot write file (" + std::strerror(errno) + ")"};
  bool ok = std::fwrite(content.data(), 1, content.size(), f) == content.size();
  ok = std::fflush(f) == 0 && ok;
  ok = ::fsync(::fileno(f)) == 0 && ok;
  int err = errno;
  ok = std::fclose(f) == 0 && ok;
  if (!ok) {
    std::remove(tmp.c_str());
    return Error{path + ": cannot write file (" + std::strerror(err) + ")"};
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    err = errno;
    std::remove(tmp.c_str());
    return Error{path + ": cannot replace file (" + std::strerror(err) + ")"};
  }
  return Ok{};
}

}  // namespace bx
