// A model's log of per-event records (packets, bytes, moves) that its readers hand back once they have read
// them, so that a long run holds only the records still to be read. Records keep the index they had in the
// whole log: a reader counts them as if none had been dropped.
#pragma once
#include <cstddef>
#include <deque>
#include <utility>

namespace cnc {

template <typename Record>
class RecordLog {
public:
    using const_iterator = typename std::deque<Record>::const_iterator;

    void push_back(Record r) { m_kept.push_back(std::move(r)); }
    // Every record ever logged, the dropped ones included: the index the next one gets.
    [[nodiscard]] std::size_t size() const { return m_first + m_kept.size(); }
    [[nodiscard]] bool empty() const { return size() == 0; }
    // The index of the first record still kept.
    [[nodiscard]] std::size_t first() const { return m_first; }
    // Record i of the whole log: first() <= i < size().
    [[nodiscard]] const Record& operator[](std::size_t i) const { return m_kept[i - m_first]; }
    [[nodiscard]] Record& operator[](std::size_t i) { return m_kept[i - m_first]; }
    // The first and the last record kept (some must be).
    [[nodiscard]] const Record& front() const { return m_kept.front(); }
    [[nodiscard]] const Record& back() const { return m_kept.back(); }
    // The kept records, from first().
    [[nodiscard]] const_iterator begin() const { return m_kept.begin(); }
    [[nodiscard]] const_iterator end() const { return m_kept.end(); }
    // Drops the records before index `end` (those already dropped or never logged are no-ops).
    void drop_before(std::size_t end) {
        for (; m_first < end && !m_kept.empty(); ++m_first) m_kept.pop_front();
    }

private:
    std::deque<Record> m_kept;
    std::size_t m_first = 0;
};

}  // namespace cnc
