#include "scenario/key_listing.hpp"

#include <algorithm>
#include <iterator>
#include <sstream>

#include "common/bad_input.hpp"

namespace cnc::sim {

std::vector<KeyDoc> keys_with_prefix(const std::vector<KeyDoc>& docs, const std::string& prefix) {
    std::vector<KeyDoc> out;
    std::copy_if(docs.begin(), docs.end(), std::back_inserter(out),
                 [&](const KeyDoc& d) { return d.key.rfind(prefix, 0) == 0; });
    if (out.empty()) {
        throw BadInput("keys " + prefix, "no key starts with '" + prefix + "' (the tables: " + key_tables_text(docs) +
                                             "; e.g. `cncsim keys machine.x`)");
    }
    return out;
}

std::string key_tables_text(const std::vector<KeyDoc>& docs) {
    std::vector<std::string> tables;
    for (const KeyDoc& d : docs) {
        const std::string table = d.key.substr(0, d.key.find('.'));
        if (std::find(tables.begin(), tables.end(), table) == tables.end()) tables.push_back(table);
    }
    std::string text;
    for (const std::string& t : tables) text += (text.empty() ? "" : ", ") + t;
    return text;
}

std::string wrap_text(const std::string& text, std::size_t width, const std::string& indent) {
    std::istringstream words(text);
    std::string out, line;
    for (std::string word; words >> word;) {
        if (!line.empty() && indent.size() + line.size() + 1 + word.size() > width) {
            out += indent + line + "\n";
            line.clear();
        }
        line += (line.empty() ? "" : " ") + word;
    }
    if (!line.empty()) out += indent + line + "\n";
    return out;
}

std::string keys_text(const std::vector<KeyDoc>& docs, std::size_t width) {
    std::string out;
    for (const KeyDoc& d : docs) {
        const std::string head = d.key + "  " + d.type + ", default " + d.default_text +
                                 (d.allowed.empty() ? std::string() : ", allowed " + d.allowed);
        out += wrap_text(head, width, "") + wrap_text(d.doc, width, "    ");
    }
    return out;
}

}  // namespace cnc::sim
