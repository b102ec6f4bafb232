// Files the CLI writes (report, VCD, and any later output): checked before anything is simulated, and written
// so that no file claims to be complete when it is not.
//
// A regular file is written as PATH.partial and renamed to PATH when it is complete (an older PATH goes when
// writing starts), so a run that fails to write it, is killed or stops on an error leaves no PATH behind; after
// a write or close error the .partial file is removed too (on a full disk it would only take the last space).
// A device or pipe (/dev/null, /dev/full, /dev/stdout) cannot be renamed: it is written in place, and a write
// or close error fails the run all the same.
#pragma once
#include <fstream>
#include <optional>
#include <stdexcept>
#include <string>

namespace cnc::sim {

// A write or close error of an output file: the run fails (exit 1).
class OutputError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Throws BadInput(label + " " + path, ...) when `path` cannot be written: its folder does not exist or is not
// writable, it is a folder, or it exists and is not writable. `label` names where the path came from
// ("--report", "s.toml: trace.vcd").
void check_output_path(const std::string& path, const std::string& label);

// The same for an output folder (--plots, --out): it exists and is a writable folder, or it can be created
// (its nearest existing ancestor is a writable folder).
void check_output_dir(const std::string& path, const std::string& label);

class OutputFile {
public:
    // Opens the file (after check_output_path); BadInput naming `label` if it cannot.
    OutputFile(std::string path, std::string label);
    ~OutputFile();  // not closed (an exception left the run): the .partial file is removed
    OutputFile(const OutputFile&) = delete;
    OutputFile& operator=(const OutputFile&) = delete;

    [[nodiscard]] std::ostream& stream() { return m_out; }
    // Whether a write has failed so far (the error is kept for close()).
    [[nodiscard]] bool failed();
    // Ends the file: flushes, closes and renames it to its path. Throws OutputError naming the file when a
    // write or the close failed, after removing the .partial file.
    void close();

private:
    [[nodiscard]] std::string error_text() const;

    std::string m_path;
    std::string m_label;
    std::string m_written;  // m_path, or m_path + ".partial"
    std::ofstream m_out;
    std::string m_error;  // the first write error (strerror of the failing call)
    bool m_closed = false;
};

// Writes `text` to `path` as one OutputFile.
void write_output_file(const std::string& path, const std::string& label, const std::string& text);

}  // namespace cnc::sim
