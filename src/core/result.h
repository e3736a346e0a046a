// Result<T>: a value or an error message, for failures that are the user's
// input (a bad genome, config or file) rather than the program's bug.
#pragma once

#include <cassert>
#include <optional>
#include <string>
#include <utility>

namespace bx {

/// An error meant for a user: one line naming the file, field and value.
struct Error {
  std::string message;
};

/// Either a T or an Error. Callers check `ok()` before `value()`.
template <class T>
class Result {
 public:
  Result(T value) : value_(std::move(value)) {}          // NOLINT: implicit by design
  Result(Error error) : error_(std::move(error.message)) {}  // NOLINT
  bool ok() const { return value_.has_value(); }
  explicit operator bool() const { return ok(); }
  T& value() {
    assert(ok());
    return *value_;
  }
  const T& value() const {
    assert(ok());
    return *value_;
  }
  T* operator->() { return &value(); }
  const T* operator->() const { return &value(); }
  T& operator*() { return value(); }
  const T& operator*() const { return value(); }
  const std::string& error() const { return error_; }

 private:
  std::optional<T> value_;
  std::string error_;
};

/// Result of an operation with no value.
struct Ok {};
using Status = Result<Ok>;

}  // namespace bx
