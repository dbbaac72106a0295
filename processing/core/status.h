// Status and Result<T>: how every library function reports a recoverable failure.
// Library code never prints or exits; converter/ maps ErrorCode to exit codes.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <variant>

namespace mocapfill {

enum class ErrorCode {
  kOk = 0,
  kInvalidArgument,   // bad options or usage (exit 1)
  kInvalidData,       // file content is malformed (exit 2)
  kUnsupported,       // valid but not handled by this tool (exit 2)
  kIoError,           // cannot read or write a file (input: exit 2, output: exit 4)
  kNumericalFailure,  // solver or NaN trouble while processing (exit 3)
  kInternal,          // a bug of ours (exit 3)
};

const char* ErrorCodeName(ErrorCode code);

class Status {
 public:
  Status() = default;
  Status(ErrorCode code, std::string message) : code_(code), message_(std::move(message)) {}

  bool ok() const { return code_ == ErrorCode::kOk; }
  ErrorCode code() const { return code_; }
  const std::string& message() const { return message_; }

  // Returns a copy whose message is "context: message", so errors read as a chain
  // from the outermost caller to the failing detail ("walk.bvh: line 12: ...").
  Status WithContext(const std::string& context) const {
    if (ok()) return *this;
    return Status(code_, context + ": " + message_);
  }

 private:
  ErrorCode code_ = ErrorCode::kOk;
  std::string message_;
};

inline Status OkStatus() { return Status(); }
inline Status InvalidArgument(std::string m) { return Status(ErrorCode::kInvalidArgument, std::move(m)); }
inline Status InvalidData(std::string m) { return Status(ErrorCode::kInvalidData, std::move(m)); }
inline Status Unsupported(std::string m) { return Status(ErrorCode::kUnsupported, std::move(m)); }
inline Status IoError(std::string m) { return Status(ErrorCode::kIoError, std::move(m)); }
inline Status NumericalFailure(std::string m) { return Status(ErrorCode::kNumericalFailure, std::move(m)); }
inline Status Internal(std::string m) { return Status(ErrorCode::kInternal, std::move(m)); }

// A value or a failed Status. Accessing value() of a failed result is a programming error.
template <typename T>
class Result {
 public:
  Result(T value) : value_(std::move(value)) {}       // NOLINT: implicit by design
  Result(Status status) : status_(std::move(status)) {}  // NOLINT: implicit by design

  bool ok() const { return status_.ok(); }
  const Status& status() const { return status_; }
  T& value() & { return *value_; }
  const T& value() const& { return *value_; }
  T&& value() && { return std::move(*value_); }
  T* operator->() { return &*value_; }
  const T* operator->() const { return &*value_; }
  T& operator*() { return *value_; }
  const T& operator*() const { return *value_; }

 private:
  std::optional<T> value_;
  Status status_;
};

}  // namespace mocapfill

#define MOCAPFILL_CONCAT_INNER(a, b) a##b
#define MOCAPFILL_CONCAT(a, b) MOCAPFILL_CONCAT_INNER(a, b)

// Returns the Status from the enclosing function when expr (a Status) is not ok.
#define RETURN_IF_ERROR(expr)                          \
  do {                                                 \
    ::mocapfill::Status _status_tmp = (expr);          \
    if (!_status_tmp.ok()) return _status_tmp;         \
  } while (0)

// Declares lhs from a Result<T> expression or returns its Status.
#define ASSIGN_OR_RETURN(lhs, expr) \
  ASSIGN_OR_RETURN_IMPL(MOCAPFILL_CONCAT(_result_tmp_, __LINE__), lhs, expr)
#define ASSIGN_OR_RETURN_IMPL(tmp, lhs, expr) \
  auto tmp = (expr);                          \
  if (!tmp.ok()) return tmp.status();         \
  lhs = std::move(tmp).value()
