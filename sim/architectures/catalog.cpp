#include "architectures/catalog.hpp"

#include "architectures/registry.hpp"
#include "common/bad_input.hpp"

namespace cnc::sim {

namespace {

template <typename... Entries>
std::vector<const Architecture*> descriptions(EntryList<Entries...>) {
    return {&Entries::architecture()...};
}

}  // namespace

const std::vector<const Architecture*>& architectures() {
    static const std::vector<const Architecture*> list = descriptions(Registry{});
    return list;
}

std::vector<std::string> architecture_names() {
    std::vector<std::string> names;
    for (const Architecture* a : architectures()) names.push_back(a->name());
    return names;
}

std::string architecture_list() {
    std::string text;
    for (const Architecture* a : architectures()) text += (text.empty() ? "" : ", ") + a->name();
    return text;
}

const Architecture* baseline_architecture() {
    for (const Architecture* a : architectures()) {
        if (a->baseline()) return a;
    }
    return nullptr;
}

const Architecture& find_architecture(const std::string& name, const std::string& where) {
    for (const Architecture* a : architectures()) {
        if (name == a->name()) return *a;
    }
    throw BadInput(where, "unknown architecture '" + name + "' (allowed: " + architecture_list() + ")");
}

}  // namespace cnc::sim
