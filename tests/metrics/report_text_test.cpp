#include <gtest/gtest.h>

#include "metrics/metrics.hpp"

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

}  // namespace
}  // namespace cnc::metrics
