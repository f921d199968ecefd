// Parsing of the command line's value lists: "LO:HI:N" ranges and "a,b,c" lists.
#pragma once

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace ivv {

// "LO:HI:N" (n points, inclusive; log spacing when `log`) or a comma-separated list.
// Throws InputError naming `field` with the accepted syntax.
std::vector<double> parse_grid(const std::string& text, const std::string& field, bool log);

// "NAME=VALUE" items of --param into a map; throws InputError("--param", ...) for a malformed
// item, a value that is not a finite number, or a name given twice.
std::map<std::string, double, std::less<>> parse_parameters(const std::vector<std::string>& items);

}  // namespace ivv
