// Readers for the CSV tables in reference_data/ (provenance notes beside each table there).
//
// Each table is plain CSV with a header row naming its columns (fast-cpp-csv-parser,
// io::CSVReader). A missing or extra column, a malformed number or a short row throws
// ReferenceTableError whose message names the file, the line and the column.
//
// reference_data_dir() is the first of ivv::data_directories() (scene/data_dir.h: $IVV_DATA_DIR,
// an installed package's share/ivv, <exe>/../share/ivv) that exists; ReferenceTableError naming
// the places searched when none does.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "scene/data_dir.h"

namespace ivv::oracles {

class ReferenceTableError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

std::filesystem::path reference_data_dir();

// thornton_1997.csv: r = V_y/V_i [-], e_thornton [-].
struct ThorntonRow {
  double r = 0.0;
  double e = 0.0;
};
std::vector<ThorntonRow> read_thornton_table(const std::filesystem::path& file);

// hunt_crossley_mu_maps.csv: model (damping map name), e_target [-], u0 = mu v0 [-],
// e_delivered [-] (exact Hunt-Crossley COR at u0).
struct HuntCrossleyMapRow {
  std::string model;
  double e_target = 0.0;
  double u0 = 0.0;
  double e_delivered = 0.0;
};
std::vector<HuntCrossleyMapRow> read_hunt_crossley_map_table(const std::filesystem::path& file);

// kuwabara_kono_pade.csv: v_star [-], e_pade [-], e_series [-].
struct KuwabaraKonoRow {
  double v_star = 0.0;
  double e_pade = 0.0;
  double e_series = 0.0;
};
std::vector<KuwabaraKonoRow> read_kuwabara_kono_table(const std::filesystem::path& file);

}  // namespace ivv::oracles
