#include "scenario/key_reader.hpp"

#include <algorithm>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <sstream>

#include "common/bad_input.hpp"

namespace cnc::sim {

namespace {

std::vector<std::string> split_key(const std::string& key) {
    std::vector<std::string> parts;
    std::stringstream ss(key);
    std::string part;
    while (std::getline(ss, part, '.')) parts.push_back(part);
    return parts;
}

std::string number_text(double v) {
    std::ostringstream os;
    os << v;
    return os.str();
}

std::string type_name(const toml::node& n) {
    switch (n.type()) {
        case toml::node_type::integer:
            return "integer";
        case toml::node_type::floating_point:
            return "float";
        case toml::node_type::string:
            return "string";
        case toml::node_type::boolean:
            return "boolean";
        case toml::node_type::table:
            return "table";
        case toml::node_type::array:
            return "array";
        default:
            return "date/time";
    }
}

// "events[2]" -> ("events", 2); a part without an index -> (part, none).
std::pair<std::string, std::optional<std::size_t>> indexed_part(const std::string& part) {
    const auto open = part.find('[');
    if (open == std::string::npos || part.back() != ']') return {part, std::nullopt};
    return {part.substr(0, open), std::stoul(part.substr(open + 1, part.size() - open - 2))};
}

// The key as the documentation lists it: an array of tables' index left out ("events[2].at_s" -> "events[].at_s").
std::string listed_key(const std::string& key) {
    std::string out;
    for (std::size_t i = 0; i < key.size(); ++i) {
        out += key[i];
        if (key[i] != '[') continue;
        while (i + 1 < key.size() && key[i + 1] != ']') ++i;
    }
    return out;
}

}  // namespace

KeyReader::KeyReader(const toml::table& root, std::string file, std::vector<std::string> overridden)
    : m_root(root), m_file(std::move(file)), m_overridden(std::move(overridden)) {}

std::optional<std::string> KeyReader::override_of(const std::string& key) const {
    for (auto o = m_overridden.rbegin(); o != m_overridden.rend(); ++o) {  // the last --set of a key wins
        if (*o == key || o->rfind(key + ".", 0) == 0) return *o;
    }
    return std::nullopt;
}

const toml::node* KeyReader::find(const std::string& key) const {
    const toml::node* node = &m_root;
    for (const std::string& part : split_key(key)) {
        const toml::table* t = node->as_table();
        if (t == nullptr) return nullptr;
        const auto [name, index] = indexed_part(part);
        node = t->get(name);
        if (node == nullptr) return nullptr;
        if (!index) continue;
        const toml::array* a = node->as_array();
        if (a == nullptr || *index >= a->size()) return nullptr;
        node = a->get(*index);
    }
    return node;
}

bool KeyReader::has(const std::string& key) const {
    return find(key) != nullptr;
}

std::string KeyReader::where(const std::string& key) const {
    if (const auto o = override_of(key)) return "--set " + *o;
    const toml::node* n = find(key);
    if (n != nullptr && n->source().begin.line > 0) {
        return file_of(*n) + ":" + std::to_string(n->source().begin.line) + ": " + key;
    }
    return m_file + ": " + key;
}

std::string KeyReader::file_of(const toml::node& n) const {
    return n.source().path ? *n.source().path : m_file;
}

void KeyReader::fail(const std::string& key, const std::string& what) const {
    throw BadInput(where(key), what);
}

void KeyReader::record(KeyDoc doc) {
    doc.key = listed_key(doc.key);
    const auto same = [&](const KeyDoc& d) { return d.key == doc.key; };
    if (std::none_of(m_docs.begin(), m_docs.end(), same)) m_docs.push_back(std::move(doc));
}

double KeyReader::get_float(const std::string& key, double def, double min, double max, const std::string& doc) {
    record({key, "float", number_text(def), number_text(min) + " .. " + number_text(max), doc});
    const toml::node* n = find(key);
    if (n == nullptr) return def;
    if (!n->is_number()) fail(key, "expected a number, got " + type_name(*n));
    const double v = n->is_integer() ? static_cast<double>(n->as_integer()->get()) : n->as_floating_point()->get();
    if (!(v >= min && v <= max))
        fail(key, number_text(v) + " is out of range (allowed " + number_text(min) + " .. " + number_text(max) + ")");
    return v;
}

std::optional<double> KeyReader::get_optional_float(const std::string& key, double min, double max,
                                                    const std::string& default_text, const std::string& doc) {
    if (find(key) == nullptr) {
        record({key, "float", default_text, number_text(min) + " .. " + number_text(max), doc});
        return std::nullopt;
    }
    return get_float(key, 0.0, min, max, doc);
}

std::int64_t KeyReader::get_int(const std::string& key, std::int64_t def, std::int64_t min, std::int64_t max,
                                const std::string& doc) {
    record({key, "integer", std::to_string(def), std::to_string(min) + " .. " + std::to_string(max), doc});
    const toml::node* n = find(key);
    if (n == nullptr) return def;
    if (!n->is_integer()) fail(key, "expected an integer, got " + type_name(*n));
    const std::int64_t v = n->as_integer()->get();
    if (v < min || v > max)
        fail(key, std::to_string(v) + " is out of range (allowed " + std::to_string(min) + " .. " +
                      std::to_string(max) + ")");
    return v;
}

bool KeyReader::get_bool(const std::string& key, bool def, const std::string& doc) {
    record({key, "boolean", def ? "true" : "false", "true | false", doc});
    const toml::node* n = find(key);
    if (n == nullptr) return def;
    if (!n->is_boolean()) fail(key, "expected true or false, got " + type_name(*n));
    return n->as_boolean()->get();
}

std::string KeyReader::get_string(const std::string& key, const std::string& def, const std::string& doc) {
    record({key, "string", def.empty() ? "\"\"" : "\"" + def + "\"", "", doc});
    const toml::node* n = find(key);
    if (n == nullptr) return def;
    if (!n->is_string()) fail(key, "expected a string, got " + type_name(*n));
    return n->as_string()->get();
}

std::vector<std::string> KeyReader::get_string_list(const std::string& key, const std::string& doc) {
    record({key, "array of strings", "[]", "", doc});
    const toml::node* n = find(key);
    if (n == nullptr) return {};
    if (!n->is_array()) fail(key, "expected an array of strings ([\"a\", \"b\"]), got " + type_name(*n));
    std::vector<std::string> out;
    for (const toml::node& item : *n->as_array()) {
        if (!item.is_string()) fail(key, "expected an array of strings, it holds a " + type_name(item));
        out.push_back(item.as_string()->get());
    }
    return out;
}

std::string KeyReader::get_choice(const std::string& key, const std::string& def,
                                  const std::vector<std::string>& choices, const std::string& doc) {
    std::string allowed;
    for (const std::string& c : choices) allowed += (allowed.empty() ? "" : " | ") + c;
    record({key, "string", "\"" + def + "\"", allowed, doc});
    const toml::node* n = find(key);
    if (n == nullptr) return def;
    if (!n->is_string()) fail(key, "expected a string (" + allowed + "), got " + type_name(*n));
    const std::string v = n->as_string()->get();
    if (std::find(choices.begin(), choices.end(), v) == choices.end()) {
        fail(key, "'" + v + "' is not allowed (allowed: " + allowed + ")");
    }
    return v;
}

std::size_t KeyReader::get_table_count(const std::string& key, const std::string& doc) {
    record({key + "[]", kArrayOfTables, "none", "", doc});
    const toml::node* n = find(key);
    if (n == nullptr) return 0;
    const toml::array* a = n->as_array();
    if (a == nullptr || !a->is_array_of_tables()) fail(key, "expected tables ([[" + key + "]]), got " + type_name(*n));
    return a->size();
}

void KeyReader::reject_unknown_keys() const {
    std::function<void(const toml::table&, const std::string&)> walk = [&](const toml::table& t,
                                                                           const std::string& prefix) {
        for (const auto& [k, node] : t) {
            const std::string key = prefix.empty() ? std::string(k.str()) : prefix + "." + std::string(k.str());
            const std::string listed = listed_key(key);
            const auto known = [&](const KeyDoc& d) { return d.key == listed; };
            const auto inside = [&](const KeyDoc& d) { return d.key.rfind(listed + ".", 0) == 0; };
            const auto tables = [&](const KeyDoc& d) { return d.key == listed + "[]"; };
            if (std::any_of(m_docs.begin(), m_docs.end(), known)) continue;
            if (node.is_table() && std::any_of(m_docs.begin(), m_docs.end(), inside)) {
                walk(*node.as_table(), key);
                continue;
            }
            if (node.is_array_of_tables() && std::any_of(m_docs.begin(), m_docs.end(), tables)) {
                const toml::array& a = *node.as_array();
                for (std::size_t i = 0; i < a.size(); ++i) walk(*a.get(i)->as_table(), key + "[" + std::to_string(i) + "]");
                continue;
            }
            std::vector<std::string> siblings;
            const std::string parent = prefix.empty() ? "" : prefix + ".";
            const std::string listed_parent = listed_key(parent);
            for (const KeyDoc& d : m_docs) {
                if (d.key.rfind(listed_parent, 0) != 0) continue;
                const std::string rest = d.key.substr(listed_parent.size());
                const std::string child = rest.substr(0, rest.find('.'));
                if (std::find(siblings.begin(), siblings.end(), child) == siblings.end()) siblings.push_back(child);
            }
            std::string allowed;
            for (const std::string& c : siblings) allowed += (allowed.empty() ? " " : ", ") + c;
            const std::string scope = prefix.empty() ? "at the top level" : "in [" + prefix + "]";
            const int line = node.source().begin.line;
            const std::optional<std::string> o = override_of(key);
            throw BadInput(
                o ? "--set " + *o : file_of(node) + (line > 0 ? ":" + std::to_string(line) : "") + ": " + key,
                "unknown key (allowed " + scope + ":" + allowed + ")");
        }
    };
    walk(m_root, "");
}

std::string override_key(const std::string& assignment) {
    const auto eq = assignment.find('=');
    if (eq == std::string::npos || eq == 0) {
        throw BadInput("--set " + assignment, "expected key=value (e.g. link.baud=57600)");
    }
    return assignment.substr(0, eq);
}

void apply_override(toml::table& root, const std::string& assignment) {
    const std::string key = override_key(assignment);
    const std::string value = assignment.substr(key.size() + 1);
    std::vector<std::string> parts = split_key(key);
    toml::table* t = &root;
    for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
        toml::node* child = t->get(parts[i]);
        if (child == nullptr) {
            t->insert(parts[i], toml::table{});
            child = t->get(parts[i]);
        }
        if (!child->is_table()) throw BadInput("--set " + key, "'" + parts[i] + "' is not a table");
        t = child->as_table();
    }
    toml::table parsed;
    try {
        parsed = toml::parse("v = " + value);
    } catch (const toml::parse_error&) {
        t->insert_or_assign(parts.back(), value);
        return;
    }
    t->insert_or_assign(parts.back(), *parsed.get("v"));
}

std::string keys_markdown(const std::vector<KeyDoc>& docs) {
    std::ostringstream os;
    os << "| key | type | default | allowed | meaning |\n|---|---|---|---|---|\n";
    for (const KeyDoc& d : docs) {
        std::string allowed = d.allowed;
        for (auto at = allowed.find('|'); at != std::string::npos; at = allowed.find('|', at + 2)) {
            allowed.replace(at, 1, "\\|");  // a bare | would end the Markdown cell
        }
        os << "| `" << d.key << "` | " << d.type << " | `" << d.default_text << "` | " << allowed << " | " << d.doc
           << " |\n";
    }
    return os.str();
}

}  // namespace cnc::sim
