// VCD reader: a tokenizer over lines (for file:line messages), the header (scopes, 1-bit vars,
// timescale) and the value changes, turned into edge logs of integer ps times.
#include "metrics/vcd/vcd_reader.hpp"

#include <cctype>
#include <cstdint>
#include <istream>
#include <limits>
#include <optional>
#include <unordered_map>

#include "common/bad_input.hpp"
#include "metrics/vcd/vcd_timescale.hpp"

namespace cnc::metrics {

namespace {

struct Token {
    std::string text;
    std::size_t line = 0;
};

// White-space separated tokens with their line numbers.
class Tokenizer {
public:
    explicit Tokenizer(std::istream& in) : m_in(in) {}

    bool next(Token& tok) {
        while (m_pos >= m_text.size()) {
            if (!std::getline(m_in, m_text)) return false;
            ++m_line;
            m_pos = 0;
            skip_space();
        }
        const std::size_t start = m_pos;
        while (m_pos < m_text.size() && !std::isspace(static_cast<unsigned char>(m_text[m_pos]))) ++m_pos;
        tok.text.assign(m_text, start, m_pos - start);
        tok.line = m_line;
        skip_space();
        return true;
    }
    // Drops the rest of the current line.
    void skip_line() { m_pos = m_text.size(); }
    [[nodiscard]] std::size_t line() const { return m_line; }

private:
    void skip_space() {
        while (m_pos < m_text.size() && std::isspace(static_cast<unsigned char>(m_text[m_pos]))) ++m_pos;
    }

    std::istream& m_in;
    std::string m_text;
    std::size_t m_pos = 0;
    std::size_t m_line = 0;
};

struct Var {
    std::string full_name;
    std::string leaf_name;
    std::size_t decl_line = 0;
    bool kept = false;  // a 1-bit signal
    std::string kind;   // for the others: "32 bits wide (wire)", "64 bits wide (real)"
    bool has_value = false;
    bool level = false;
    EdgeLog log;
};

class VcdReader {
public:
    VcdReader(std::istream& in, std::string filename) : m_tokens(in), m_file(std::move(filename)) {}

    VcdContents read() {
        read_header();
        read_body();
        return collect();
    }

private:
    [[noreturn]] void fail(std::size_t line, const std::string& what) const {
        throw BadInput(m_file + ":" + std::to_string(line), what);
    }

    // Tokens up to the closing $end of a section opened on `open_line`.
    std::vector<Token> section_body(const std::string& keyword, std::size_t open_line) {
        std::vector<Token> out;
        Token tok;
        while (m_tokens.next(tok)) {
            if (tok.text == "$end") return out;
            out.push_back(tok);
        }
        fail(open_line, keyword + " is not closed by $end");
    }

    void read_header() {
        Token tok;
        while (m_tokens.next(tok)) {
            const std::string& k = tok.text;
            if (k == "$enddefinitions") {
                section_body(k, tok.line);
                if (!m_timescale_fs) fail(tok.line, "no $timescale before $enddefinitions");
                return;
            }
            if (k == "$timescale") {
                read_timescale(section_body(k, tok.line), tok.line);
            } else if (k == "$scope") {
                const std::vector<Token> body = section_body(k, tok.line);
                // "$scope module top $end"; some writers leave the type out ("$scope top $end").
                if (body.empty() || body.size() > 2) fail(tok.line, "$scope needs a type and a name");
                m_scopes.push_back(body.back().text);
            } else if (k == "$upscope") {
                section_body(k, tok.line);
                if (m_scopes.empty()) fail(tok.line, "$upscope without an open $scope");
                m_scopes.pop_back();
            } else if (k == "$var") {
                read_var(section_body(k, tok.line), tok.line);
            } else if (!k.empty() && k[0] == '$') {
                section_body(k, tok.line);  // $date, $version, $comment and tool-specific sections
            } else if (k == "META") {
                m_tokens.skip_line();  // sigrok-cli's "META samplerate: 1000000000"
            } else {
                fail(tok.line, "unexpected '" + k + "' in the header");
            }
        }
        fail(m_tokens.line(), "the header has no $enddefinitions");
    }

