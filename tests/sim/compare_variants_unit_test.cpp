// The columns of `cncsim compare --variant` in the table, its JSON and CSV, and their colours.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include <nlohmann/json.hpp>

#include "compare/compare.hpp"
#include "compare/html_report.hpp"
#include "plots/plot_render.hpp"

namespace {

cnc::sim::CompareColumn column(const char* variant, std::vector<std::string> sets, double job_s) {
    return {"fpga-uart", 0, {{"metrics", {{"job", {{"job_time_s", job_s}}}}}}, 1.0, variant, std::move(sets)};
}

cnc::sim::Comparison two_variants() {
    return {{column("seed", {}, 8.0), column("crc16", {"protocol.crc=\"crc16\"", "faults.uart_ber=1e-5"}, 9.0)}, {}};
}

}  // namespace

// The header names the variant, its sets are listed under the table (a row under the status in CSV), and the best
// is marked as among architectures.
TEST(CompareVariants, TableNamesEachVariantAndItsSets) {
    const std::string text = cnc::sim::compare_table(two_variants(), cnc::sim::TableFormat::Text);
    EXPECT_NE(text.find("  fpga-uart: seed  fpga-uart: crc16\n"), std::string::npos) << text;
    EXPECT_NE(text.find("\nfpga-uart: seed: the scenario as it is\n"
                        "fpga-uart: crc16: --set protocol.crc=\"crc16\" --set faults.uart_ber=1e-5\n"),
              std::string::npos)
        << text;
    EXPECT_NE(text.find("8.0000*"), std::string::npos) << text;
    const std::string md = cnc::sim::compare_table(two_variants(), cnc::sim::TableFormat::Markdown);
    EXPECT_NE(md.find("\n- **fpga-uart: crc16**: --set protocol.crc=\"crc16\" --set faults.uart_ber=1e-5\n"),
              std::string::npos)
        << md;
    EXPECT_NE(md.find("**8.0000**"), std::string::npos) << md;
    // A CSV field's quotes are doubled, so that the file reads back as written.
    const std::string csv = cnc::sim::compare_table(two_variants(), cnc::sim::TableFormat::Csv);
    EXPECT_NE(csv.find("\"metric\",\"fpga-uart: seed\",\"fpga-uart: crc16\",\"best\""), std::string::npos) << csv;
    EXPECT_NE(csv.find("\"variant sets\",\"-\",\"protocol.crc=\"\"crc16\"\", faults.uart_ber=1e-5\",\"\""),
              std::string::npos)
        << csv;
    EXPECT_NE(csv.find("\"job time [s]\",\"8.0000\",\"9.0000\",\"fpga-uart: seed\""), std::string::npos) << csv;
}

TEST(CompareVariants, JsonCarriesTheVariantAndItsSets) {
    const nlohmann::json j = cnc::sim::compare_json(two_variants());
    ASSERT_EQ(j.size(), 2U);
    EXPECT_EQ(j[0]["architecture"], "fpga-uart");
    EXPECT_EQ(j[0]["label"], "fpga-uart: seed");
    EXPECT_EQ(j[0]["variant"], "seed");
    EXPECT_EQ(j[0]["variant_sets"], nlohmann::json::array());
    EXPECT_EQ(j[1]["variant_sets"], (nlohmann::json{"protocol.crc=\"crc16\"", "faults.uart_ber=1e-5"}));
    EXPECT_EQ(j[0]["best"], nlohmann::json{"metrics/job/job_time_s"});
    // Without variants a column is its architecture as before.
    const nlohmann::json plain = cnc::sim::compare_json({{{"atmega", 0, nullptr, 0.0, "", {}}}, {}});
    EXPECT_TRUE(plain[0]["variant"].is_null());
    EXPECT_EQ(plain[0]["label"], "atmega");
}

// One variant keeps its architecture's colour; several get colours of their own, all different, each dark enough
// for a thin line on white (its Rec. 601 luma at most 0.52).
TEST(CompareVariants, ColoursAreDistinctAndReadable) {
    EXPECT_EQ(cnc::sim::variant_colour("#0072b2", 0, 1), "#0072b2");
    for (const char* base : {"#0072b2", "#d55e00", "#009e73", "#000000"}) {
        for (std::size_t n = 2; n <= 8; ++n) {
            std::set<std::string> seen;
            for (std::size_t k = 0; k < n; ++k) {
                const std::string c = cnc::sim::variant_colour(base, k, n);
                ASSERT_EQ(c.size(), 7U);
                const auto ch = [&](int i) { return std::stoi(c.substr(1 + 2 * i, 2), nullptr, 16) / 255.0; };
                EXPECT_LE(0.299 * ch(0) + 0.587 * ch(1) + 0.114 * ch(2), 0.53)
                    << base << " " << k << "/" << n << ": " << c;
                seen.insert(c);
            }
            EXPECT_EQ(seen.size(), n) << base;
        }
    }
    // On the page and in the plots: per architecture, so that an architecture alone keeps its own.
    const std::vector<cnc::sim::CompareColumn> cols = {{"fpga-uart", 0, nullptr, 0.0, "a", {}},
                                                       {"atmega", 0, nullptr, 0.0, "a", {}},
                                                       {"fpga-uart", 0, nullptr, 0.0, "b", {}}};
    const std::vector<std::string> colours = cnc::sim::column_colours(cols);
    EXPECT_EQ(colours[1], "#d55e00");
    EXPECT_EQ(colours[0], cnc::sim::variant_colour("#0072b2", 0, 2));
    EXPECT_EQ(colours[2], cnc::sim::variant_colour("#0072b2", 1, 2));
}
