// A design variant of `cncsim compare`: a name and the --set overrides that make it, written
// "NAME: key=value, key=value" on the command line (--variant) and in a scenario's compare.variants.
#pragma once
#include <string>
#include <vector>

namespace cnc::sim {

struct Variant {
    std::string name;               // letters, digits and - _ . + (a file name in compare --out)
    std::vector<std::string> sets;  // key=value, applied after the command's own --set
};

// What a variant may be, for the messages and the docs.
extern const char* const kVariantSyntax;

// Reads "NAME: key=value, key=value". The assignments are split at the commas that are neither inside a quoted
// string ("..." or '...') nor inside brackets or braces, so a TOML array or inline table is one value; "NAME:" alone
// is the scenario as it is. Throws BadInput(where, ...) naming what is wrong and what is allowed. The keys are
// checked when the scenario is read with them, not here.
Variant parse_variant(const std::string& text, const std::string& where);

// Each variant once by name: BadInput(where, ...) naming the first name given twice.
void check_variant_names(const std::vector<Variant>& variants, const std::string& where);

}  // namespace cnc::sim
