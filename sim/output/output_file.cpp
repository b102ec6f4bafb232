#include "output/output_file.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <system_error>

#include "common/bad_input.hpp"

namespace cnc::sim {

namespace {

namespace fs = std::filesystem;

// Regular files (or new ones) are written beside their path and renamed; anything else is written in place.
bool written_in_place(const std::string& path) {
    std::error_code ec;
    const fs::file_status st = fs::status(path, ec);
    return fs::exists(st) && !fs::is_regular_file(st);
}

}  // namespace

void check_output_path(const std::string& path, const std::string& label) {
    const std::string where = label + " " + path;
    if (path.empty()) throw BadInput(label, "the output file name is empty");
    std::error_code ec;
    const fs::file_status st = fs::status(path, ec);
    if (fs::is_directory(st)) throw BadInput(where, "is a folder, not a file");
    if (fs::exists(st)) {
        if (access(path.c_str(), W_OK) != 0) {
            throw BadInput(where, std::string("cannot be written: ") + std::strerror(errno));
        }
        if (!fs::is_regular_file(st)) return;  // a device or pipe: written in place
    }
    const fs::path parent = fs::path(path).parent_path();
    const fs::path folder = parent.empty() ? fs::path(".") : parent;
    if (!fs::is_directory(folder, ec)) throw BadInput(where, "its folder " + folder.string() + " does not exist");
    // The .partial file is created there, and renamed or removed.
    if (access(folder.c_str(), W_OK | X_OK) != 0) {
        throw BadInput(where, "its folder " + folder.string() + " is not writable: " + std::strerror(errno));
    }
}

void check_output_dir(const std::string& path, const std::string& label) {
    const std::string where = label + " " + path;
    if (path.empty()) throw BadInput(label, "the output folder name is empty");
    std::error_code ec;
    fs::path folder = fs::absolute(path, ec);
    while (!fs::exists(folder, ec) && folder.has_parent_path() && folder != folder.parent_path()) {
        folder = folder.parent_path();
    }
    if (!fs::is_directory(folder, ec)) throw BadInput(where, folder.string() + " is not a folder");
    if (access(folder.c_str(), W_OK | X_OK) != 0) {
        throw BadInput(where, folder.string() + " is not writable: " + std::strerror(errno));
    }
}

OutputFile::OutputFile(std::string path, std::string label) : m_path(std::move(path)), m_label(std::move(label)) {
    check_output_path(m_path, m_label);
    m_written = written_in_place(m_path) ? m_path : m_path + ".partial";
    if (m_written != m_path) {
        std::error_code ec;
        fs::remove(m_path, ec);  // an older file of the same name would claim to be this run's
    }
    m_out.open(m_written, std::ios::binary | std::ios::trunc);
    if (!m_out) throw BadInput(m_label + " " + m_path, std::string("cannot be written: ") + std::strerror(errno));
}

OutputFile::~OutputFile() {
    if (m_closed || m_written == m_path) return;
    m_out.close();
    std::error_code ec;
    fs::remove(m_written, ec);
}

bool OutputFile::failed() {
    if (!m_out && m_error.empty()) m_error = std::strerror(errno != 0 ? errno : EIO);
    return !m_error.empty();
}

std::string OutputFile::error_text() const {
    return "cannot write " + m_path + " (" + m_label + "): " + m_error +
           (m_written == m_path ? "" : "; the incomplete file was removed");
}

void OutputFile::close() {
    m_closed = true;
    (void)failed();
    m_out.flush();
    (void)failed();
    m_out.close();
    (void)failed();
    std::error_code ec;
    if (m_error.empty() && m_written != m_path) {
        fs::rename(m_written, m_path, ec);
        if (ec) m_error = ec.message();
    }
    if (m_error.empty()) return;
    if (m_written != m_path) fs::remove(m_written, ec);
    throw OutputError(error_text());
}

void write_output_file(const std::string& path, const std::string& label, const std::string& text) {
    OutputFile file(path, label);
    file.stream() << text;
    file.close();
}

}  // namespace cnc::sim
