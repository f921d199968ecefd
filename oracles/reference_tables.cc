#include "oracles/reference_tables.h"

// csv.h copies file names with strncpy into fixed buffers; once inlined here GCC's
// -Wstringop-truncation flags that library code (the truncation is intended and
// NUL-terminated there). Silenced for this translation unit only.
#pragma GCC diagnostic ignored "-Wstringop-truncation"
#include <libfccp/csv.h>

#include <cstdlib>
#include <exception>
#include <fstream>
#include <string_view>
#include <system_error>

namespace ivv::oracles {

namespace {

// Opens the file first so that a missing file gets the same error type as a malformed one,
// then runs `read(reader)` translating every parser error (whose message already names the
// file, line and column) into ReferenceTableError.
template <unsigned N, class Row, class ReadRow, class... Columns>
std::vector<Row> read_table(const std::filesystem::path& file, ReadRow read_row,
                            Columns... columns) {
  if (!std::ifstream(file)) {
    throw ReferenceTableError("reference table \"" + file.string() + "\": cannot open file");
  }
  std::vector<Row> rows;
  try {
    io::CSVReader<N> reader(file.string());
    reader.read_header(io::ignore_no_column, columns...);
    Row row;
    while (read_row(reader, row)) rows.push_back(row);
  } catch (const io::error::base& err) {
    throw ReferenceTableError(std::string("reference table: ") + err.what());
  }
  if (rows.empty()) {
    throw ReferenceTableError("reference table \"" + file.string() + "\": no data rows");
  }
  return rows;
}

}  // namespace

std::filesystem::path reference_data_dir() {
  std::string searched;
  for (const auto& dir : data_directories()) {
    std::error_code ec;
    if (std::filesystem::is_directory(dir, ec)) return dir;
    searched += (searched.empty() ? "" : ", ") + dir.string();
  }
  throw ReferenceTableError("reference data: no data directory found (searched " + searched +
                            "; set IVV_DATA_DIR to the directory holding thornton_1997.csv)");
}

std::vector<ThorntonRow> read_thornton_table(const std::filesystem::path& file) {
  return read_table<2, ThorntonRow>(
      file, [](io::CSVReader<2>& in, ThorntonRow& row) { return in.read_row(row.r, row.e); }, "r",
      "e_thornton");
}

std::vector<HuntCrossleyMapRow> read_hunt_crossley_map_table(const std::filesystem::path& file) {
  return read_table<4, HuntCrossleyMapRow>(
      file,
      [](io::CSVReader<4>& in, HuntCrossleyMapRow& row) {
        return in.read_row(row.model, row.e_target, row.u0, row.e_delivered);
      },
      "model", "e_target", "u0", "e_delivered");
}

std::vector<KuwabaraKonoRow> read_kuwabara_kono_table(const std::filesystem::path& file) {
  return read_table<3, KuwabaraKonoRow>(
      file,
      [](io::CSVReader<3>& in, KuwabaraKonoRow& row) {
        return in.read_row(row.v_star, row.e_pade, row.e_series);
      },
      "v_star", "e_pade", "e_series");
}

}  // namespace ivv::oracles
