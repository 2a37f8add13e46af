// Reading a LiveRows: row lookup, plot summaries that use the sealed chunks'
// min/max instead of their rows where a chunk lies inside one bucket, and the
// latest present value.
#include "acquisition/live/LiveRows.h"

#include <algorithm>
#include <cmath>

namespace driftlab::live {

std::pair<const LiveChunk*, int> LiveRows::locate(std::int64_t row) const {
    // Chunks are contiguous and all kCapacityRows long.
    const std::int64_t offset = row - m_chunks.front()->firstRow();
    const LiveChunk* chunk = m_chunks[std::size_t(offset / LiveChunk::kCapacityRows)].get();
    return {chunk, int(offset % LiveChunk::kCapacityRows)};
}

double LiveRows::time_s(std::int64_t row) const {
    const auto [chunk, i] = locate(row);
    return chunk->time_s(i);
}

double LiveRows::value(std::int64_t row, int column) const {
    const auto [chunk, i] = locate(row);
    return chunk->value(i, column);
}

int bucketOf(double t_s, double from_s, double to_s, int buckets) {
    if (t_s >= to_s) return buckets - 1;
    // Monotonic in t_s (subtraction, division by a positive width and floor all
    // are), so a chunk's rows share a bucket iff its first and last rows do.
    const double width_s = (to_s - from_s) / buckets;
    return std::clamp(int(std::floor((t_s - from_s) / width_s)), 0, buckets - 1);
}

LiveSummary summarize(const LiveRows& rows, int column, double from_s, double to_s, int buckets) {
    LiveSummary summary;
    if (buckets < 1 || !(to_s > from_s) || column < 0 || column >= rows.columns()) return summary;
    const double width_s = (to_s - from_s) / buckets;
    for (int b = 0; b < buckets; ++b)
        summary.buckets.push_back({from_s + b * width_s, from_s + (b + 1) * width_s, {}});
    summary.buckets.back().to_s = to_s;

    for (const auto& chunk : rows.chunks()) {
        const int first = int(std::max<std::int64_t>(rows.beginRow() - chunk->firstRow(), 0));
        const int end = int(
            std::min<std::int64_t>(rows.endRow() - chunk->firstRow(), LiveChunk::kCapacityRows));
        if (end <= first) continue;
        const double t0_s = chunk->time_s(first);
        const double t1_s = chunk->time_s(end - 1);
        if (t1_s < from_s || t0_s > to_s) continue;
        const bool whole = first == 0 && end == LiveChunk::kCapacityRows && chunk->sealed();
        if (whole && t0_s >= from_s && t1_s <= to_s) {
            // In one bucket when its first time is not before the bucket of its
            // last one; a caller that puts edges on chunk starts computes them
            // with rounding, so an edge a hair above the first time still counts.
            const int b = bucketOf(t1_s, from_s, to_s, buckets);
            if (t0_s >= from_s + b * width_s - 1e-9 * width_s) {
                summary.buckets[b].range.merge(chunk->range(column));
                ++summary.chunks_from_summaries;
                continue;
            }
        }
        for (int i = first; i < end; ++i) {
            const double t = chunk->time_s(i);
            if (t < from_s || t > to_s) continue;
            summary.buckets[bucketOf(t, from_s, to_s, buckets)].range.add(chunk->value(i, column));
        }
    }
    return summary;
}

std::optional<LiveValue> latestPresent(const LiveRows& rows, int column) {
    if (column < 0 || column >= rows.columns()) return std::nullopt;
    const auto& chunks = rows.chunks();
    for (auto it = chunks.rbegin(); it != chunks.rend(); ++it) {
        const LiveChunk& chunk = **it;
        const int first = int(std::max<std::int64_t>(rows.beginRow() - chunk.firstRow(), 0));
        const int end =
            int(std::min<std::int64_t>(rows.endRow() - chunk.firstRow(), LiveChunk::kCapacityRows));
        // A sealed chunk with nothing present in the column is skipped unread.
        if (chunk.sealed() && first == 0 && end == LiveChunk::kCapacityRows &&
            chunk.range(column).present == 0)
            continue;
        for (int i = end - 1; i >= first; --i)
            if (!std::isnan(chunk.value(i, column)))
                return LiveValue{chunk.firstRow() + i, chunk.time_s(i), chunk.value(i, column)};
    }
    return std::nullopt;
}

}  // namespace driftlab::live