    void read_timescale(const std::vector<Token>& body, std::size_t line) {
        std::string text;
        for (const Token& t : body) text += t.text;
        m_timescale_fs = parse_vcd_timescale_fs(text);
        if (!m_timescale_fs) {
            fail(line, "$timescale '" + text + "' is not 1, 10 or 100 of s, ms, us, ns, ps or fs");
        }
    }

    void read_var(const std::vector<Token>& body, std::size_t line) {
        if (body.size() < 4) fail(line, "$var needs a type, a size, an identifier and a name");
        const std::string& type = body[0].text;
        const std::string& size_text = body[1].text;
        if (size_text.empty() || size_text.find_first_not_of("0123456789") != std::string::npos ||
            size_text.size() > 9) {
            fail(line, "$var size '" + size_text + "' is not a number");
        }
        const bool one_bit =
            std::stoul(size_text) == 1 && type != "real" && type != "realtime" && type != "event" && type != "string";
        Var v;
        v.leaf_name = body[3].text;
        // A 1-bit select keeps its index ("data [3]" -> "data[3]"); a vector's range ("cnt [31:0]") is not a name.
        for (std::size_t i = 4; one_bit && i < body.size(); ++i) v.leaf_name += body[i].text;
        for (const std::string& s : m_scopes) v.full_name += s + ".";
        v.full_name += v.leaf_name;
        v.decl_line = line;
        v.kept = one_bit;
        v.kind = size_text + " bits wide (" + type + ")";
        m_ids[body[2].text].push_back(m_vars.size());
        m_vars.push_back(std::move(v));
    }

    // The open $dump... section, if any: $dumpvars values may set initial levels, $dumpoff values are x.
    enum class Block { None, Dump, DumpVars, DumpOff };

    void read_body() {
        Token tok;
        Block block = Block::None;
        while (m_tokens.next(tok)) {
            const std::string& k = tok.text;
            const char c = k[0];
            if (c == '#') {
                read_time(tok);
            } else if (c == '$') {
                if (k == "$end") {
                    if (block == Block::None) {
                        fail(tok.line, "$end without an open $dumpvars/$dumpall/$dumpon/$dumpoff");
                    }
                    block = Block::None;
                } else if (k == "$dumpvars" || k == "$dumpall" || k == "$dumpon" || k == "$dumpoff") {
                    if (block != Block::None) fail(tok.line, k + " inside an open " + m_block_keyword);
                    block = k == "$dumpvars" ? Block::DumpVars : k == "$dumpoff" ? Block::DumpOff : Block::Dump;
                    m_block_keyword = k;
                    m_block_line = tok.line;
                } else if (k == "$comment") {
                    section_body(k, tok.line);
                } else {
                    fail(tok.line, "unexpected '" + k + "' after $enddefinitions");
                }
            } else if (c == '0' || c == '1' || c == 'x' || c == 'X' || c == 'z' || c == 'Z') {
                if (k.size() < 2) fail(tok.line, "value change '" + k + "' has no identifier");
                const std::vector<std::size_t>& vars = vars_of(k.substr(1), tok.line);
                if (block != Block::DumpOff) apply(vars, c == '1', block == Block::DumpVars);
            } else if (c == 'b' || c == 'B' || c == 'r' || c == 'R') {
                read_vector(tok, block);
            } else {
                fail(tok.line, "unexpected '" + k + "'");
            }
        }
        if (block != Block::None) fail(m_block_line, m_block_keyword + " is not closed by $end");
    }

    void read_time(const Token& tok) {
        const std::string digits = tok.text.substr(1);
        if (digits.empty() || digits.find_first_not_of("0123456789") != std::string::npos) {
            fail(tok.line, "time '" + tok.text + "' is not a whole number");
        }
        constexpr std::int64_t kMax = std::numeric_limits<std::int64_t>::max();
        std::int64_t units = 0;
        for (const char d : digits) {
            if (units > (kMax - (d - '0')) / 10) fail(tok.line, "time '" + tok.text + "' is too large");
            units = units * 10 + (d - '0');
        }
        const std::optional<TimePs> t_ps = vcd_ticks_to_ps(units, *m_timescale_fs);
        if (!t_ps) fail(tok.line, "time '" + tok.text + "' is too large in ps");
        const TimePs t = *t_ps;
        if (m_time_ps && t < *m_time_ps) fail(tok.line, "time goes backwards (" + tok.text + ")");
        if (!m_first_time_ps) m_first_time_ps = t;
        m_time_ps = t;
    }

