// Parsing of the command line's value lists: "LO:HI:N" ranges and "a,b,c" lists.
#pragma once

#include <string>
#include <vector>

namespace ivv {

// "LO:HI:N" (n points, inclusive; log spacing when `log`) or a comma-separated list.
// Throws InputError naming `field` with the accepted syntax.
std::vector<double> parse_grid(const std::string& text, const std::string& field, bool log);

}  // namespace ivv
