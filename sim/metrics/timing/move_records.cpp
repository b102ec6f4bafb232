#include "metrics/timing/move_records.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <type_traits>

namespace cnc::metrics {

namespace {

// A row: the fixed fields, then per axis the commanded and emitted steps and the sync error. An optional is a
// presence byte and its value; a vector of up to `axes` values is a count byte and `axes` slots.
constexpr std::size_t kOptSize = 1 + sizeof(double);
constexpr std::size_t kFixedSize = 2 * sizeof(std::int32_t) + sizeof(std::uint64_t) + 2 + sizeof(double) +
                                   2 * (1 + sizeof(TimePs)) + 3 * kOptSize + (1 + sizeof(std::size_t)) +
                                   (1 + sizeof(TimePs)) + sizeof(std::uint64_t) + 5 * kOptSize + 1 +
                                   3 * sizeof(double) + 2 * kOptSize;
constexpr std::size_t kPerAxisSize = 2 * sizeof(std::int64_t) + kOptSize;
constexpr std::size_t kVectorCounts = 3;
// Rows gathered before a write and read per pread: large enough that a pass costs few system calls, small
// against the memory budget (docs/streaming.md).
constexpr std::size_t kBufferBytes = 64 * 1024;

class RowWriter {
public:
    explicit RowWriter(unsigned char* at) : m_at(at) {}
    template <typename Stored, typename T>
    void as(const T& v) {
        field(static_cast<Stored>(v));
    }
    template <typename T>
    void field(const T& v) {
        static_assert(std::is_arithmetic_v<T>);
        std::memcpy(m_at, &v, sizeof v);
        m_at += sizeof v;
    }
    template <typename T>
    void field(const std::optional<T>& v) {
        as<std::uint8_t>(v.has_value());
        field(v.value_or(T{}));
    }
    template <typename T>
    void field(const std::vector<T>& v, std::size_t slots) {
        as<std::uint8_t>(v.size());
        for (std::size_t i = 0; i < slots; ++i) field(i < v.size() ? v[i] : T{});
    }

private:
    unsigned char* m_at;
};

class RowReader {
public:
    explicit RowReader(const unsigned char* at) : m_at(at) {}
    template <typename Stored, typename T>
    void as(T& v) {
        Stored stored{};
        field(stored);
        v = static_cast<T>(stored);
    }
    template <typename T>
    void field(T& v) {
        static_assert(std::is_arithmetic_v<T>);
        std::memcpy(&v, m_at, sizeof v);
        m_at += sizeof v;
    }
    template <typename T>
    void field(std::optional<T>& v) {
        std::uint8_t present = 0;
        T value{};
        field(present);
        field(value);
        v = present != 0 ? std::optional<T>(value) : std::nullopt;
    }
    template <typename T>
    void field(std::vector<T>& v, std::size_t slots) {
        std::uint8_t n = 0;
        field(n);
        v.resize(n);
        for (std::size_t i = 0; i < slots; ++i) {
            T value{};
            field(value);
            if (i < n) v[i] = value;
        }
    }

private:
    const unsigned char* m_at;
};

// The row's fields in their order, for writing (RowWriter, a const move) and reading back (RowReader).
template <typename Row, typename Move>
void row_fields(Row& r, Move& m, std::size_t axes) {
    r.template as<std::int32_t>(m.index);
    r.template as<std::int32_t>(m.line);
    r.template as<std::uint64_t>(m.pieces);
    r.template as<std::uint8_t>(m.timing.below_feed);
    r.field(m.feed_mm_per_min);
    r.field(m.t_first_edge_ps);
    r.field(m.t_last_edge_ps);
    r.field(m.timing.motion_time_s);
    r.field(m.timing.achieved_feed_mm_per_min);
    r.field(m.timing.feed_error_pct);
    r.field(m.timing.dead_after_move);
    r.field(m.timing.dead_before_ps);
    r.template as<std::uint64_t>(m.path.samples);
    r.field(m.path.contour_max_um);
    r.field(m.path.following_max_um);
    r.field(m.path.following_rms_um);
    r.field(m.path.endpoint_vs_command_um);
    r.field(m.path.endpoint_vs_program_um);
    r.template as<std::uint8_t>(m.programmed.kind);
    r.field(m.programmed.x_mm);
    r.field(m.programmed.y_mm);
    r.field(m.programmed.z_mm);
    r.field(m.programmed.center_x_mm);
    r.field(m.programmed.center_y_mm);
    r.field(m.steps_commanded, axes);
    r.field(m.steps_emitted, axes);
    r.field(m.sync_max_abs_ns, axes);
}

std::string temp_dir() {
    const char* dir = std::getenv("TMPDIR");
    return dir != nullptr && *dir != '\0' ? dir : "/tmp";
}

}  // namespace

class MoveRecords::Spill {
public:
    Spill(std::size_t axes, int fd, std::string path)
        : m_axes(axes),
          m_row_size(kFixedSize + kVectorCounts + axes * kPerAxisSize),
          m_fd(fd),
          m_path(std::move(path)) {
        m_buffer.reserve(std::max<std::size_t>(1, kBufferBytes / m_row_size) * m_row_size);
    }
    ~Spill() { ::close(m_fd); }
    Spill(const Spill&) = delete;
    Spill& operator=(const Spill&) = delete;

