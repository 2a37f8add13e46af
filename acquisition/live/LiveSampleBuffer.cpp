#include "acquisition/live/LiveSampleBuffer.h"

#include <cmath>

namespace driftlab::live {

LiveSampleBuffer::LiveSampleBuffer(QStringList columns, int keep_chunks)
    : m_columns(std::move(columns)), m_keepChunks(std::max(0, keep_chunks)) {}

bool LiveSampleBuffer::append(double time_s, std::span<const double> values, QString* error) {
    const std::int64_t row = m_rowCount.load(std::memory_order_relaxed);
    if (values.size() != std::size_t(m_columns.size())) {
        if (error)
            *error = QStringLiteral("live buffer: row %1 has %2 values for %3 columns")
                         .arg(row)
                         .arg(values.size())
                         .arg(m_columns.size());
        return false;
    }
    if (!std::isfinite(time_s) || (row > 0 && time_s < m_lastTime_s)) {
        if (error)
            *error = QStringLiteral("live buffer: row %1 at t = %2 s is %3")
                         .arg(row)
                         .arg(time_s)
                         .arg(std::isfinite(time_s) ? QStringLiteral("earlier than the row "
                                                                     "before (%1 s)")
                                                          .arg(m_lastTime_s)
                                                    : QStringLiteral("not a finite time"));
        return false;
    }
    if (!m_open) {
        // A new chunk: allocated here, outside the lock; the lock only links it in.
        // Dropped chunks are freed after the lock too (unless a reader holds them).
        auto chunk = std::make_shared<LiveChunk>(row, int(m_columns.size()));
        std::vector<std::shared_ptr<const LiveChunk>> dropped;
        std::lock_guard lock(m_chunksMutex);
        if (m_keepChunks > 0 && int(m_chunks.size()) >= m_keepChunks) {
            const auto keepFrom = m_chunks.end() - (m_keepChunks - 1);
            dropped.assign(std::make_move_iterator(m_chunks.begin()),
                           std::make_move_iterator(keepFrom));
            m_chunks.erase(m_chunks.begin(), keepFrom);
        }
        m_chunks.push_back(chunk);
        m_open = std::move(chunk);
    }
    m_lastTime_s = time_s;
    const bool full = m_open->appendRow(time_s, values.data());
    m_rowCount.store(row + 1, std::memory_order_release);
    m_rowsArrived.publish();
    if (full) {
        m_open->seal();
        m_open.reset();
    }
    return true;
}

std::int64_t LiveSampleBuffer::firstHeldRow() const {
    std::lock_guard lock(m_chunksMutex);
    return m_chunks.empty() ? 0 : m_chunks.front()->firstRow();
}

LiveRows LiveSampleBuffer::rowsSince(std::int64_t row) const {
    LiveRows rows;
    rows.m_columns = int(m_columns.size());
    std::lock_guard lock(m_chunksMutex);
    if (m_chunks.empty()) return rows;
    const std::int64_t held = m_chunks.front()->firstRow();
    const LiveChunk& last = *m_chunks.back();
    // Every chunk before the last is full, so the last one's published count
    // bounds a consistent prefix.
    rows.m_end = last.firstRow() + last.publishedRows();
    rows.m_begin = std::clamp(row, held, rows.m_end);
    const auto from = std::min<std::size_t>((rows.m_begin - held) / LiveChunk::kCapacityRows,
                                            m_chunks.size() - 1);
    rows.m_chunks.assign(m_chunks.begin() + std::ptrdiff_t(from), m_chunks.end());
    return rows;
}

LiveSummary LiveSampleBuffer::summary(int column, double from_s, double to_s, int buckets) const {
    return summarize(snapshot(), column, from_s, to_s, buckets);
}

std::optional<LiveValue> LiveSampleBuffer::latest(int column) const {
    return latestPresent(snapshot(), column);
}

std::int64_t LiveSampleBuffer::waitForRows(std::int64_t row_count,
                                           std::chrono::microseconds timeout) const {
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    for (;;) {
        // The word first: a row published after this read changes it, and
        // then the sleep returns at once.
        const std::uint32_t seen = m_rowsArrived.word();
        const std::int64_t rows = rowCount();
        if (rows > row_count || std::chrono::steady_clock::now() >= deadline) return rows;
        m_rowsArrived.sleep(seen, deadline);
    }
}

}  // namespace driftlab::live
