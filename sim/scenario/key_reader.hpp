// Typed, documented, validated access to a scenario's TOML tables. Every getter registers its key (type,
// default, range, unit, doc) so that one code path both validates a scenario and generates the
// scenario reference; keys a scenario sets that no getter read are reported as unknown.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <toml++/toml.h>

namespace cnc::sim {

inline constexpr const char* kArrayOfTables = "array of tables";  // KeyDoc::type of an array of tables itself

struct KeyDoc {
    std::string key;   // dotted path: link.baud
    std::string type;  // integer | float | string | boolean | array of strings
    std::string default_text;
    std::string allowed;  // "1 .. 65535", "belt | leadscrew"
    std::string doc;      // one line, unit included
};

class KeyReader {
public:
    // `file` names the scenario in messages (a key read from another file, its machine file, names that one); `root`
    // is the whole document (after --set overrides). Messages about
    // a key that `overridden` lists (--set keys) name "--set key" instead of the file.
    KeyReader(const toml::table& root, std::string file, std::vector<std::string> overridden = {});

    double get_float(const std::string& key, double def, double min, double max, const std::string& doc);
    std::int64_t get_int(const std::string& key, std::int64_t def, std::int64_t min, std::int64_t max,
                         const std::string& doc);
    bool get_bool(const std::string& key, bool def, const std::string& doc);
    // A number with no default value: empty when the document does not set it (`default_text` says what then).
    std::optional<double> get_optional_float(const std::string& key, double min, double max,
                                             const std::string& default_text, const std::string& doc);
    std::string get_string(const std::string& key, const std::string& def, const std::string& doc);
    // An array of strings (empty by default).
    std::vector<std::string> get_string_list(const std::string& key, const std::string& doc);
    // The number of tables in the array of tables `key` ([[key]] in TOML; 0 without one). Their keys are read as
    // "key[i].field" and listed as "key[].field".
    std::size_t get_table_count(const std::string& key, const std::string& doc);
    // A string from a fixed set of choices.
    std::string get_choice(const std::string& key, const std::string& def, const std::vector<std::string>& choices,
                           const std::string& doc);

    // Throws BadInput naming the first key the document holds that no getter asked for.
    void reject_unknown_keys() const;
    // BadInput for `key` with the key's line when the document has it.
    [[noreturn]] void fail(const std::string& key, const std::string& what) const;

    // "file:line: key" (the line when the document has one), or "--set key" for a key set on the command line.
    [[nodiscard]] std::string where(const std::string& key) const;
    [[nodiscard]] const std::vector<KeyDoc>& docs() const { return m_docs; }
    [[nodiscard]] bool has(const std::string& key) const;

private:
    const toml::node* find(const std::string& key) const;
    // The file a key was read from: a scenario's machine file (scenario.machine) for the keys it gave.
    std::string file_of(const toml::node& n) const;
    void record(KeyDoc doc);
    // The --set key that set `key` or, for a table, a key inside it.
    std::optional<std::string> override_of(const std::string& key) const;

    const toml::table& m_root;
    std::string m_file;
    std::vector<std::string> m_overridden;
    std::vector<KeyDoc> m_docs;
};

// The key of `--set key=value` (BadInput naming the option if there is no '=').
std::string override_key(const std::string& assignment);

// Applies `--set key=value`: the value is parsed as a TOML value (42, 1.5, true, "text"); anything that is not a
// TOML value is taken as a bare string (paths). Creates intermediate tables.
void apply_override(toml::table& root, const std::string& assignment);

// Markdown table of the keys (docs/scenario-reference.md).
std::string keys_markdown(const std::vector<KeyDoc>& docs);

}  // namespace cnc::sim
