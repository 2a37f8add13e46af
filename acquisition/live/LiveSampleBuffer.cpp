#include "acquisition/live/LiveSampleBuffer.h"

#include <cmath>

namespace driftlab::live {

LiveSampleBuffer::LiveSampleBuffer(QStringList columns, int keep_chunks)
    : columns_(std::move(columns)), keepChunks_(std::max(0, keep_chunks)) {}

bool LiveSampleBuffer::append(double time_s, std::span<const double> values, QString* error) {
    const std::int64_t row = rowCount_.load(std::memory_order_relaxed);
    if (values.size() != std::size_t(columns_.size())) {
        if (error)
            *error = QStringLiteral("live buffer: row %1 has %2 values for %3 columns")
                         .arg(row)
                         .arg(values.size())
                         .arg(columns_.size());
        return false;
    }
    if (!std::isfinite(time_s) || (row > 0 && time_s < lastTime_s_)) {
        if (error)
            *error = QStringLiteral("live buffer: row %1 at t = %2 s is %3")
                         .arg(row)
                         .arg(time_s)
                         .arg(std::isfinite(time_s) ? QStringLiteral("earlier than the row "
                                                                     "before (%1 s)")
                                                          .arg(lastTime_s_)
                                                    : QStringLiteral("not a finite time"));
        return false;
    }
    if (!open_) {
        // A new chunk: allocated here, outside the lock; the lock only links it in.
        // Dropped chunks are freed after the lock too (unless a reader holds them).
        auto chunk = std::make_shared<LiveChunk>(row, int(columns_.size()));
        std::vector<std::shared_ptr<const LiveChunk>> dropped;
        std::lock_guard lock(chunksMutex_);
        if (keepChunks_ > 0 && int(chunks_.size()) >= keepChunks_) {
            const auto keepFrom = chunks_.end() - (keepChunks_ - 1);
            dropped.assign(std::make_move_iterator(chunks_.begin()),
                           std::make_move_iterator(keepFrom));
            chunks_.erase(chunks_.begin(), keepFrom);
        }
        chunks_.push_back(chunk);
        open_ = std::move(chunk);
    }
    lastTime_s_ = time_s;
    const bool full = open_->appendRow(time_s, values.data());
    rowCount_.store(row + 1, std::memory_order_release);
    rowsArrived_.publish();
    if (full) {
        open_->seal();
        open_.reset();
    }
    return true;
}

std::int64_t LiveSampleBuffer::firstHeldRow() const {
    std::lock_guard lock(chunksMutex_);
    return chunks_.empty() ? 0 : chunks_.front()->firstRow();
}

LiveRows LiveSampleBuffer::rowsSince(std::int64_t row) const {
    LiveRows rows;
    rows.columns_ = int(columns_.size());
    std::lock_guard lock(chunksMutex_);
    if (chunks_.empty()) return rows;
    const std::int64_t held = chunks_.front()->firstRow();
    const LiveChunk& last = *chunks_.back();
    // Every chunk before the last is full, so the last one's published count
    // bounds a consistent prefix.
    rows.end_ = last.firstRow() + last.publishedRows();
    rows.begin_ = std::clamp(row, held, rows.end_);
    const auto from =
        std::min<std::size_t>((rows.begin_ - held) / LiveChunk::kCapacityRows, chunks_.size() - 1);
    rows.chunks_.assign(chunks_.begin() + std::ptrdiff_t(from), chunks_.end());
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
        const std::uint32_t seen = rowsArrived_.word();
        const std::int64_t rows = rowCount();
        if (rows > row_count || std::chrono::steady_clock::now() >= deadline) return rows;
        rowsArrived_.sleep(seen, deadline);
    }
}

}  // namespace driftlab::live
