// analyze --commanded: the rate segments a run writes into its report are read back exactly, a report holding only
// moves gives a segment per move from its first STEP edge, and a report that cannot serve is refused by name.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <string>

#include "metrics/pulse/commanded_rates.hpp"
#include "support/bad_input_message.hpp"

namespace cnc::metrics {
namespace {

using nlohmann::json;

TEST(CommandedRates, SegmentsRoundTripExactly) {
    RunInput in;
    in.axes.resize(2);
    in.axes[0].name = "x";
    in.axes[1].name = "y";
    // A rate that no short decimal holds: the analyzed rate error must equal the run's to the last bit.
    in.rate_segments = {{{20'000, 1000.0 / 3.0}, {1'000'020'000, 0.0}}, {{40'000, 2.0 / 7.0}}};
    const json report = {{"commanded_rates", commanded_rates_json(in)}};
    const auto back = commanded_rates_from_report(json::parse(report.dump()), "r.json", 2);
    ASSERT_EQ(back.size(), 2U);
    ASSERT_EQ(back[0].size(), 2U);
    EXPECT_EQ(back[0][0].t_ps, 20'000);
    EXPECT_EQ(back[0][0].steps_per_s, 1000.0 / 3.0);
    EXPECT_EQ(back[0][1].t_ps, 1'000'020'000);
    ASSERT_EQ(back[1].size(), 1U);
    EXPECT_EQ(back[1][0].steps_per_s, 2.0 / 7.0);
}

TEST(CommandedRates, MovesGiveASegmentPerMoveFromItsFirstEdge) {
    // Move 1 has no edges (null): it starts no segment.
    const json report = {{"metrics", {{"moves", {{"t_first_edge_ps", {100, nullptr, 5000}}}}}}};
    const auto back = commanded_rates_from_report(report, "r.json", 2);
    ASSERT_EQ(back.size(), 2U);
    for (const auto& axis : back) {
        ASSERT_EQ(axis.size(), 2U);
        EXPECT_EQ(axis[0].t_ps, 100);
        EXPECT_EQ(axis[1].t_ps, 5000);
        EXPECT_EQ(axis[1].steps_per_s, 0.0);  // unknown: no rate error
    }
}

TEST(CommandedRates, RefusesReportsThatCannotServe) {
    const auto message = [](const json& report, std::size_t axes) {
        return test::bad_input_message([&] { (void)commanded_rates_from_report(report, "run.json", axes); });
    };
    EXPECT_NE(message({{"commanded_rates", nullptr}}, 2)
                  .find("run.json: the run changed its commanded rates on its "
                        "own schedule and this report does not hold them: "
                        "write it with `cncsim run --detail`"),
              std::string::npos);
    RunInput in;
    in.axes.resize(1);
    in.rate_segments = {{{0, 1.0}}};
    EXPECT_NE(message({{"commanded_rates", commanded_rates_json(in)}}, 2)
                  .find("run.json: the run's report has 1 axes, --step gives 2"),
              std::string::npos);
    EXPECT_EQ(message({{"ok", true}}, 2).rfind("run.json: not a cncsim run report", 0), 0U);
}

}  // namespace
}  // namespace cnc::metrics
