// StepWatch (cosim/core/step_watch.hpp): who of this process is inside its model step, since when.
#include <gtest/gtest.h>

#include <memory>

#include "cosim/core/step_watch.hpp"

using hbt::cosim::core::StepWatch;

TEST(StepWatch, OnlyTheOneInsideItsStepIsNamedWithItsTimeAndDuration) {
  StepWatch a("engine"), b("battery");
  EXPECT_TRUE(StepWatch::inStep(100.0).empty());
  EXPECT_EQ(StepWatch::describe(100.0), "");
  a.enter(3000000000, 100.0);  // t = 3 s, entered at 100 s of the steady clock
  const auto in = StepWatch::inStep(101.25);
  ASSERT_EQ(in.size(), 1u);
  EXPECT_EQ(in[0].participant, "engine");
  EXPECT_EQ(in[0].t, 3000000000);
  EXPECT_DOUBLE_EQ(in[0].for_s, 1.25);
  EXPECT_EQ(StepWatch::describe(101.25),
            "in the stepper's process, engine has been inside its model step (from t = 3.000 s) for 1.25 s");
  a.leave();
  EXPECT_TRUE(StepWatch::inStep(102.0).empty());
}

TEST(StepWatch, AParticipantGoneIsNoLongerWatched) {
  auto w = std::make_unique<StepWatch>("cooling");
  w->enter(0, 5.0);
  EXPECT_EQ(StepWatch::inStep(6.0).size(), 1u);
  w.reset();  // unregistered with it
  EXPECT_TRUE(StepWatch::inStep(6.0).empty());
}
