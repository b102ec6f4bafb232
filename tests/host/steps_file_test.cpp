#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "host/core/steps_file.hpp"
#include "host_test_util.hpp"
#include "support/test_path.hpp"

namespace cnc::host {
namespace {

using test::expect_bad_input;
using test::run_gcode;

std::vector<MotionSegment> read_text(const std::string& text) {
    std::istringstream in(text);
    return read_steps_file(in, "s.steps");
}

void expect_read_error(const std::string& row, std::initializer_list<std::string> parts) {
    expect_bad_input(
        [&] { read_text(std::string(kStepsFileHeader) + "\n1,1,1,10,5,1600,800,1000,894\n" + row + "\n"); }, parts);
}

std::string write_text(const std::vector<MotionSegment>& segs) {
    std::ostringstream out;
    write_steps_file(out, segs);
    return out.str();
}

TEST(HostStepsFile, WritesHeaderAndRows) {
    const auto segs = cam(run_gcode("G1 X10 Y5 F1000\nG1 X10 Y0 F1000\nG0 X0.00625 Y-31.4625\n"), {}, {});
    EXPECT_EQ(write_text(segs),
              "Segment,GcodeLine,Motion,DX_mm,DY_mm,StepsX,StepsY,PathFeed,FeedRate\n"
              "1,1,1,10,5,1600,800,1000,894\n"
              "2,2,1,0,-5,0,-800,1000,1000\n"
              "3,3,0,-9.99375,-31.4625,-1599,-5034,1200,1144\n");
}

TEST(HostStepsFile, RoundTripsEveryField) {
    MachineModel m;
    m.y.microsteps = 16;
    m.x.pulley_teeth = 17;  // 6400 / 34 steps/mm: DX values with long decimal expansions
    const auto segs = cam(run_gcode("G0 X3.3 Y-2\nG1 X7 Y1 F777\nG2 X13 Y1 I3 F333.3\nG3 X7 Y1 R-3\n"), m, {});
    ASSERT_GT(segs.size(), 80u);  // two half circles of R 3 in chords
    const auto back = read_text(write_text(segs));
    ASSERT_EQ(back.size(), segs.size());
    for (std::size_t i = 0; i < segs.size(); ++i) {
        EXPECT_EQ(back[i].index, segs[i].index);
        EXPECT_EQ(back[i].line, segs[i].line);
        EXPECT_EQ(back[i].motion, segs[i].motion);
        EXPECT_EQ(back[i].steps_x, segs[i].steps_x);
        EXPECT_EQ(back[i].steps_y, segs[i].steps_y);
        EXPECT_EQ(back[i].feed, segs[i].feed);
        EXPECT_EQ(back[i].dx_mm, segs[i].dx_mm);
        EXPECT_EQ(back[i].dy_mm, segs[i].dy_mm);
        EXPECT_EQ(back[i].path_feed_mm_per_min, segs[i].path_feed_mm_per_min);
        EXPECT_EQ(back[i].move, -1);
    }
    EXPECT_EQ(write_text(back), write_text(segs));
}

TEST(HostStepsFile, ReaderAcceptsWhatTheSenderAccepts) {
    const auto segs = read_text(
        "any header at all\r\n"
        "\n"
        " 7 , 0 , 2 , 0.5 , -0.5 , +80 , -80 , 800 , 894.5 \r\n"
        "8,0,3,0,0,1,2,800,895.5,extra,columns\n"
        "   \n"
        "9,0,0,0,0,-2147483648,2147483647,0,65535\n");
    ASSERT_EQ(segs.size(), 3u);
    EXPECT_EQ(segs[0].index, 7);
    EXPECT_EQ(segs[0].motion, MotionKind::ArcCW);
    EXPECT_EQ(segs[0].steps_x, 80);
    EXPECT_EQ(segs[0].steps_y, -80);
    EXPECT_EQ(segs[0].feed, 894);  // Python round(): half to even
    EXPECT_EQ(segs[1].feed, 896);
    EXPECT_EQ(segs[1].motion, MotionKind::ArcCCW);
    EXPECT_EQ(segs[2].steps_x, -2147483648LL);
    EXPECT_EQ(segs[2].steps_y, 2147483647LL);
    EXPECT_EQ(segs[2].feed, 65535);
    EXPECT_TRUE(read_text("").empty());
    EXPECT_TRUE(read_text("header only\n").empty());
}

TEST(HostStepsFile, CorruptRowsAreErrorsWithFileLineAndColumn) {
    expect_read_error("2,0,1,0,0,1,2,800", {"s.steps:3:", "8 columns, at least 9 needed", kStepsFileHeader});
    expect_read_error("x,0,1,0,0,1,2,800,800", {"s.steps:3:", "column 0 (Segment) 'x' is not an integer"});
    expect_read_error("2,-1,1,0,0,1,2,800,800", {"column 1 (GcodeLine) '-1' outside 0..2147483647"});
    expect_read_error("2,0,4,0,0,1,2,800,800", {"s.steps:3:", "column 2 (Motion) '4' outside 0..3"});
    expect_read_error("2,0,1.0,0,0,1,2,800,800", {"column 2 (Motion) '1.0' is not an integer"});
    expect_read_error("2,0,1,abc,0,1,2,800,800", {"column 3 (DX_mm) 'abc' is not a finite number"});
    expect_read_error("2,0,1,0,nan,1,2,800,800", {"column 4 (DY_mm) 'nan' is not a finite number"});
    expect_read_error("2,0,1,0,0,1.5,2,800,800", {"column 5 (StepsX) '1.5' is not an integer"});
    expect_read_error("2,0,1,0,0,2147483648,2,800,800",
                      {"s.steps:3:", "column 5 (StepsX) '2147483648' outside int32 (-2147483648..2147483647)"});
    expect_read_error("2,0,1,0,0,1,-2147483649,800,800", {"column 6 (StepsY) '-2147483649' outside int32"});
    expect_read_error("2,0,1,0,0,1,99999999999999999999,800,800", {"column 6 (StepsY)", "is not an integer"});
    expect_read_error("2,0,1,0,0,1,2,,800", {"column 7 (PathFeed) '' is not a finite number"});
    expect_read_error("2,0,1,0,0,1,2,800,65536", {"s.steps:3:", "column 8 (FeedRate) '65536' outside 0..65535"});
    expect_read_error("2,0,1,0,0,1,2,800,-1", {"column 8 (FeedRate) '-1' outside 0..65535"});
    expect_read_error("2,0,1,0,0,1,2,800,12 3", {"column 8 (FeedRate) '12 3' is not a finite number"});
    expect_read_error("2;0;1;0;0;1;2;800;800", {"1 columns"});
}

// send_steps.py skips line 1 (seed 000 App. A.2): a file that starts with a data row would lose that segment.
TEST(HostStepsFile, AFileWithoutItsHeaderIsRefusedNotShortened) {
    expect_bad_input([] { read_text("1,1,1,10,5,1600,800,1000,894\n2,1,1,10,5,1600,800,1000,894\n"); },
                     {"s.steps:1:", "a data row where the header belongs", kStepsFileHeader});
    EXPECT_EQ(read_text("Segment;anything\n1,1,1,10,5,1600,800,1000,894\n").size(), 1u);
}

TEST(HostStepsFile, SaveAndLoadFile) {
    const std::string path = cnc::test::test_path("job.steps");
    const auto segs = cam(run_gcode("G1 X10 Y5 F1000\n"), {}, {});
    save_steps_file(path, segs);
    const auto back = load_steps_file(path);
    ASSERT_EQ(back.size(), 1u);
    EXPECT_EQ(back[0].steps_x, 1600);
    EXPECT_EQ(back[0].feed, 894);
    expect_bad_input([] { load_steps_file("/nonexistent/x.steps"); }, {"/nonexistent/x.steps:", "cannot open"});
    expect_bad_input([&] { save_steps_file("/nonexistent/dir/x.steps", segs); }, {"cannot create"});
}

}  // namespace
}  // namespace cnc::host
