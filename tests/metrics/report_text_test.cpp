#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "metrics/metrics.hpp"
#include "metrics/report/report.hpp"

namespace cnc::metrics {
namespace {

TEST(ReportText, ObjectsIndentedArraysOfPlainValuesOnOneLine) {
    const nlohmann::json j = {{"job_time_s", 1.5},
                              {"moves", {{"index", {1, 2, 3}}, {"contour_max_um", {0.5, nullptr, 2.25}}}},
                              {"runs", nlohmann::json::array({{{"move", 1}}, {{"move", 2}}})},
                              {"empty", nlohmann::json::object()},
                              {"name", "a \"b\""}};
    // nlohmann orders object keys alphabetically.
    EXPECT_EQ(report_text(j),
              "{\n"
              "  \"empty\": {},\n"
              "  \"job_time_s\": 1.5,\n"
              "  \"moves\": {\n"
              "    \"contour_max_um\": [0.5,null,2.25],\n"
              "    \"index\": [1,2,3]\n"
              "  },\n"
              "  \"name\": \"a \\\"b\\\"\",\n"
              "  \"runs\": [\n"
              "    {\n"
              "      \"move\": 1\n"
              "    },\n"
              "    {\n"
              "      \"move\": 2\n"
              "    }\n"
              "  ]\n"
              "}\n");
    EXPECT_EQ(nlohmann::json::parse(report_text(j)), j);
}

// The programmed moves' columns written from the records (spilled, as a streamed run has them) equal the json
// columns report_text() writes: same keys in the same order (axes named out of alphabetical order), same numbers.
TEST(ReportText, MoveColumnsWrittenFromTheRecordsEqualTheJsonOnes) {
    RunMetrics m;
    for (const char* name : {"y", "x"}) {
        AxisMetrics a;
        a.name = name;
        m.axes.push_back(a);
    }
    m.moves = MoveRecords::spilled(2);
    for (int i = 0; i < 4; ++i) {
        MoveMetrics mv;
        mv.index = i + 1;
        mv.line = 10 + i;
        mv.programmed.kind = i == 0 ? ProgrammedKind::Rapid : ProgrammedKind::Line;
        mv.feed_mm_per_min = 1000.0 / 3.0 + i;  // rounded to the thousandth in both
        mv.steps_commanded = {i * 100, -i};
        mv.steps_emitted = {i * 100 - 1, -i};
        mv.sync_max_abs_ns = {std::nullopt, 1.0 / 7.0};
        if (i > 0) mv.t_first_edge_ps = TimePs{123'456'789} * i;
        if (i % 2 == 1) mv.timing.motion_time_s = 0.1 * i;
        mv.path.contour_max_um = i == 2 ? std::optional<double>() : 2.0 / 3.0;
        m.moves.append(mv);
    }
    for (const bool detail : {false, true}) {
        const nlohmann::json whole = {{"metrics", to_json(m, detail)}, {"ok", true}};
        const nlohmann::json placeholder = {{"metrics", to_json(m, detail, MoveColumns::Streamed)}, {"ok", true}};
        ASSERT_TRUE(placeholder["metrics"]["moves"].is_null());
        const StreamedMember moves{{"metrics", "moves"}, [&m, detail](std::ostream& os, int depth) {
                                       write_move_columns(os, m, detail, depth);
                                   }};
        std::ostringstream streamed;
        write_report_text(streamed, placeholder, &moves);
        EXPECT_EQ(streamed.str(), report_text(whole)) << "detail " << detail;
    }
}

}  // namespace
}  // namespace cnc::metrics
