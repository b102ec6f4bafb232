#include <fcntl.h>
#include <unistd.h>

#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "metrics/timing/move_records.hpp"

namespace cnc::metrics {
namespace {

// Moves with every field of a row set, absent figures among them, and fewer per-axis values than the file's axes
// on some (a steps file's rows): what a run's programmed moves can hold.
std::vector<MoveMetrics> varied_moves(std::size_t n) {
    std::vector<MoveMetrics> out;
    for (std::size_t i = 0; i < n; ++i) {
        const int k = static_cast<int>(i);
        const double x = 0.1 * k + 1.0 / 3.0;  // not a short binary fraction: a row must keep every bit
        MoveMetrics m;
        m.index = k + 1;
        m.line = 3 * k + 7;
        m.pieces = 1 + i % 4;
        m.feed_mm_per_min = 600.0 + x;
        m.steps_commanded = {k * 16, -k};
        m.steps_emitted = i % 7 == 0 ? std::vector<std::int64_t>{k * 16} : std::vector<std::int64_t>{k * 16, 1 - k};
        if (i % 3 != 0) m.t_first_edge_ps = TimePs{1'000'000'007} * k;
        if (i % 3 != 1) m.t_last_edge_ps = TimePs{1'000'000'009} * k + 5;
        m.sync_max_abs_ns = {std::nullopt, x * 20.0};
        if (i % 2 == 0) m.timing.motion_time_s = x / 7.0;
        if (i % 4 != 3) m.timing.achieved_feed_mm_per_min = 599.0 + x;
        if (i % 4 == 1) m.timing.feed_error_pct = -x / 11.0;
        m.timing.below_feed = i % 6 == 1;
        if (i % 3 != 0) {
            m.timing.dead_after_move = i - 1;
            m.timing.dead_before_ps = TimePs{999'983} * k;
        }
        m.path.samples = 10 * i;
        if (i % 2 == 1) m.path.contour_max_um = x * 1.5;
        if (i % 3 == 2) m.path.following_max_um = -x;
        m.path.following_rms_um = x / 2.0;
        if (i % 5 != 4) m.path.endpoint_vs_command_um = x * 0.25;
        if (i % 8 == 0) m.path.endpoint_vs_program_um = 1e-9 * x;
        m.programmed.kind = static_cast<ProgrammedKind>(i % 4);
        m.programmed.x_mm = x * 3.0;
        m.programmed.y_mm = -x;
        m.programmed.z_mm = i % 2 == 0 ? 0.0 : x / 3.0;
        if (i % 4 >= 2) {
            m.programmed.center_x_mm = x + 0.5;
            m.programmed.center_y_mm = -x - 0.25;
        }
        out.push_back(m);
    }
    return out;
}

void expect_same(const MoveMetrics& got, const MoveMetrics& want) {
    EXPECT_EQ(got.index, want.index);
    EXPECT_EQ(got.line, want.line);
    EXPECT_EQ(got.pieces, want.pieces);
    EXPECT_EQ(got.feed_mm_per_min, want.feed_mm_per_min);
    EXPECT_EQ(got.steps_commanded, want.steps_commanded);
    EXPECT_EQ(got.steps_emitted, want.steps_emitted);
    EXPECT_EQ(got.t_first_edge_ps, want.t_first_edge_ps);
    EXPECT_EQ(got.t_last_edge_ps, want.t_last_edge_ps);
    EXPECT_EQ(got.sync_max_abs_ns, want.sync_max_abs_ns);
    EXPECT_EQ(got.timing.motion_time_s, want.timing.motion_time_s);
    EXPECT_EQ(got.timing.achieved_feed_mm_per_min, want.timing.achieved_feed_mm_per_min);
    EXPECT_EQ(got.timing.feed_error_pct, want.timing.feed_error_pct);
    EXPECT_EQ(got.timing.below_feed, want.timing.below_feed);
    EXPECT_EQ(got.timing.dead_after_move, want.timing.dead_after_move);
    EXPECT_EQ(got.timing.dead_before_ps, want.timing.dead_before_ps);
    EXPECT_EQ(got.path.samples, want.path.samples);
    EXPECT_EQ(got.path.contour_max_um, want.path.contour_max_um);
    EXPECT_EQ(got.path.following_max_um, want.path.following_max_um);
    EXPECT_EQ(got.path.following_rms_um, want.path.following_rms_um);
    EXPECT_EQ(got.path.endpoint_vs_command_um, want.path.endpoint_vs_command_um);
    EXPECT_EQ(got.path.endpoint_vs_program_um, want.path.endpoint_vs_program_um);
    EXPECT_EQ(got.programmed.kind, want.programmed.kind);
    EXPECT_EQ(got.programmed.x_mm, want.programmed.x_mm);
    EXPECT_EQ(got.programmed.y_mm, want.programmed.y_mm);
    EXPECT_EQ(got.programmed.z_mm, want.programmed.z_mm);
    EXPECT_EQ(got.programmed.center_x_mm, want.programmed.center_x_mm);
    EXPECT_EQ(got.programmed.center_y_mm, want.programmed.center_y_mm);
}

std::filesystem::path test_dir(const std::string& name) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("cncsim-" + name);
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

// 3,000 rows: several times the write buffer (64 KiB of rows of about 200 B), so most passes read from the file.
constexpr std::size_t kMoves = 3000;

TEST(MoveRecords, InMemoryAndSpilledGiveTheSameRowsPassAfterPass) {
    const std::vector<MoveMetrics> moves = varied_moves(kMoves);
    const std::filesystem::path dir = test_dir("MoveRecords.InMemoryAndSpilledGiveTheSameRowsPassAfterPass");
    MoveRecords memory;
    MoveRecords spilled = MoveRecords::spilled(2, dir.string());
    for (const MoveMetrics& m : moves) {
        memory.append(m);
        spilled.append(m);
    }
    ASSERT_EQ(memory.size(), kMoves);
    ASSERT_EQ(spilled.size(), kMoves);
    for (int pass = 0; pass < 3; ++pass) {
        for (const MoveRecords* records : {&memory, &spilled}) {
            std::size_t i = 0;
            records->for_each([&](const MoveMetrics& m) {
                ASSERT_LT(i, kMoves);
                expect_same(m, moves[i++]);
            });
            EXPECT_EQ(i, kMoves) << "pass " << pass;
        }
    }
    for (const std::size_t i : {std::size_t{0}, std::size_t{1234}, kMoves - 1}) expect_same(spilled.at(i), moves[i]);
    EXPECT_THROW((void)spilled.at(kMoves), std::out_of_range);
    // Appending after a pass goes on where the rows ended.
    spilled.append(moves[5]);
    expect_same(spilled.at(kMoves), moves[5]);
    // The file was unlinked when it was made: nothing in its folder, whatever happens to the run.
    EXPECT_TRUE(std::filesystem::is_empty(dir));
}

TEST(MoveRecords, TheDeadGapsAreTheMovesWithOneInOrderSpilledOrNot) {
    const std::vector<MoveMetrics> moves = varied_moves(kMoves);
    MoveRecords memory;
    MoveRecords spilled = MoveRecords::spilled(2, test_dir("MoveRecords.TheDeadGaps").string());
    for (const MoveMetrics& m : moves) {
        memory.append(m);
        spilled.append(m);
    }
    for (const MoveRecords* records : {&memory, &spilled}) {
        const std::vector<DeadGap> gaps = dead_gaps(*records);
        ASSERT_EQ(gaps.size(), kMoves - (kMoves + 2) / 3);  // every move but each third one
        for (const DeadGap& g : gaps) {
            ASSERT_NE(g.before_move % 3, 0U);
            EXPECT_EQ(g.after_move, g.before_move - 1);
            EXPECT_EQ(g.dead_ps, *moves[g.before_move].timing.dead_before_ps);
        }
        for (std::size_t k = 1; k < gaps.size(); ++k) EXPECT_LT(gaps[k - 1].before_move, gaps[k].before_move);
    }
}

TEST(MoveRecords, AFullDiskFailsTheAppendOrTheReadNamingTheFile) {
    const int fd = ::open("/dev/full", O_RDWR);
    ASSERT_GE(fd, 0);
    MoveRecords records = MoveRecords::spilled_to(2, fd, "/dev/full");
    const std::vector<MoveMetrics> moves = varied_moves(2);
    records.append(moves[0]);  // buffered
    try {
        records.for_each([](const MoveMetrics&) {});
        FAIL() << "no error";
    } catch (const MoveRecordsError& e) {
        EXPECT_NE(std::string(e.what()).find("cannot write the programmed moves' records in /dev/full"),
                  std::string::npos)
            << e.what();
    }
    MoveRecords growing = MoveRecords::spilled_to(2, ::open("/dev/full", O_RDWR), "/dev/full");
    EXPECT_THROW(for (std::size_t i = 0; i < kMoves; ++i) growing.append(moves[1]),
                 MoveRecordsError);  // a buffer's worth
}

TEST(MoveRecords, AFolderThatCannotHoldTheFileIsNamed) {
    try {
        (void)MoveRecords::spilled(2, "/nonexistent-cncsim-folder");
        FAIL() << "no error";
    } catch (const MoveRecordsError& e) {
        EXPECT_NE(std::string(e.what()).find("cannot create a temporary file in /nonexistent-cncsim-folder"),
                  std::string::npos)
            << e.what();
    }
}

}  // namespace
}  // namespace cnc::metrics
