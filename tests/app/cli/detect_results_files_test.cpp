// `detect --json` and `--csv` are the core's results writers: the files the CLI writes equal
// what core/report makes of the same document, and the summary's sigma is the sample sigma.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <vector>

#include "core/report/results_csv.h"
#include "core/report/results_json.h"
#include "core/report/statistics.h"
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

  write_detection_json(tmp.file("core.json"), doc);
  EXPECT_EQ(slurp(tmp.file("core.json")), json_text);
  EXPECT_EQ(detection_csv(doc), csv_text);
  write_detection_csv(tmp.file("core.csv"), doc);
  EXPECT_EQ(slurp(tmp.file("core.csv")), csv_text);

  // The CSV carries the JSON's values: header and one "ok" row per frame.
  EXPECT_EQ(count_lines(csv_text), 4);
  const std::string row0 = csv_text.substr(csv_text.find('\n') + 1);
  EXPECT_EQ(row0.rfind("0," + doc["frames"][0]["source"].get<std::string>() + ",pgc,1,ok," +
                           doc["frames"][0]["width_m"].dump() + "," + doc["frames"][0]["height_m"].dump() +
                           ",measured,measured,",
                       0),
            0u)
      << row0;

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