    void append(const MoveMetrics& m) {
        if (m.steps_commanded.size() > m_axes || m.steps_emitted.size() > m_axes || m.sync_max_abs_ns.size() > m_axes) {
            throw std::logic_error("MoveRecords: a move with more axes than the spill file's " +
                                   std::to_string(m_axes));
        }
        if (m_buffer.size() + m_row_size > m_buffer.capacity()) flush();
        const std::size_t at = m_buffer.size();
        m_buffer.resize(at + m_row_size);
        RowWriter w(m_buffer.data() + at);
        row_fields(w, m, m_axes);
        ++m_rows;
    }

    [[nodiscard]] std::size_t size() const { return m_rows; }

    void for_each(const std::function<void(const MoveMetrics&)>& visit) {
        flush();
        std::vector<unsigned char> chunk(m_buffer.capacity());
        MoveMetrics m;  // reused: its vectors keep their storage from row to row
        for (std::size_t row = 0; row < m_rows;) {
            const std::size_t n = std::min(m_rows - row, chunk.size() / m_row_size);
            read(chunk.data(), n, row);
            for (std::size_t i = 0; i < n; ++i) {
                decode(chunk.data() + i * m_row_size, m);
                visit(m);
            }
            row += n;
        }
    }

    [[nodiscard]] MoveMetrics at(std::size_t i) {
        flush();
        std::vector<unsigned char> row(m_row_size);
        read(row.data(), 1, i);
        MoveMetrics m;
        decode(row.data(), m);
        return m;
    }

private:
    void flush() {
        for (std::size_t done = 0; done < m_buffer.size();) {
            const ssize_t n = ::write(m_fd, m_buffer.data() + done, m_buffer.size() - done);
            if (n < 0 && errno == EINTR) continue;
            if (n <= 0) fail("cannot write", n < 0 ? errno : ENOSPC);
            done += static_cast<std::size_t>(n);
        }
        m_buffer.clear();
    }

    void read(unsigned char* to, std::size_t rows, std::size_t first_row) {
        const std::size_t bytes = rows * m_row_size;
        for (std::size_t done = 0; done < bytes;) {
            const ssize_t n = ::pread(m_fd, to + done, bytes - done, static_cast<off_t>(first_row * m_row_size + done));
            if (n < 0 && errno == EINTR) continue;
            if (n <= 0) fail("cannot read back", n < 0 ? errno : EIO);
            done += static_cast<std::size_t>(n);
        }
    }

    [[noreturn]] void fail(const char* what, int err) const {
        throw MoveRecordsError(std::string(what) + " the programmed moves' records in " + m_path + ": " +
                               std::strerror(err));
    }

    void decode(const unsigned char* at, MoveMetrics& m) const {
        RowReader r(at);
        row_fields(r, m, m_axes);
    }

    std::size_t m_axes;
    std::size_t m_row_size;
    int m_fd;
    std::string m_path;
    std::size_t m_rows = 0;
    std::vector<unsigned char> m_buffer;  // rows not yet written
};

MoveRecords MoveRecords::spilled(std::size_t axes, const std::string& dir) {
    const std::string folder = dir.empty() ? temp_dir() : dir;
    std::string path = folder + "/cncsim-moves-XXXXXX";
    const int fd = ::mkstemp(path.data());
    if (fd < 0) {
        throw MoveRecordsError("cannot create a temporary file in " + folder +
                               " for the programmed moves' records: " + std::strerror(errno));
    }
    ::unlink(path.c_str());
    return spilled_to(axes, fd, path);
}

MoveRecords MoveRecords::spilled_to(std::size_t axes, int fd, std::string path) {
    MoveRecords out;
    out.m_spill = std::make_unique<Spill>(axes, fd, std::move(path));
    return out;
}

MoveRecords::MoveRecords() = default;
MoveRecords::MoveRecords(std::vector<MoveMetrics> moves) : m_memory(std::move(moves)) {}
MoveRecords::MoveRecords(MoveRecords&&) noexcept = default;
MoveRecords& MoveRecords::operator=(MoveRecords&&) noexcept = default;
MoveRecords::~MoveRecords() = default;

void MoveRecords::append(const MoveMetrics& move) {
    if (m_spill) {
        m_spill->append(move);
    } else {
        m_memory.push_back(move);
    }
}

std::size_t MoveRecords::size() const {
    return m_spill ? m_spill->size() : m_memory.size();
}

void MoveRecords::for_each(const std::function<void(const MoveMetrics&)>& visit) const {
    if (m_spill) {
        m_spill->for_each(visit);
        return;
    }
    for (const MoveMetrics& m : m_memory) visit(m);
}

std::vector<DeadGap> dead_gaps(const MoveRecords& moves) {
    std::vector<DeadGap> gaps;
    std::size_t i = 0;
    moves.for_each([&](const MoveMetrics& m) {
        if (m.timing.dead_before_ps) gaps.push_back({*m.timing.dead_after_move, i, *m.timing.dead_before_ps});
        ++i;
    });
    return gaps;
}

MoveMetrics MoveRecords::at(std::size_t i) const {
    if (i >= size()) throw std::out_of_range("MoveRecords::at: " + std::to_string(i) + " of " + std::to_string(size()));
    return m_spill ? m_spill->at(i) : m_memory[i];
}

}  // namespace cnc::metrics
