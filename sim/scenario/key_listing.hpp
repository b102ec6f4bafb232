// `cncsim keys [PREFIX]`: the keys of the registry (scenario_keys) chosen by a prefix, and their listing for a
// terminal. The Markdown table (keys_markdown) is what a pipe or a file gets.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "scenario/key_reader.hpp"

namespace cnc::sim {

// The keys whose name starts with `prefix` ("machine.x", "link"); BadInput naming the prefix and the top-level
// tables when none does.
std::vector<KeyDoc> keys_with_prefix(const std::vector<KeyDoc>& docs, const std::string& prefix);

// The top-level tables of the keys, in reading order: "scenario, machine, ...".
std::string key_tables_text(const std::vector<KeyDoc>& docs);

// One key per paragraph, no line longer than `width` (but a word that is): the key, its type, default and range,
// then its meaning indented.
std::string keys_text(const std::vector<KeyDoc>& docs, std::size_t width);

// `text` as lines of at most `width` characters (a longer word alone on its line), each starting with `indent`.
std::string wrap_text(const std::string& text, std::size_t width, const std::string& indent);

}  // namespace cnc::sim
