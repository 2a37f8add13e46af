#pragma once
// What a reader of the live read path holds: a consistent prefix of the rows
// (buffer-wide indices [beginRow, endRow)) as shared chunks, no copy of the
// data. Holding it keeps its chunks alive even when the buffer's memory policy
// has dropped them; rows appended later are not part of it.

#include <QString>
#include <memory>
#include <optional>
#include <vector>

#include "acquisition/live/LiveChunk.h"

namespace driftlab::live {

class LiveRows {
public:
    std::int64_t beginRow() const { return m_begin; }
    std::int64_t endRow() const { return m_end; }
    std::int64_t size() const { return m_end - m_begin; }
    bool empty() const { return m_end == m_begin; }
    int columns() const { return m_columns; }

    /// beginRow() ≤ row < endRow().
    double time_s(std::int64_t row) const;
    double value(std::int64_t row, int column) const;

    /// The chunks holding [beginRow, endRow), oldest first (the first and last
    /// may hold rows outside it).
    const std::vector<std::shared_ptr<const LiveChunk>>& chunks() const { return m_chunks; }

private:
    friend class LiveSampleBuffer;
    std::pair<const LiveChunk*, int> locate(std::int64_t row) const;

    std::vector<std::shared_ptr<const LiveChunk>> m_chunks;
    std::int64_t m_begin = 0;
    std::int64_t m_end = 0;
    int m_columns = 0;
};

/// One bucket of a plot summary: the column's present values with from_s ≤ t < to_s
/// (the last bucket also holds t = to_s).
struct LiveBucket {
    double from_s = 0;
    double to_s = 0;
    ColumnRange range;
};

struct LiveSummary {
    std::vector<LiveBucket> buckets;
    /// Sealed chunks that fell wholly inside one bucket and were taken from
    /// their summaries instead of their rows.
    int chunks_from_summaries = 0;
};

/// The most recent present value of a column.
struct LiveValue {
    std::int64_t row = 0;
    double time_s = 0;
    double value = 0;
};

/// The bucket a time falls in; the same rule for every reader and for the tests.
int bucketOf(double t_s, double from_s, double to_s, int buckets);

/// Min/max per bucket of `column` over `rows`, rows outside [from_s, to_s] left
/// out. Empty when the arguments make no buckets (buckets < 1, to_s ≤ from_s).
LiveSummary summarize(const LiveRows& rows, int column, double from_s, double to_s, int buckets);

/// The last row of `rows` where `column` is present.
std::optional<LiveValue> latestPresent(const LiveRows& rows, int column);

}  // namespace driftlab::live
