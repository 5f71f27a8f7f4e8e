// The stop conditions of a render and the series it records (server/render/prepare/convergence.h).
#include "render/prepare/convergence.h"

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

namespace geodesic {
namespace {

TEST(StopCondition, SppStopsAtTheCountAndNotBefore) {
  StopCondition stop;
  stop.spp = 64;
  EXPECT_FALSE(stop.reached({10.0, 63, 0.001}));
  EXPECT_TRUE(stop.reached({0.1, 64, -1}));
  EXPECT_STREQ(stop.met({0.1, 70, 0.5}), "spp");
  EXPECT_DOUBLE_EQ(stop.progress({1.0, 16, 0.1}), 0.25);
}

TEST(StopCondition, SecondsStopAtTheTimeWhateverTheSamples) {
  StopCondition stop;
  stop.seconds = 2.0;
  EXPECT_FALSE(stop.reached({1.99, 100000, 0.0001}));
  EXPECT_STREQ(stop.met({2.0, 1, -1}), "seconds");
  EXPECT_DOUBLE_EQ(stop.progress({0.5, 1, -1}), 0.25);
  EXPECT_DOUBLE_EQ(stop.progress({3.0, 1, -1}), 1.0);  // clamped
}

TEST(StopCondition, TargetErrorNeedsAKnownEstimateFromAtLeastEightSamples) {
  StopCondition stop;
  stop.target_error = 0.05;
  EXPECT_FALSE(stop.reached({1.0, 4, 0.01}));    // too few samples to trust the estimate
  EXPECT_FALSE(stop.reached({1.0, 16, -1}));     // no estimate yet
  EXPECT_FALSE(stop.reached({1.0, 16, 0.051}));  // above the target
  EXPECT_STREQ(stop.met({1.0, 8, 0.05}), "target_error");  // at the target counts
  // Error falls as 1/sqrt(spp): at twice the target, a quarter of the samples are done.
  EXPECT_DOUBLE_EQ(stop.progress({1.0, 16, 0.1}), 0.25);
  EXPECT_DOUBLE_EQ(stop.progress({1.0, 1, -1}), 0.0);
}

TEST(StopCondition, TheFirstConditionMetEndsTheRender) {
  StopCondition stop;
  stop.spp = 100;
  stop.seconds = 5;
  EXPECT_EQ(stop.met({1, 50, 0.1}), nullptr);
  EXPECT_STREQ(stop.met({6, 50, 0.1}), "seconds");
  EXPECT_DOUBLE_EQ(stop.progress({4, 50, 0.1}), 0.8);  // the nearer of 50 % and 80 %
}

TEST(StopCondition, JsonNamesEveryLimitAndNullsTheUnset) {
  StopCondition stop;
  stop.target_error = 0.02;
  const nlohmann::ordered_json j = stop.to_json();
  EXPECT_TRUE(j.at("spp").is_null());
  EXPECT_TRUE(j.at("seconds").is_null());
  EXPECT_DOUBLE_EQ(j.at("target_error").get<double>(), 0.02);
}

ConvergenceLog three_points() {
  ConvergenceLog log;
  log.record({0.25, 1, -1});
  log.record({0.5, 3, 0.2});
  log.record({1.5, 7, 0.125});
  return log;
}

TEST(ConvergenceLog, JsonSeriesHasOneObjectPerPointAndNullBeforeAnEstimate) {
  const nlohmann::ordered_json j = three_points().to_json();
  const auto& series = j.at("series");
  ASSERT_EQ(series.size(), 3u);
  EXPECT_DOUBLE_EQ(series[0].at("seconds").get<double>(), 0.25);
  EXPECT_EQ(series[0].at("spp").get<int>(), 1);
  EXPECT_TRUE(series[0].at("estimated_error").is_null());
  EXPECT_EQ(series[2].at("spp").get<int>(), 7);
  EXPECT_DOUBLE_EQ(series[2].at("estimated_error").get<double>(), 0.125);
  std::vector<std::string> keys;
  for (const auto& [key, value] : series[1].items()) keys.push_back(key);
  EXPECT_EQ(keys, (std::vector<std::string>{"seconds", "spp", "estimated_error"}));
}

TEST(ConvergenceLog, CsvHasAHeaderAndOneRowPerPointWithAnEmptyUnknownError) {
  std::istringstream csv(three_points().to_csv());
  std::vector<std::string> lines;
  for (std::string line; std::getline(csv, line);) lines.push_back(line);
  ASSERT_EQ(lines.size(), 4u);
  EXPECT_EQ(lines[0], "seconds,spp,estimated_error");
  EXPECT_EQ(lines[1], "0.250000,1,");
  EXPECT_EQ(lines[2], "0.500000,3,0.2");
  EXPECT_EQ(lines[3], "1.500000,7,0.125");
}

TEST(ConvergenceLog, AnEmptyLogIsAHeaderAndAnEmptySeries) {
  const ConvergenceLog log;
  EXPECT_TRUE(log.empty());
  EXPECT_EQ(log.to_csv(), "seconds,spp,estimated_error\n");
  EXPECT_TRUE(log.to_json().at("series").empty());
}

}  // namespace
}  // namespace geodesic
