// Bad user input (scenario, G-code, steps file, machine parameter): the CLI prints the message and exits 2.
#pragma once
#include <stdexcept>
#include <string>

#include "common/printable.hpp"

namespace cnc {

class BadInput : public std::runtime_error {
public:
    // `where` names the file and line, or the file and key ("jobs/a.nc:12", "s.toml: link.baud"). Bytes of the
    // input quoted in either are escaped (printable.hpp).
    BadInput(const std::string& where, const std::string& what)
        : std::runtime_error(printable(where.empty() ? what : where + ": " + what)) {}
};

}  // namespace cnc
