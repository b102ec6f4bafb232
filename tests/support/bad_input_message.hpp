// The message of the cnc::BadInput that `fn` throws; a test failure (and "") if it throws none.
#pragma once
#include <functional>
#include <string>

#include <gtest/gtest.h>

#include "common/bad_input.hpp"

namespace cnc::test {

inline std::string bad_input_message(const std::function<void()>& fn) {
    try {
        fn();
    } catch (const BadInput& e) {
        return e.what();
    }
    ADD_FAILURE() << "no BadInput thrown";
    return {};
}

}  // namespace cnc::test
