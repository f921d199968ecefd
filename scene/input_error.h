// Bad input: one error type for every user-facing validation failure (docs/design.md §7).
//
// An InputError names the field at fault and says what is accepted. The command line maps it
// to exit code 2 with the message on stderr and writes no output file.
#pragma once

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>

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

// Throws InputError(field, "must be <range>, got <value>") unless `ok`. Views, so that a
// check that passes builds no string (validation runs once per impact, on the hot path).
inline void require(bool ok, std::string_view field, std::string_view range, double value) {
  if (ok) return;
  std::ostringstream os;
  os << "must be " << range << ", got " << value;
  throw InputError(std::string(field), os.str());
}

// The most common precondition: a finite number > 0.
inline void require_positive(std::string_view field, double value) {
  require(std::isfinite(value) && value > 0.0, field, "positive and finite", value);
}

}  // namespace ivv
