// A sweep's job-array tasks, the `--array` list, the point list collect reads back, and the job script's words.
#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "sweep/sweep_slurm.hpp"

using cnc::sim::array_list;
using cnc::sim::task_count;
using cnc::sim::task_points;

TEST(SweepSlurm, TasksCoverEveryPointOnce) {
    // 10 points at 4 a task: 0-3, 4-7, 8-9.
    EXPECT_EQ(task_count(10, 4), 3u);
    using Range = std::pair<std::size_t, std::size_t>;
    EXPECT_EQ(task_points(0, 10, 4), Range(0, 4));
    EXPECT_EQ(task_points(2, 10, 4), Range(8, 10));
    EXPECT_EQ(task_count(8, 4), 2u);
    EXPECT_EQ(task_count(1, 1), 1u);
}

TEST(SweepSlurm, DefaultPointsPerTaskKeepsWithinTheArrayLimit) {
    EXPECT_EQ(cnc::sim::default_points_per_task(60), 1u);
    EXPECT_EQ(cnc::sim::default_points_per_task(1000), 1u);
    // 1001 points: 2 a task make 501 tasks; 250,000 points: 250 a task make 1000.
    EXPECT_EQ(cnc::sim::default_points_per_task(1001), 2u);
    EXPECT_EQ(task_count(250000, cnc::sim::default_points_per_task(250000)), 1000u);
}

TEST(SweepSlurm, ArrayListJoinsRuns) {
    EXPECT_EQ(array_list({0, 1, 2, 3}), "0-3");
    EXPECT_EQ(array_list({0, 1, 2, 3, 5, 7, 8}), "0-3,5,7-8");
    EXPECT_EQ(array_list({4}), "4");
}

TEST(SweepSlurm, SubmissionReadsBack) {
    const cnc::sim::SlurmSubmission s{
        "s.toml", "out",   "/home/me", "/opt/cncsim",
        4,        "debug", "10:00",    {{"scenario.architecture=ideal"}, {"scenario.architecture=atmega", "a=1"}}};
    const auto back = cnc::sim::parse_submission(cnc::sim::submission_json(s).dump());
    ASSERT_TRUE(back.has_value());
    EXPECT_EQ(back->sweep_file, "s.toml");
    EXPECT_EQ(back->cwd, "/home/me");
    EXPECT_EQ(back->per_task, 4u);
    EXPECT_EQ(back->time, "10:00");
    EXPECT_EQ(back->point_sets, s.point_sets);
    EXPECT_FALSE(cnc::sim::parse_submission("{\"sweep\": 1}").has_value());
    EXPECT_FALSE(cnc::sim::parse_submission("not json").has_value());
}

TEST(SweepSlurm, ScriptQuotesItsWords) {
    EXPECT_EQ(cnc::sim::shell_word("/a/b.toml"), "/a/b.toml");
    EXPECT_EQ(cnc::sim::shell_word("my sweep's.toml"), "'my sweep'\\''s.toml'");
    const cnc::sim::SlurmSubmission s{"my sweep.toml", "out", "/w", "/opt/cncsim", 3, "", "", {}};
    const std::string script = cnc::sim::job_script(s, "/w/out/slurm/task_%A_%a.log");
    EXPECT_NE(script.find("#SBATCH --output=/w/out/slurm/task_%A_%a.log\n"), std::string::npos);
    EXPECT_EQ(script.find("--partition"), std::string::npos);
    EXPECT_NE(script.find("cd /w || exit 2\n"), std::string::npos);
    EXPECT_NE(script.find("exec /opt/cncsim sweep 'my sweep.toml' --out out --point \"$SLURM_ARRAY_TASK_ID\" "
                          "--points-per-task 3\n"),
              std::string::npos);
}
