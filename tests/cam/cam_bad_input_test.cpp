// What the CAM refuses, naming the file and line: a file that is not a DXF, entity types it does not read (listed
// with their counts), units it does not convert, a drawing outside the machine's travel.
#include <gtest/gtest.h>

#include <fstream>

#include "cam/dxf_reader.hpp"
#include "cam/travel_check.hpp"
#include "dxf_text.hpp"
#include "support/bad_input_message.hpp"
#include "support/test_path.hpp"

namespace cnc::cam {
namespace {

std::string message_of(const std::string& path) {
    return test::bad_input_message([&] { (void)read_dxf(path, {}); });
}

TEST(CamBadInput, GcodeIsNotADxf) {
    const std::string path = test::test_path("job.dxf");
    std::ofstream(path) << "G21\nG1 X10 Y10 F800\n";
    EXPECT_EQ(message_of(path).rfind(path + ":1: not a DXF drawing", 0), 0u) << message_of(path);
}

TEST(CamBadInput, DxfWithoutEntitiesIsRefused) {
    const std::string path = test::test_path("header_only.dxf");
    std::ofstream(path) << "0\nSECTION\n2\nHEADER\n0\nENDSEC\n0\nEOF\n";
    EXPECT_NE(message_of(path).find("no ENTITIES section"), std::string::npos) << message_of(path);
}

TEST(CamBadInput, UnreadEntityTypesAreListedWithTheirCounts) {
    const std::string path = test::test_path("spline.dxf");
    test::DxfText().line(0, 0, 10, 0).other("SPLINE").other("TEXT").other("SPLINE").write(path);
    const std::string m = message_of(path);
    EXPECT_NE(m.find("spline.dxf:"), std::string::npos) << m;
    EXPECT_NE(m.find("SPLINE (2), TEXT (1)"), std::string::npos) << m;
    DxfOptions skip;
    skip.skip_unread = true;
    const Drawing d = read_dxf(path, skip);
    EXPECT_EQ(d.entities.size(), 1u);
    EXPECT_EQ(d.unread.at("SPLINE"), 2);
    EXPECT_EQ(d.unread.at("TEXT"), 1);
}

TEST(CamBadInput, UnitsWithoutALengthAreRefused) {
    const std::string path = test::test_path("parsecs.dxf");
    test::DxfText().insunits(20).line(0, 0, 1, 0).write(path);
    EXPECT_NE(message_of(path).find("$INSUNITS 20"), std::string::npos) << message_of(path);
}

TEST(CamBadInput, DrawingOutsideTheTravelNamesTheEntity) {
    const std::string path = test::test_path("large.dxf");
    test::DxfText().line(0, 0, 50, 0).circle(100, 100, 30).write(path);
    const Drawing d = read_dxf(path, {});
    host::MachineModel m;
    m.x.travel_mm = 120.0;  // the circle reaches x = 130
    m.y.travel_mm = 200.0;
    const std::string text = test::bad_input_message([&] { check_travel(d, m); });
    EXPECT_NE(text.find("large.dxf:"), std::string::npos) << text;
    EXPECT_NE(text.find("CIRCLE (entity 1, layer 0)"), std::string::npos) << text;
    EXPECT_NE(text.find("machine.x.travel_mm"), std::string::npos) << text;
    m.x.travel_mm = 140.0;
    EXPECT_NO_THROW(check_travel(d, m));
}

}  // namespace
}  // namespace cnc::cam
