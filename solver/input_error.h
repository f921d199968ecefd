// Bad input: one error type for every user-facing validation failure (SPEC §7).
//
// An InputError names the field at fault and says what is accepted. The command line maps it
// to exit code 2 with the message on stderr and writes no output file.
#pragma once

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace ivv {

class InputError : public std::runtime_error {
 public:
  // `field` is the dotted name the user typed (e.g. "impactor.mass" or "--v0");
  // `message` says what was wrong and what range is accepted.
  InputError(std::string field, const std::string& message)
      : std::runtime_error(field + ": " + message), field_(std::move(field)) {}
  const std::string& field() const { return field_; }

 private:
  std::string field_;
};

// Throws InputError(field, "must be <range>, got <value>") unless `ok`.
inline void require(bool ok, const std::string& field, const std::string& range, double value) {
  if (ok) return;
  std::ostringstream os;
  os << "must be " << range << ", got " << value;
  throw InputError(field, os.str());
}

// The most common precondition: a finite number > 0.
inline void require_positive(const std::string& field, double value) {
  require(std::isfinite(value) && value > 0.0, field, "positive and finite", value);
}

}  // namespace ivv
