// `detect --json` and `--csv` are the core's results writers, both fed the same typed records:
// every CSV cell equals the JSON's value, and the summary's sigma is the sample sigma.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <sstream>
#include <vector>

#include "core/report/statistics.h"
#include "core/util/build_paths.h"
#include "tests/support/cli_runner.h"

using namespace tunnelmap;
using namespace tunnelmap::testing;

namespace {
const std::string kSample = std::string(TUNNELMAP_SOURCE_DIR) + "/resources/sample/lab";
}  // namespace

TEST(CliResultsFiles, DetectJsonAndCsvAreTheCoreWriters) {
  IoTempDir tmp;
  const CliRun r = run_cli("detect " + kSample + " -q --json " + tmp.file("r.json") + " --csv " + tmp.file("r.csv"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string json_text = slurp(tmp.file("r.json"));
  const std::string csv_text = slurp(tmp.file("r.csv"));
  const nlohmann::json doc = nlohmann::json::parse(json_text);
  ASSERT_EQ(doc["frames"].size(), 3u);

  // The two writers read the same records: every CSV cell is the JSON's value, written as the
  // JSON writes it (an unknown value: null there, an empty cell here).
  EXPECT_EQ(count_lines(csv_text), 4);
  std::istringstream rows(csv_text);
  std::string row;
  std::getline(rows, row);
  EXPECT_EQ(row, "index,source,method,detected,status,width_m,height_m,width_source,height_source,planes,total_ms,reason");
  for (const auto& f : doc["frames"]) {
    ASSERT_TRUE(std::getline(rows, row));
    const auto cell = [](const nlohmann::json& v) {
      if (v.is_null()) return std::string();
      if (!v.is_string()) return v.dump();
      const std::string s = v.get<std::string>();
      if (s.find_first_of(",\"") == std::string::npos) return s;
      std::string quoted = "\"";  // RFC 4180
      for (char c : s) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
      return quoted + "\"";
    };
    const std::string expected = std::to_string(f["index"].get<int>()) + "," + cell(f["source"]) + ",pgc," +
                                 (f["detected"].get<bool>() ? "1," : "0,") + cell(f["status"]) + "," +
                                 cell(f["width_m"]) + "," + cell(f["height_m"]) + "," + cell(f["width_source"]) +
                                 "," + cell(f["height_source"]) + "," + cell(f["planes"]) + "," +
                                 cell(f["timings_ms"]["total"]) + "," + cell(f.value("reason", nlohmann::json()));
    EXPECT_EQ(row, expected);
  }

  // Summary sigma: the sample sigma of the frames' widths (each rounded to 0.01 mm in the JSON).
  std::vector<double> widths, heights;
  for (const auto& f : doc["frames"]) {
    widths.push_back(f["width_m"].get<double>());
    heights.push_back(f["height_m"].get<double>());
  }
  EXPECT_NEAR(doc["summary"]["width_std_m"].get<double>(), mean_sigma(widths).sigma, 2e-5);
  EXPECT_NEAR(doc["summary"]["height_std_m"].get<double>(), mean_sigma(heights).sigma, 2e-5);
  EXPECT_GT(doc["summary"]["width_std_m"].get<double>(), 0.0);
}
