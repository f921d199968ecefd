// Tests of the reference-table readers, and of the oracles against the tables produced by
// the independent Python scripts in reference_data/.
//
// Tolerance: every number is printed with 13 significant digits (%.12e), so a value is
// known to half a unit of its 13th digit, <= 5e-13 relative; kTableDigits = 1e-12 relative
// adds room for the C++ and Python evaluations rounding differently (a few ulps).
#include "oracles/reference_tables.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <string>

#include "closed_forms/hunt_crossley.h"
#include "oracles/published.h"

namespace ivv::oracles {
namespace {

constexpr double kTableDigits = 1e-12;

void expect_relative(double actual, double expected, const std::string& what) {
  EXPECT_LE(std::abs(actual - expected), kTableDigits * std::abs(expected))
      << what << ": " << actual << " vs table " << expected;
}

TEST(ReferenceTables, Thornton) {
  const auto rows = read_thornton_table(reference_data_dir() / "thornton_1997.csv");
  ASSERT_EQ(rows.size(), 40u);
  EXPECT_EQ(rows.front().r, 1.0);
  EXPECT_NEAR(rows.back().r, 1e-4, 1e-4 * kTableDigits);
  for (const ThorntonRow& row : rows) {
    expect_relative(thornton_cor(row.r), row.e, "Thornton e at r = " + std::to_string(row.r));
  }
}

TEST(ReferenceTables, HuntCrossleyMaps) {
  const auto rows =
      read_hunt_crossley_map_table(reference_data_dir() / "hunt_crossley_mu_maps.csv");
  ASSERT_EQ(rows.size(), 7u * 11u);
  for (const HuntCrossleyMapRow& row : rows) {
    const auto map = closed_forms::find_damping_map(row.model);
    ASSERT_TRUE(map.has_value()) << "unknown model " << row.model;
    const std::string where = row.model + " at e_target " + std::to_string(row.e_target);
    expect_relative(map->mu(row.e_target, 1.0), row.u0, "u0 of " + where);
    expect_relative(closed_forms::delivered_cor(*map, row.e_target), row.e_delivered,
                    "e_delivered of " + where);
  }
}

TEST(ReferenceTables, KuwabaraKono) {
  const auto rows = read_kuwabara_kono_table(reference_data_dir() / "kuwabara_kono_pade.csv");
  ASSERT_EQ(rows.size(), 41u);
  for (const KuwabaraKonoRow& row : rows) {
    const std::string at = " at v* = " + std::to_string(row.v_star);
    expect_relative(kuwabara_kono_pade(row.v_star), row.e_pade, "Pade" + at);
    expect_relative(kuwabara_kono_series(row.v_star), row.e_series, "series" + at);
  }
}

class MalformedTable : public ::testing::Test {
 protected:
  std::filesystem::path write(const std::string& name, const std::string& text) {
    const auto path = std::filesystem::path(::testing::TempDir()) / name;
    std::ofstream(path) << text;
    return path;
  }
};

TEST_F(MalformedTable, BadNumberNamesFileLineAndColumn) {
  const auto path = write("ivv_bad_number.csv", "r,e_thornton\n0.5,0.9\n0.25,zero\n");
  try {
    read_thornton_table(path);
    FAIL() << "expected ReferenceTableError";
  } catch (const ReferenceTableError& err) {
    const std::string what = err.what();
    EXPECT_NE(what.find("ivv_bad_number.csv"), std::string::npos) << what;
    EXPECT_NE(what.find("line \"3\""), std::string::npos) << what;  // fccp quotes numbers
    EXPECT_NE(what.find("e_thornton"), std::string::npos) << what;
  }
}

TEST_F(MalformedTable, MissingColumnAndShortRowAndMissingFile) {
  const auto missing = write("ivv_missing_column.csv", "r\n0.5\n");
  EXPECT_THROW(read_thornton_table(missing), ReferenceTableError);
  const auto short_row = write("ivv_short_row.csv", "r,e_thornton\n0.5\n");
  try {
    read_thornton_table(short_row);
    FAIL() << "expected ReferenceTableError";
  } catch (const ReferenceTableError& err) {
    EXPECT_NE(std::string(err.what()).find("line 2"), std::string::npos) << err.what();
  }
  const auto empty = write("ivv_empty_table.csv", "r,e_thornton\n");
  EXPECT_THROW(read_thornton_table(empty), ReferenceTableError);
  EXPECT_THROW(read_thornton_table("/nonexistent/ivv/table.csv"), ReferenceTableError);
}

// Restores $IVV_DATA_DIR when a test ends.
class ReferenceDataDir : public ::testing::Test {
 protected:
  void SetUp() override {
    const char* saved = std::getenv("IVV_DATA_DIR");
    had_value_ = saved != nullptr;
    if (had_value_) saved_ = saved;
    ::unsetenv("IVV_DATA_DIR");
  }
  void TearDown() override {
    if (had_value_)
      ::setenv("IVV_DATA_DIR", saved_.c_str(), 1);
    else
      ::unsetenv("IVV_DATA_DIR");
  }
  bool had_value_ = false;
  std::string saved_;
};

// The test binary lives in <build>/oracles/, so <exe>/../share/ivv is the build tree's link to
// reference_data/: found without a source path compiled in.
TEST_F(ReferenceDataDir, BuildTreeIsFoundBesideTheExecutable) {
  const auto dir = reference_data_dir();
  EXPECT_EQ(dir.filename(), "ivv");
  EXPECT_EQ(dir.parent_path().filename(), "share");
  EXPECT_TRUE(std::filesystem::exists(dir / "thornton_1997.csv")) << dir;
  EXPECT_TRUE(std::filesystem::exists(dir / "scenes" / "paper-damped.toml")) << dir;
}

TEST_F(ReferenceDataDir, EnvironmentComesFirstWhenItExists) {
  const auto tmp = std::filesystem::temp_directory_path() / "ivv_data_dir_test";
  std::filesystem::create_directories(tmp);
  ::setenv("IVV_DATA_DIR", tmp.c_str(), 1);
  EXPECT_EQ(reference_data_dir(), tmp);
  EXPECT_EQ(data_directories().front(), tmp);
  ::setenv("IVV_DATA_DIR", "/nonexistent/ivv/data", 1);  // skipped: falls back to the build tree
  EXPECT_TRUE(std::filesystem::exists(reference_data_dir() / "thornton_1997.csv"));
}

TEST_F(ReferenceDataDir, AddedDirectoryComesAfterTheEnvironmentBeforeTheExecutable) {
  add_data_directory("/opt/ivv-test/share/ivv");
  add_data_directory("/opt/ivv-test/share/ivv");  // once only
  ::setenv("IVV_DATA_DIR", "/env/dir", 1);
  const auto dirs = data_directories();
  ASSERT_EQ(dirs.size(), 3u);
  EXPECT_EQ(dirs[0], std::filesystem::path("/env/dir"));
  EXPECT_EQ(dirs[1], std::filesystem::path("/opt/ivv-test/share/ivv"));
  EXPECT_EQ(dirs[2].filename(), "ivv");
}

}  // namespace
}  // namespace ivv::oracles
