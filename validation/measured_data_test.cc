// The data reader: the accepted format and every kind of malformed file (named line, column).
#include "validation/measured_data.h"

#include <gtest/gtest.h>

#include "scene/input_error.h"

namespace ivv::validation {
namespace {

// The field of the InputError parsing `text` throws ("" if none).
std::string error_field(const std::string& text) {
  try {
    parse_measured_data(text, "d.csv");
  } catch (const InputError& e) {
    return e.field();
  }
  return "";
}

TEST(MeasuredData, ReadsColumnsProvenanceAndBlankOptionalCells) {
  const auto d = parse_measured_data(
      "# drop tower, lab A\n\nv0, e ,u_e,F_max\n# mid-file note\n1.0,0.8,0.01,\n2,0.7,0.02,350\n",
      "d.csv");
  ASSERT_EQ(d.points.size(), 2u);
  EXPECT_EQ(d.provenance.size(), 2u);
  EXPECT_EQ(d.provenance[0], "drop tower, lab A");
  EXPECT_TRUE(d.has_uncertainty[0]);
  EXPECT_TRUE(d.has_quantity[1]);
  EXPECT_FALSE(d.has_uncertainty[1]);
  EXPECT_FALSE(d.points[0].value[1].has_value());
  EXPECT_DOUBLE_EQ(*d.points[1].value[1], 350);
  EXPECT_EQ(d.points[1].line, 6);
  EXPECT_EQ(d.count(Quantity::F_max), 1u);
}

// A column blank in every row measured nothing: it is absent, so the fit neither counts the
// quantity nor estimates a noise for it from no points (which changed the statistics of e).
TEST(MeasuredData, AnAllBlankOptionalColumnIsAnAbsentColumn) {
  const auto d = parse_measured_data(
      "v0,e,u_e,F_max,u_F_max,t_contact\n0.5,0.9,0.01,,,\n1,0.8,0.01, , ,\n", "d.csv");
  EXPECT_FALSE(d.has_quantity[static_cast<std::size_t>(Quantity::F_max)]);
  EXPECT_FALSE(d.has_uncertainty[static_cast<std::size_t>(Quantity::F_max)]);
  EXPECT_FALSE(d.has_quantity[static_cast<std::size_t>(Quantity::t_contact)]);
  EXPECT_TRUE(d.has_quantity[0] && d.has_uncertainty[0]);
  EXPECT_EQ(to_csv(d), "v0,e,u_e\n0.5,0.90000000000000002,0.01\n1,0.80000000000000004,0.01\n");
}

// Excel's "CSV UTF-8" begins with a byte-order mark; classic Mac line ends are a lone CR.
TEST(MeasuredData, ReadsAByteOrderMarkAndEveryLineEnd) {
  for (const std::string text :
       {"\xEF\xBB\xBFv0,e\n1,0.8\n2,0.7\n", "v0,e\r1,0.8\r2,0.7\r", "v0,e\r\n1,0.8\r\n2,0.7\r\n"}) {
    const auto d = parse_measured_data(text, "d.csv");
    ASSERT_EQ(d.points.size(), 2u);
    EXPECT_EQ(d.points[1].line, 3);
  }
  try {
    parse_measured_data("v0,e\r1,x\r", "d.csv");
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).find('\r'), std::string::npos) << e.what();
    EXPECT_EQ(e.field(), "d.csv:2:e");
  }
}

TEST(MeasuredData, RoundTripsThroughCsv) {
  const auto d = parse_measured_data("# p\nv0,e,u_e\n0.5,0.9123456789012345,0.01\n", "d.csv");
  const auto again = parse_measured_data(to_csv(d), "d.csv");
  ASSERT_EQ(again.points.size(), 1u);
  EXPECT_EQ(*again.points[0].value[0], *d.points[0].value[0]);
  EXPECT_EQ(again.provenance, d.provenance);
}

TEST(MeasuredData, MalformedFilesNameLineAndColumn) {
  EXPECT_EQ(error_field("v0,e\n1,abc\n"), "d.csv:2:e");
  EXPECT_EQ(error_field("v0,e\n-1,0.5\n"), "d.csv:2:v0");
  EXPECT_EQ(error_field("v0,e\n1,0.5\n2,0.5,3\n"), "d.csv:3");
  EXPECT_EQ(error_field("v0,e,u_e\n1,0.5,\n"), "d.csv:2:u_e");   // blank u beside a value
  EXPECT_EQ(error_field("v0,e,u_e\n1,0.5,0\n"), "d.csv:2:u_e");  // u must be > 0
  EXPECT_EQ(error_field("v0,e\n1,\n"), "d.csv:2:e");             // e is required
  EXPECT_EQ(error_field("v0,e,u_E\n1,0.5,1\n"), "d.csv:1:3");    // unknown column
  EXPECT_EQ(error_field("v0,u_e\n1,0.5\n"), "d.csv:1");          // e missing
  EXPECT_EQ(error_field("v0,e,v0\n1,0.5,1\n"), "d.csv:1:3");     // twice
  EXPECT_EQ(error_field("v0,e,u_F_max\n1,0.5,1\n"), "d.csv:1");  // u without its quantity
  EXPECT_EQ(error_field("# only provenance\n"), "d.csv");
  EXPECT_EQ(error_field("v0,e\n"), "d.csv");
  EXPECT_EQ(error_field("v0,e\n1,0.5x\n"), "d.csv:2:e");
  EXPECT_EQ(error_field("v0,e\n1,inf\n"), "d.csv:2:e");
}

TEST(MeasuredData, MissingFileIsBadInputNamingTheFlag) {
  try {
    read_measured_data("/nonexistent/x.csv");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "--data");
  }
}

}  // namespace
}  // namespace ivv::validation
