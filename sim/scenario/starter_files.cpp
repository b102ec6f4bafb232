#include "scenario/starter_files.hpp"

#include <algorithm>
#include <map>

#include "scenario/key_listing.hpp"
#include "scenario/scenario.hpp"

namespace cnc::sim {

namespace {

constexpr std::size_t kCommentWidth = 100;  // the width of the project's own files (.clang-format)
const char* const kScenarioFile = "scenario.toml";
const char* const kMachineFile = "machine.toml";
const char* const kJobFile = "job.nc";

const char* const kScenarioHead =
    "A cncsim scenario: one job on one machine through one controller architecture "
    "(docs/scenario-reference.md). `cncsim run scenario.toml` runs it, `cncsim compare scenario.toml` runs it on "
    "every architecture, `--set key=value` overrides a key on the command line. Paths are relative to this file. "
    "The keys set below are the ones a run needs; every other key is commented out at its default: remove its # to "
    "change it. `cncsim keys PREFIX` describes the keys; docs/scenario-reference.md says which architecture reads "
    "which.";

const char* const kMachineHead =
    "A cncsim machine file: the machine every architecture drives, named by a scenario's scenario.machine or by "
    "`cncsim run JOB.nc --machine machine.toml`. It holds only the machine's tables. Every key is commented out at "
    "its default, which is the seed 000 machine (docs/architectures.md): remove its # to change it.";

// Our own job: a 10 mm square engraved at F600, inside any machine of 20 mm travel.
const char* const kJob =
    "(cncsim init: a 10 mm square engraved at F600 from X5 Y5; put your own job here or name it in scenario.toml)\n"
    "G21 G90 G17 G94\n"
    "G0 X5 Y5\n"
    "M3 S255\n"
    "G1 X15 Y5 F600\n"
    "G1 X15 Y15\n"
    "G1 X5 Y15\n"
    "G1 X5 Y5\n"
    "M5\n"
    "G0 X0 Y0\n"
    "M30\n";

std::string parent_table(const std::string& key) {
    return key.substr(0, key.rfind('.'));
}

// The keys as TOML, a table header once per table (in the order the tables are first read), each key after its
// meaning; the keys of `set` with that value, every other commented out at its default.
std::string toml_text(const char* head, const std::vector<KeyDoc>& keys,
                      const std::map<std::string, std::string>& set) {
    std::vector<std::string> tables;
    std::map<std::string, std::string> table_docs;  // an array of tables' own meaning ("events[]": ...)
    for (const KeyDoc& d : keys) {
        if (d.type == kArrayOfTables) {
            table_docs[d.key] = d.doc;
            continue;
        }
        if (std::find(tables.begin(), tables.end(), parent_table(d.key)) == tables.end()) {
            tables.push_back(parent_table(d.key));
        }
    }
    std::string out = wrap_text(head, kCommentWidth, "# ");
    for (const std::string& table : tables) {
        // An array of tables has none by default: its header and keys are an example, commented out.
        const bool array = table.size() > 2 && table.compare(table.size() - 2, 2, "[]") == 0;
        if (array) {
            out += "\n" + wrap_text(table_docs[table], kCommentWidth, "# ") + "# [[" +
                   table.substr(0, table.size() - 2) + "]]\n";
        } else {
            out += "\n[" + table + "]\n";
        }
        for (const KeyDoc& d : keys) {
            if (d.type == kArrayOfTables || parent_table(d.key) != table) continue;
            const std::string name = d.key.substr(table.size() + 1);
            out += wrap_text(d.doc + (d.allowed.empty() ? "" : " (allowed: " + d.allowed + ")"), kCommentWidth, "# ");
            const auto value = set.find(d.key);
            out += value != set.end() && !array ? name + " = " + value->second + "\n\n"
                                                : "# " + name + " = " + d.default_text + "\n\n";
        }
    }
    return out;
}

std::string quoted(const std::string& text) {
    return "\"" + text + "\"";
}

}  // namespace

std::vector<StarterFile> starter_files(const std::vector<KeyDoc>& docs) {
    std::vector<KeyDoc> own_keys, machine_keys;
    for (const KeyDoc& d : docs) (is_machine_key(d.key) ? machine_keys : own_keys).push_back(d);
    std::map<std::string, std::string> set = {{"scenario.job", quoted(kJobFile)},
                                              {"scenario.machine", quoted(kMachineFile)}};
    for (const KeyDoc& d : docs) {
        if (d.key == "scenario.architecture") set[d.key] = d.default_text;
    }
    return {{kScenarioFile, toml_text(kScenarioHead, own_keys, set)},
            {kMachineFile, toml_text(kMachineHead, machine_keys, {})},
            {kJobFile, kJob}};
}

}  // namespace cnc::sim
