#include "acquisition/live/LiveChunk.h"

#include <algorithm>
#include <cmath>

namespace driftlab::live {

void ColumnRange::add(double value) {
    if (std::isnan(value)) return;
    min = present ? std::min(min, value) : value;
    max = present ? std::max(max, value) : value;
    ++present;
}

void ColumnRange::merge(const ColumnRange& other) {
    if (!other.present) return;
    min = present ? std::min(min, other.min) : other.min;
    max = present ? std::max(max, other.max) : other.max;
    present += other.present;
}

LiveChunk::LiveChunk(std::int64_t first_row, int columns)
    : firstRow_(first_row),
      columns_(columns),
      time_s_(new double[kCapacityRows]),
      values_(new double[std::size_t(kCapacityRows) * columns]),
      ranges_(columns) {}

bool LiveChunk::appendRow(double time_s, const double* values) {
    // Only the writer changes rows_, so a relaxed load sees its own last store.
    const int i = rows_.load(std::memory_order_relaxed);
    time_s_[i] = time_s;
    std::copy(values, values + columns_, values_.get() + std::size_t(i) * columns_);
    rows_.store(i + 1, std::memory_order_release);
    return i + 1 == kCapacityRows;
}

void LiveChunk::seal() {
    for (int c = 0; c < columns_; ++c) {
        ColumnRange r;
        for (int i = 0; i < kCapacityRows; ++i) r.add(value(i, c));
        ranges_[c] = r;
    }
    sealed_.store(true, std::memory_order_release);
}

}  // namespace driftlab::live
