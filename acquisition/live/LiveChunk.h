#pragma once
// One fixed-capacity block of the live read path (LiveSampleBuffer.h): rows of
// time_s + one double per column (NaN = missing), allocated once and never
// reallocated, so a reader can read rows the writer has published while the
// writer appends the next ones. Row i is readable once publishedRows() > i
// (acquire); a full chunk is sealed and then carries per-column min/max/count.

#include <atomic>
#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

namespace driftlab::live {

/// Min/max/count of the present (non-NaN) values of one column over some rows.
struct ColumnRange {
    double min = std::numeric_limits<double>::quiet_NaN();
    double max = std::numeric_limits<double>::quiet_NaN();
    std::int64_t present = 0;

    void add(double value);
    void merge(const ColumnRange& other);
};

class LiveChunk {
public:
    /// 512 rows: a seal (min/max over the chunk) every ~50 s at 10 Hz, and a
    /// 64-column chunk is 256 KiB.
    static constexpr int kCapacityRows = 512;

    LiveChunk(std::int64_t first_row, int columns);
    LiveChunk(const LiveChunk&) = delete;
    LiveChunk& operator=(const LiveChunk&) = delete;

    /// The buffer-wide index of this chunk's first row.
    std::int64_t firstRow() const { return m_firstRow; }
    int columns() const { return m_columns; }
    /// Rows complete and readable now; rows below it never change again.
    int publishedRows() const { return m_rows.load(std::memory_order_acquire); }
    /// Full, with its column ranges computed (acquire: ranges are readable after).
    bool sealed() const { return m_sealed.load(std::memory_order_acquire); }

    /// Row `i` < publishedRows().
    double time_s(int i) const { return m_time_s[i]; }
    double value(int i, int column) const { return m_values[std::size_t(i) * m_columns + column]; }
    /// Only when sealed(): the column over all kCapacityRows rows.
    const ColumnRange& range(int column) const { return m_ranges[column]; }

private:
    friend class LiveSampleBuffer;
    /// Writer only: writes row publishedRows() and publishes it (release).
    /// Returns true when this row filled the chunk.
    bool appendRow(double time_s, const double* values);
    /// Writer only, once full: computes the ranges, then marks sealed (release).
    void seal();

    const std::int64_t m_firstRow;
    const int m_columns;
    std::unique_ptr<double[]> m_time_s;
    std::unique_ptr<double[]> m_values;
    std::vector<ColumnRange> m_ranges;
    std::atomic<int> m_rows{0};
    std::atomic<bool> m_sealed{false};
};

}  // namespace driftlab::live
