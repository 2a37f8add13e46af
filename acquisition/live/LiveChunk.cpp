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
    : m_firstRow(first_row),
      m_columns(columns),
      m_time_s(new double[kCapacityRows]),
      m_values(new double[std::size_t(kCapacityRows) * columns]),
      m_ranges(columns) {}

bool LiveChunk::appendRow(double time_s, const double* values) {
    // Only the writer changes m_rows, so a relaxed load sees its own last store.
    const int i = m_rows.load(std::memory_order_relaxed);
    m_time_s[i] = time_s;
    std::copy(values, values + m_columns, m_values.get() + std::size_t(i) * m_columns);
    m_rows.store(i + 1, std::memory_order_release);
    return i + 1 == kCapacityRows;
}

void LiveChunk::seal() {
    for (int c = 0; c < m_columns; ++c) {
        ColumnRange r;
        for (int i = 0; i < kCapacityRows; ++i) r.add(value(i, c));
        m_ranges[c] = r;
    }
    m_sealed.store(true, std::memory_order_release);
}

}  // namespace driftlab::live
