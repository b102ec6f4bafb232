// The small design the RTL plug-in tests build, and its port list.
#pragma once
#include <string>

#include "rtl/plugin_spec.hpp"

namespace cnc::rtl {

// An 8-bit counter that counts while `enable` is high and saturates at LIMIT: a fixed point once it is there.
constexpr const char* kCounter = R"(module counter #(parameter LIMIT = 5) (
    input wire clk, input wire enable, output reg [7:0] count, output wire at_limit);
    reg [7:0] shadow;
    initial count = 8'd0;
    always @(posedge clk) begin
        if (enable && count != LIMIT) count <= count + 8'd1;
        shadow <= count;
    end
    assign at_limit = count == LIMIT;
endmodule
)";

inline PluginSpec counter_spec(const std::string& file) {
    PluginSpec spec;
    spec.top_module = "counter";
    spec.sources = {file};
    spec.clock = "clk";
    spec.inputs = {{"enable", 1}};
    spec.outputs = {{"count", 8}, {"at_limit", 1}};
    spec.observed = {{"counter", "shadow", "shadow"}, {"counter", "missing", "missing"}};
    spec.where = "test.toml: fpga.rtl_top";
    return spec;
}

}  // namespace cnc::rtl
