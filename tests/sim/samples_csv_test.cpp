// The --samples CSV (sim/output/samples_csv.hpp): header, one row per tool sample, exact time digits.
#include <gtest/gtest.h>

#include <sstream>

#include "output/samples_csv.hpp"

namespace {

TEST(SamplesCsv, HeaderThenOneRowPerSampleToThePicosecond) {
    // 3,600.5 s + 1 ps: a double holds it to about 0.5 ps, the row must still read ...500000000001.
    const std::vector<cnc::ToolSample> samples = {{0, {10.0, -0.00625}}, {3'600'500'000'000'001, {30.125, 1.5}}};
    std::ostringstream out;
    cnc::sim::write_samples_csv(out, samples);
    EXPECT_EQ(out.str(),
              "t_s,x_mm,y_mm\n"
              "0.000000000000,10.000000000,-0.006250000\n"
              "3600.500000000001,30.125000000,1.500000000\n");
}

TEST(SamplesCsv, NoSamplesIsTheHeaderAlone) {
    std::ostringstream out;
    cnc::sim::write_samples_csv(out, {});
    EXPECT_EQ(out.str(), "t_s,x_mm,y_mm\n");
}

}  // namespace
