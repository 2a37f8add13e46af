#pragma once
// The live read path: what the acquisition thread logs, readable at once by the
// GUI's plots and the live compensation without ever holding up the logger.
//
// One writer (the acquisition thread) appends rows of time_s + one double per
// column (NaN = missing) into fixed 512-row chunks (LiveChunk.h). Appending a
// row into the open chunk takes no lock: the row is written, then the chunk's
// row count is published with a release store that readers load with acquire.
// The chunk list changes under a short mutex only when a chunk is added (every
// 512 rows); readers take it only to copy the list's shared pointers. Readers
// never wait on the writer and the writer never waits on a reader's work.
//
// Memory: keep_chunks = 0 keeps every row (8 h of 64 channels at 10 Hz is
// 150 MB); keep_chunks = N keeps the newest N chunks and drops older ones
// (they are in the store); a reader's LiveRows keeps what it holds alive.

#include <QStringList>
#include <chrono>
#include <mutex>
#include <span>

#include "acquisition/live/LiveRows.h"
#include "acquisition/live/RowsArrivedSignal.h"

namespace driftlab::live {

class LiveSampleBuffer {
public:
    explicit LiveSampleBuffer(QStringList columns, int keep_chunks = 0);
    LiveSampleBuffer(const LiveSampleBuffer&) = delete;
    LiveSampleBuffer& operator=(const LiveSampleBuffer&) = delete;

    // --- the writer (one thread) ---
    /// Appends one row. Refuses (and appends nothing) a row with the wrong
    /// number of values or a time that is not finite or is earlier than the
    /// row before: summaries and incremental reads rely on time order.
    bool append(double time_s, std::span<const double> values, QString* error);

    // --- readers (any thread, any number) ---
    const QStringList& columns() const { return m_columns; }
    int columnIndex(const QString& name) const { return int(m_columns.indexOf(name)); }
    /// Rows appended and published so far (acquire).
    std::int64_t rowCount() const { return m_rowCount.load(std::memory_order_acquire); }
    /// The first row still held (0 unless keep_chunks dropped older chunks).
    std::int64_t firstHeldRow() const;

    /// Every row held so far.
    LiveRows snapshot() const { return rowsSince(0); }
    /// Rows from `row` on; when the memory policy already dropped `row`,
    /// beginRow() says where the held rows start (the rest are in the store).
    LiveRows rowsSince(std::int64_t row) const;
    /// Min/max per time bucket of `column` for a plot (LiveRows.h: summarize).
    LiveSummary summary(int column, double from_s, double to_s, int buckets) const;
    /// The most recent present value of `column`.
    std::optional<LiveValue> latest(int column) const;

    /// Waits until more than `row_count` rows are published or `timeout`
    /// passes; returns rowCount() then. The writer wakes sleeping readers
    /// without waiting for them (RowsArrivedSignal.h).
    std::int64_t waitForRows(std::int64_t row_count, std::chrono::microseconds timeout) const;

private:
    const QStringList m_columns;
    const int m_keepChunks;

    // Writer-owned: the chunk being filled, the time of the last row.
    std::shared_ptr<LiveChunk> m_open;
    double m_lastTime_s = 0;

    mutable std::mutex m_chunksMutex;
    std::vector<std::shared_ptr<const LiveChunk>> m_chunks;  // guarded by m_chunksMutex

    std::atomic<std::int64_t> m_rowCount{0};
    RowsArrivedSignal m_rowsArrived;
};

}  // namespace driftlab::live
