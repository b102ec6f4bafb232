#include "scenario/variant.hpp"

#include <algorithm>
#include <cctype>
#include <set>

#include "common/bad_input.hpp"
#include "host/core/text_number.hpp"

namespace cnc::sim {

const char* const kVariantSyntax =
    "\"NAME: key=value, key=value\" (NAME of letters, digits and - _ . +; a value holds a comma only inside quotes "
    "or brackets; \"NAME:\" alone runs the scenario as it is)";

namespace {

std::string trimmed(const std::string& s) {
    return std::string(host::trim(s));
}

bool name_char(char c) {
    return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '-' || c == '_' || c == '.' || c == '+';
}

// A scenario key as --set names it: dotted words.
bool key_char(char c) {
    return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_' || c == '.' || c == '-';
}

[[noreturn]] void refuse(const std::string& where, const std::string& text, const std::string& what) {
    throw BadInput(where, "\"" + text + "\": " + what + "; a variant is " + kVariantSyntax);
}

// The assignments after the colon, split at the top-level commas.
std::vector<std::string> split_sets(const std::string& body, const std::string& where, const std::string& text) {
    std::vector<std::string> parts;
    std::string part;
    char quote = 0;
    std::string open;  // the brackets and braces not yet closed, innermost last
    for (std::size_t i = 0; i < body.size(); ++i) {
        const char c = body[i];
        if (quote != 0) {
            // A basic string ("...") escapes its quote with a backslash; a literal one ('...') has no escapes.
            if (c == '\\' && quote == '"' && i + 1 < body.size()) {
                part += c;
                part += body[++i];
                continue;
            }
            if (c == quote) quote = 0;
            part += c;
            continue;
        }
        if (c == '"' || c == '\'') {
            quote = c;
        } else if (c == '[' || c == '{') {
            open += c;
        } else if (c == ']' || c == '}') {
            if (open.empty() || open.back() != (c == ']' ? '[' : '{'))
                refuse(where, text, std::string("a '") + c + "' closes nothing");
            open.pop_back();
        } else if (c == ',' && open.empty()) {
            parts.push_back(part);
            part.clear();
            continue;
        }
        part += c;
    }
    if (quote != 0) refuse(where, text, std::string("a ") + quote + " is not closed");
    if (!open.empty()) refuse(where, text, std::string("a '") + open.back() + "' is not closed");
    parts.push_back(part);
    return parts;
}

}  // namespace

Variant parse_variant(const std::string& text, const std::string& where) {
    const auto colon = text.find(':');
    if (colon == std::string::npos) refuse(where, text, "no ':' after the name");
    Variant v{trimmed(text.substr(0, colon)), {}};
    if (v.name.empty()) refuse(where, text, "no name before the ':'");
    if (!std::all_of(v.name.begin(), v.name.end(), name_char) || v.name.front() == '.')
        refuse(where, text, "the name \"" + v.name + "\" holds a character other than letters, digits and - _ . +");
    const std::string body = trimmed(text.substr(colon + 1));
    if (body.empty()) return v;
    for (const std::string& raw : split_sets(body, where, text)) {
        const std::string set = trimmed(raw);
        if (set.empty()) refuse(where, text, "an empty assignment (two commas, or one at the end)");
        const auto eq = set.find('=');
        const std::string key = trimmed(set.substr(0, eq));
        if (eq == std::string::npos) refuse(where, text, "\"" + set + "\" is not key=value");
        if (key.empty() || !std::all_of(key.begin(), key.end(), key_char))
            refuse(where, text, "\"" + set + "\" does not start with a scenario key (`cncsim keys` lists them)");
        v.sets.push_back(key + "=" + trimmed(set.substr(eq + 1)));
    }
    return v;
}

void check_variant_names(const std::vector<Variant>& variants, const std::string& where) {
    std::set<std::string> seen;
    for (const Variant& v : variants) {
        if (!seen.insert(v.name).second)
            throw BadInput(where, "the variant name \"" + v.name + "\" is given twice; each variant needs its own");
    }
}

}  // namespace cnc::sim