    void read_vector(const Token& tok, Block block) {
        Token id;
        if (!m_tokens.next(id)) fail(tok.line, "value '" + tok.text + "' has no identifier");
        const bool real = tok.text[0] == 'r' || tok.text[0] == 'R';
        const std::string bits = tok.text.substr(1);
        if (!real && (bits.empty() || bits.find_first_not_of("01xXzZ") != std::string::npos)) {
            fail(tok.line, "vector value '" + tok.text + "' is not binary");
        }
        const std::vector<std::size_t>& vars = vars_of(id.text, id.line);
        // A 1-bit variable written in vector form takes the value's last (least significant) bit.
        if (!real && block != Block::DumpOff) apply(vars, bits.back() == '1', block == Block::DumpVars);
    }

    const std::vector<std::size_t>& vars_of(const std::string& id, std::size_t line) const {
        const auto it = m_ids.find(id);
        if (it == m_ids.end()) fail(line, "value change for undeclared identifier '" + id + "'");
        return it->second;
    }

    void apply(const std::vector<std::size_t>& vars, bool level, bool in_dumpvars) {
        const TimePs t = m_time_ps.value_or(0);
        const bool at_start = !m_time_ps || t == *m_first_time_ps;
        for (const std::size_t i : vars) {
            Var& v = m_vars[i];
            if (!v.kept) continue;
            if (!v.has_value && (in_dumpvars || at_start)) {
                v.log.initial = level;
            } else if (level != v.level) {
                v.log.add(t, level);
            }
            v.has_value = true;
            v.level = level;
        }
    }

    VcdContents collect() {
        std::map<std::string, std::size_t> leaf_count;
        for (const Var& v : m_vars) {
            if (v.kept) ++leaf_count[v.leaf_name];
        }
        VcdContents out;
        for (Var& v : m_vars) {
            if (!v.kept) {
                out.other_variables.emplace(v.leaf_name, v.kind);
                out.other_variables.emplace(v.full_name, v.kind);
                continue;
            }
            const std::string key = leaf_count[v.leaf_name] == 1 ? v.leaf_name : v.full_name;
            if (out.signals.count(key) != 0) fail(v.decl_line, "signal '" + key + "' is declared twice");
            v.log.name = key;
            out.paths.emplace(v.full_name, key);
            out.signals.emplace(key, std::move(v.log));
        }
        return out;
    }

    Tokenizer m_tokens;
    std::string m_file;
    std::optional<std::int64_t> m_timescale_fs;
    std::vector<std::string> m_scopes;
    std::vector<Var> m_vars;
    std::unordered_map<std::string, std::vector<std::size_t>> m_ids;
    std::optional<TimePs> m_time_ps;
    std::optional<TimePs> m_first_time_ps;
    std::string m_block_keyword;
    std::size_t m_block_line = 0;
};

}  // namespace

VcdContents read_vcd(std::istream& in, const std::string& filename) {
    return VcdReader(in, filename).read();
}

const EdgeLog* find_vcd_signal(const VcdContents& vcd, const std::string& name) {
    const auto it = vcd.signals.find(name);
    if (it != vcd.signals.end()) return &it->second;
    const std::string tail = "." + name;
    const EdgeLog* found = nullptr;
    for (const auto& [path, key] : vcd.paths) {
        const bool ends = path.size() > tail.size() && path.compare(path.size() - tail.size(), tail.size(), tail) == 0;
        if (!ends && path != name) continue;
        if (found != nullptr) return nullptr;
        found = &vcd.signals.at(key);
    }
    return found;
}

}  // namespace cnc::metrics
