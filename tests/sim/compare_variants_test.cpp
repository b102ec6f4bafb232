// cncsim compare --variant: each variant's column holds the figures of `cncsim run` with the command's --set and
// then the variant's, on the scenario's own architecture.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "support/command_output.hpp"

namespace {

const std::string kSquare = std::string(CNC_SOURCE_DIR) + "/scenarios/fpga-uart/square_20mm.toml";
const std::string kSets = " --set mechanics.model=ideal";

nlohmann::json run_report(const std::string& sets, const std::string& name) {
    const std::string report = (std::filesystem::temp_directory_path() / ("cnc_variant_" + name + ".json")).string();
    (void)cnc::test::command_output(std::string(CNCSIM_EXE) + " run " + kSquare + kSets + sets +
                                    " --progress off --report " + report);
    std::ifstream in(report);
    const nlohmann::json j = nlohmann::json::parse(in);
    std::filesystem::remove(report);
    return j;
}

}  // namespace

TEST(CompareVariants, EachColumnEqualsItsOwnRun) {
    const nlohmann::json cols = nlohmann::json::parse(cnc::test::command_output(
        std::string(CNCSIM_EXE) + " compare " + kSquare + kSets +
        " --variant 'seed:' --variant 'crc16: protocol.crc = \"crc16\", host.ack_timeout_s=2' --format json"));
    ASSERT_EQ(cols.size(), 2U);  // the scenario's architecture only, the ideal baseline hidden
    EXPECT_EQ(cols[0]["label"], "fpga-uart: seed");
    EXPECT_EQ(cols[1]["label"], "fpga-uart: crc16");
    EXPECT_EQ(cols[1]["variant_sets"], (nlohmann::json{"protocol.crc=\"crc16\"", "host.ack_timeout_s=2"}));
    const nlohmann::json runs[] = {run_report("", "seed"),
                                   run_report(" --set 'protocol.crc=\"crc16\"' --set host.ack_timeout_s=2", "crc16")};
    for (std::size_t k = 0; k < 2; ++k) {
        const nlohmann::json& m = cols[k]["metrics"];
        int compared = 0;
        for (const auto& [key, value] : m.items()) {
            const nlohmann::json::json_pointer ptr("/" + key);
            if (!runs[k].contains(ptr)) continue;  // a row over the ideal: not a figure of the run
            EXPECT_EQ(value, runs[k].at(ptr)) << cols[k]["label"] << " " << key;
            ++compared;
        }
        EXPECT_GE(compared, 15) << cols[k]["label"];
    }
    // The packet check's two CRC bytes and its answers per packet make the job longer: the variants differ.
    EXPECT_GT(cols[1]["metrics"]["metrics/job/job_time_s"].get<double>(),
              cols[0]["metrics"]["metrics/job/job_time_s"].get<double>());
}
