// The pieces of the Slurm jobs backend that need no cluster: how a job's samples are split
// into parts, and running the client tools (tests/deploy/slurm_test.sh runs the rest against a
// one-node cluster).
#include <gtest/gtest.h>

#include "jobs/slurm_job.h"
#include "jobs/subprocess.h"

namespace geodesic::jobs {
namespace {

TEST(SlurmParts, TheLargestDivisorOfTheSamplesAtMostTheLimit) {
  EXPECT_EQ(slurm_parts(12, 4), 4);
  EXPECT_EQ(slurm_parts(12, 5), 4);
  EXPECT_EQ(slurm_parts(10, 3), 2);
  EXPECT_EQ(slurm_parts(7, 4), 1);   // a prime: one part
  EXPECT_EQ(slurm_parts(1, 4), 1);
  EXPECT_EQ(slurm_parts(3000, 3), 3);
  EXPECT_EQ(slurm_parts(2, 8), 2);   // never more parts than samples
  EXPECT_EQ(slurm_parts(64, 0), 1);
}

TEST(RunCommand, CollectsBothStreamsAndTheExitCode) {
  const CommandResult r = run_command({"sh", "-c", "echo out; echo err >&2; echo $EXTRA; exit 3"},
                                      {{"EXTRA", "given"}});
  EXPECT_EQ(r.exit_code, 3);
  EXPECT_FALSE(r.timed_out);
  EXPECT_EQ(r.out, "out\ngiven\n");
  EXPECT_EQ(r.err, "err\n");
}

TEST(RunCommand, KillsACommandPastItsTimeout) {
  const CommandResult r = run_command({"sleep", "30"}, {}, 0.2);
  EXPECT_TRUE(r.timed_out);
  EXPECT_EQ(r.exit_code, -1);
}

TEST(RunCommand, AMissingCommandThrowsNamingIt) {
  try {
    run_command({"geodesic-no-such-command"});
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("geodesic-no-such-command: cannot run"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace geodesic::jobs
