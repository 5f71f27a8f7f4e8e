// The size of a moving camera's frames (render/service/render_session.h moving_frame_divisor).
#include <gtest/gtest.h>

#include <cmath>

#include "render/service/render_session.h"

using namespace geodesic;

namespace {

// The seconds one sample of the full view takes when a frame divided by `divisor` takes the
// moving frames' time.
double full_sample_for(double divisor) { return kMovingFrameSeconds * divisor * divisor; }

}  // namespace

// A scene whose full-view sample takes 5.4 frame times fits a frame divided by sqrt(5.4) = 2.32:
// the nearest step is 2^(10/8) = 2.38, 215 px of a 512-px view, where whole divisors gave 3,
// 170 px, a frame using 60 % of its time. Every fit between the bounds gets a step within half
// a step of it, so a frame takes its time within 2^(±1/8), ±9 %.
TEST(MovingFrame, TheDivisorIsTheNearestStepToTheFit) {
  EXPECT_DOUBLE_EQ(moving_frame_divisor(full_sample_for(2.32)), std::exp2(10.0 / 8));
  const double half_step = std::exp2(0.5 / kMovingDivisorSteps);
  for (double fit = kMinMovingDivisor; fit <= kMaxMovingDivisor; fit *= 1.013) {
    const double d = moving_frame_divisor(full_sample_for(fit));
    EXPECT_LE(d, fit * half_step * (1 + 1e-12)) << fit;
    EXPECT_GE(d, fit / half_step * (1 - 1e-12)) << fit;
    const double steps = std::log2(d) * kMovingDivisorSteps;
    EXPECT_NEAR(steps, std::round(steps), 1e-9) << fit;
  }
}

// A walk's frames keep their size while the measured cost wavers by a few per cent about a fit
// between steps; one that moves further (the first moving frames, one bounce, against the
// still view's deeper paths) gives the new step at once.
TEST(MovingFrame, AWaveringCostKeepsTheFramesSize) {
  const double fit = std::exp2(19.0 / 8);  // 5.19, a step
  const double d = moving_frame_divisor(full_sample_for(fit));
  for (double waver : {0.93, 0.97, 1.0, 1.03, 1.07})  // cost ±7 %: divisor ±3.5 %
    EXPECT_EQ(moving_frame_divisor(waver * full_sample_for(fit)), d) << waver;
  EXPECT_LT(moving_frame_divisor(0.6 * full_sample_for(fit)), d);  // one bounce instead of two
  EXPECT_GT(moving_frame_divisor(1.4 * full_sample_for(fit)), d);
}

// A cheap scene keeps half the width; a dear one is held at an eighth, whatever it costs.
TEST(MovingFrame, TheDivisorStaysWithinItsBounds) {
  EXPECT_EQ(moving_frame_divisor(0), kMinMovingDivisor);  // nothing measured yet
  EXPECT_EQ(moving_frame_divisor(full_sample_for(1.2)), kMinMovingDivisor);
  EXPECT_EQ(moving_frame_divisor(full_sample_for(40)), kMaxMovingDivisor);
}
