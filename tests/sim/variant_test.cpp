// The variant syntax of `cncsim compare --variant` and a scenario's compare.variants.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "common/bad_input.hpp"
#include "scenario/variant.hpp"

namespace {

using cnc::sim::parse_variant;

std::string refusal(const std::string& text) {
    try {
        (void)parse_variant(text, "--variant");
    } catch (const cnc::BadInput& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST(Variant, NameAndAssignmentsTrimmed) {
    const cnc::sim::Variant v = parse_variant("  crc16 :protocol.crc = \"crc16\" ,faults.uart_ber=1e-5 ", "--variant");
    EXPECT_EQ(v.name, "crc16");
    EXPECT_EQ(v.sets, (std::vector<std::string>{"protocol.crc=\"crc16\"", "faults.uart_ber=1e-5"}));
}

TEST(Variant, NameAloneIsTheScenarioAsItIs) {
    const cnc::sim::Variant v = parse_variant("seed:", "--variant");
    EXPECT_EQ(v.name, "seed");
    EXPECT_TRUE(v.sets.empty());
    EXPECT_TRUE(parse_variant("seed:   ", "--variant").sets.empty());
}

// A comma splits only outside quotes and brackets: a TOML array, an inline table or a string keeps its commas.
TEST(Variant, CommasInsideQuotesAndBracketsStayInTheValue) {
    const cnc::sim::Variant v = parse_variant(
        "w: trace.signals = [\"x.step\", 'y.step'], scenario.name = \"a, b\", k = {a = 1, b = [2, 3]}, "
        "s = \"say \\\"hi, there\\\"\", t='c:\\d,e'",
        "--variant");
    EXPECT_EQ(v.sets,
              (std::vector<std::string>{"trace.signals=[\"x.step\", 'y.step']", "scenario.name=\"a, b\"",
                                        "k={a = 1, b = [2, 3]}", "s=\"say \\\"hi, there\\\"\"", "t='c:\\d,e'"}));
    // The first colon ends the name; later ones belong to a value.
    EXPECT_EQ(parse_variant("p: scenario.job = \"c:/jobs/a.nc\"", "--variant").sets.front(),
              "scenario.job=\"c:/jobs/a.nc\"");
}

TEST(Variant, NameCharacters) {
    EXPECT_EQ(parse_variant("ber1e-5_crc+nak.v2: a=1", "--variant").name, "ber1e-5_crc+nak.v2");
    EXPECT_NE(refusal("two words: a=1").find("the name \"two words\" holds a character other than"), std::string::npos);
    EXPECT_NE(refusal("a/b: a=1").find("the name"), std::string::npos);
    EXPECT_NE(refusal(".hidden: a=1").find("the name"), std::string::npos);
    EXPECT_NE(refusal(": a=1").find("no name before the ':'"), std::string::npos);
}

// Each refusal names the option, quotes the variant, says what is wrong and what a variant is.
TEST(Variant, BadSyntaxIsRefusedWithWhatIsAllowed) {
    const std::string no_colon = refusal("crc16 protocol.crc=crc16");
    EXPECT_EQ(no_colon.rfind("--variant: \"crc16 protocol.crc=crc16\": no ':' after the name; a variant is "
                             "\"NAME: key=value, key=value\"",
                             0),
              0U)
        << no_colon;
    EXPECT_NE(refusal("v: a=1,, b=2").find("an empty assignment"), std::string::npos);
    EXPECT_NE(refusal("v: a=1,").find("an empty assignment"), std::string::npos);
    EXPECT_NE(refusal("v: protocol.crc").find("\"protocol.crc\" is not key=value"), std::string::npos);
    EXPECT_NE(refusal("v: =1").find("does not start with a scenario key"), std::string::npos);
    EXPECT_NE(refusal("v: a b=1").find("does not start with a scenario key"), std::string::npos);
    EXPECT_NE(refusal("v: a=\"open, b=2").find("a \" is not closed"), std::string::npos);
    EXPECT_NE(refusal("v: a=[1, 2").find("a '[' is not closed"), std::string::npos);
    EXPECT_NE(refusal("v: a=[1, 2}").find("a '}' closes nothing"), std::string::npos);
}

TEST(Variant, NamesAreUnique) {
    const std::vector<cnc::sim::Variant> twice = {{"a", {}}, {"b", {}}, {"a", {"x=1"}}};
    try {
        cnc::sim::check_variant_names(twice, "--variant");
        FAIL() << "a name given twice was taken";
    } catch (const cnc::BadInput& e) {
        EXPECT_STREQ(e.what(), "--variant: the variant name \"a\" is given twice; each variant needs its own");
    }
    EXPECT_NO_THROW(cnc::sim::check_variant_names({{"a", {}}, {"b", {}}}, "--variant"));
}
