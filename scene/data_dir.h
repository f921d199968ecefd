// Where ivv's shipped data is found: the reference tables (*.csv with their provenance notes)
// and the scenes (scenes/NAME.toml), laid out as reference_data/ in the source tree and as
// <prefix>/share/ivv once installed.
//
// data_directories() lists, in order:
//   1. $IVV_DATA_DIR, when set and non-empty (the user's own data, or a moved installation);
//   2. the share/ivv of an installed ivv package, for a program built against it: the imported
//      targets of find_package(ivv) define IVV_PACKAGE_DATA_DIR (computed from where the package
//      was found, so an installation can be moved), and including this header adds it;
//   3. <exe>/../share/ivv: the ivv program installed as <prefix>/bin/ivv, and every program of
//      the build tree (<build>/<dir>/<exe>), where <build>/share/ivv links to reference_data/.
// No source-tree path is compiled into the libraries.
#pragma once

#include <filesystem>
#include <vector>

namespace ivv {

std::vector<std::filesystem::path> data_directories();

// Adds `dir` to the directories searched after $IVV_DATA_DIR (repeated calls add nothing new).
void add_data_directory(const std::filesystem::path& dir);

#ifdef IVV_PACKAGE_DATA_DIR
namespace detail {
// One registration per program (an inline variable has one definition across the program).
inline const bool package_data_directory_added = (add_data_directory(IVV_PACKAGE_DATA_DIR), true);
}  // namespace detail
#endif

}  // namespace ivv
