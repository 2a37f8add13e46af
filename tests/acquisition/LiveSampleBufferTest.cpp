// The live read path: rows and chunk boundaries, sealed-chunk summaries and
// plot buckets against brute force over random data with gaps (NaN), a writer
// appending a million rows while two readers read incrementally (every value
// is a function of its row index, so a torn or reordered row is caught), and
// readers woken when rows arrive.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <thread>

#include "acquisition/live/LiveSampleBuffer.h"

namespace driftlab::test {
namespace {

using live::ColumnRange;
using live::LiveChunk;
using live::LiveSampleBuffer;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr int kCap = LiveChunk::kCapacityRows;

QStringList columnNames(int n) {
    QStringList names;
    for (int c = 0; c < n; ++c) names << QStringLiteral("T%1").arg(c + 1);
    return names;
}

/// Row r, column c: exact in a double, so any mixed-up row shows.
double valueOf(std::int64_t row, int column) {
    return double(row) * 8 + column;
}

void appendRows(LiveSampleBuffer& buffer, std::int64_t from, std::int64_t to) {
    const int columns = int(buffer.columns().size());
    std::vector<double> values(columns);
    QString error;
    for (std::int64_t r = from; r < to; ++r) {
        for (int c = 0; c < columns; ++c) values[c] = valueOf(r, c);
        ASSERT_TRUE(buffer.append(0.1 * double(r), values, &error)) << qPrintable(error);
    }
}

/// Random times (steps of 0…0.2 s, some repeated) and values with ~20 % NaN;
/// column 2 has nothing present after row 700.
struct RandomRows {
    std::vector<double> t_s;
    std::vector<std::vector<double>> values;
};

RandomRows fillRandom(LiveSampleBuffer& buffer, int rows, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> step(0, 0.2), value(-50, 150), u(0, 1);
    RandomRows data;
    double t = 3;
    QString error;
    for (int r = 0; r < rows; ++r) {
        t += u(rng) < 0.1 ? 0 : step(rng);
        std::vector<double> row(3);
        for (int c = 0; c < 3; ++c) row[c] = u(rng) < 0.2 ? kNaN : value(rng);
        if (r > 700) row[2] = kNaN;
        EXPECT_TRUE(buffer.append(t, row, &error)) << qPrintable(error);
        data.t_s.push_back(t);
        data.values.push_back(row);
    }
    return data;
}

TEST(LiveSampleBuffer, holdsRowsInFixedChunksAndReadsThemBackByRowIndex) {
    LiveSampleBuffer buffer(columnNames(3));
    EXPECT_EQ(buffer.rowCount(), 0);
    EXPECT_TRUE(buffer.snapshot().empty());
    appendRows(buffer, 0, 2 * kCap + 7);
    EXPECT_EQ(buffer.rowCount(), 2 * kCap + 7);

    const live::LiveRows all = buffer.snapshot();
    EXPECT_EQ(all.beginRow(), 0);
    EXPECT_EQ(all.endRow(), 2 * kCap + 7);
    ASSERT_EQ(all.chunks().size(), 3u);
    EXPECT_TRUE(all.chunks()[0]->sealed());
    EXPECT_TRUE(all.chunks()[1]->sealed());
    EXPECT_FALSE(all.chunks()[2]->sealed());
    EXPECT_EQ(all.chunks()[1]->firstRow(), kCap);
    EXPECT_EQ(all.chunks()[2]->publishedRows(), 7);
    for (std::int64_t r = 0; r < all.endRow(); ++r) {
        ASSERT_DOUBLE_EQ(all.time_s(r), 0.1 * double(r));
        for (int c = 0; c < 3; ++c) ASSERT_EQ(all.value(r, c), valueOf(r, c)) << r;
    }
    // Incremental: from a chunk boundary, from inside a chunk, at the end.
    const live::LiveRows fromBoundary = buffer.rowsSince(kCap);
    EXPECT_EQ(fromBoundary.beginRow(), kCap);
    EXPECT_EQ(fromBoundary.chunks().size(), 2u);
    EXPECT_EQ(fromBoundary.value(kCap, 1), valueOf(kCap, 1));
    const live::LiveRows inside = buffer.rowsSince(2 * kCap + 3);
    EXPECT_EQ(inside.size(), 4);
    EXPECT_EQ(inside.value(2 * kCap + 6, 2), valueOf(2 * kCap + 6, 2));
    EXPECT_TRUE(buffer.rowsSince(buffer.rowCount()).empty());
    EXPECT_EQ(buffer.columnIndex(QStringLiteral("T2")), 1);
}

TEST(LiveSampleBuffer, sealedChunksCarryTheMinMaxAndCountOfPresentValues) {
    LiveSampleBuffer buffer(columnNames(3));
    const RandomRows data = fillRandom(buffer, 5 * kCap + 100, 7);
    const live::LiveRows all = buffer.snapshot();
    ASSERT_EQ(all.chunks().size(), 6u);
    for (int k = 0; k < 5; ++k) {
        const LiveChunk& chunk = *all.chunks()[k];
        ASSERT_TRUE(chunk.sealed());
        for (int c = 0; c < 3; ++c) {
            double lo = INFINITY, hi = -INFINITY;
            std::int64_t present = 0;
            for (int i = 0; i < kCap; ++i) {
                const double v = data.values[std::size_t(k * kCap + i)][c];
                if (std::isnan(v)) continue;
                lo = std::min(lo, v);
                hi = std::max(hi, v);
                ++present;
            }
            EXPECT_EQ(chunk.range(c).present, present) << k << " " << c;
            if (present) {
                EXPECT_EQ(chunk.range(c).min, lo);
                EXPECT_EQ(chunk.range(c).max, hi);
            }
        }
    }
    EXPECT_EQ(all.chunks()[3]->range(2).present, 0);  // column 2 is absent there
}

TEST(LiveSampleBuffer, plotBucketsMatchBruteForceAndUseTheChunkSummaries) {
    LiveSampleBuffer buffer(columnNames(3));
    const RandomRows data = fillRandom(buffer, 20 * kCap + 300, 11);
    const double t0 = data.t_s.front(), t1 = data.t_s.back();
    struct Case {
        double from_s, to_s;
        int buckets;
    };
    // Coarse (chunks inside buckets), fine (none), a window cutting chunks.
    for (const Case& k : {Case{t0, t1, 4}, Case{t0, t1, 3000}, Case{t0 + 37.3, t1 - 91.9, 7},
                          Case{t0 - 10, t1 + 10, 1}}) {
        for (int column = 0; column < 3; ++column) {
            const live::LiveSummary s = buffer.summary(column, k.from_s, k.to_s, k.buckets);
            ASSERT_EQ(int(s.buckets.size()), k.buckets);
            std::vector<ColumnRange> expected(std::size_t(k.buckets));
            for (std::size_t r = 0; r < data.t_s.size(); ++r) {
                const double t = data.t_s[r];
                if (t < k.from_s || t > k.to_s) continue;
                expected[live::bucketOf(t, k.from_s, k.to_s, k.buckets)].add(
                    data.values[r][column]);
            }
            for (int b = 0; b < k.buckets; ++b) {
                const ColumnRange& got = s.buckets[b].range;
                ASSERT_EQ(got.present, expected[b].present) << b << " of " << k.buckets;
                if (got.present) {
                    ASSERT_EQ(got.min, expected[b].min);
                    ASSERT_EQ(got.max, expected[b].max);
                }
            }
            if (k.buckets <= 7) {
                EXPECT_GT(s.chunks_from_summaries, 0) << k.buckets;
            }
            if (k.buckets == 1) {
                EXPECT_EQ(s.chunks_from_summaries, 20);
            }
        }
    }
    EXPECT_TRUE(buffer.summary(0, t1, t0, 5).buckets.empty());
    EXPECT_TRUE(buffer.summary(9, t0, t1, 5).buckets.empty());
}

TEST(LiveSampleBuffer, bucketsOnChunkStartsComputedWithRoundingStillUseEverySummary) {
    // A 10 Hz log (0.1 s is not a binary fraction) and buckets of three chunks
    // whose edges are derived from the data as the dashboard derives them.
    // Rounding puts some edges a hair above a chunk's first time; every whole
    // chunk must still come from its summary (the redraw time depends on it).
    LiveSampleBuffer buffer(columnNames(2));
    constexpr int kChunks = 60, kRows = kChunks * kCap;
    for (int r = 0; r < kRows; ++r) {
        const double values[] = {std::sin(r * 0.01), double(r % 7)};
        ASSERT_TRUE(buffer.append(r * 0.1, values, nullptr));
    }
    const double from_s = 0, last_s = (kRows - 1) * 0.1;
    const double width_s = 3 * (last_s - from_s) / double(kRows - 1) * kCap;
    const int buckets = int(std::ceil((last_s - from_s) / width_s));
    const live::LiveSummary s = buffer.summary(0, from_s, from_s + buckets * width_s, buckets);
    ASSERT_EQ(buckets, kChunks / 3);
    EXPECT_EQ(s.chunks_from_summaries, kChunks);  // 51 before edges got their tolerance
    for (const live::LiveBucket& b : s.buckets) EXPECT_EQ(b.range.present, 3 * kCap);
}

TEST(LiveSampleBuffer, latestIsTheLastPresentValueOfTheColumn) {
    LiveSampleBuffer buffer(columnNames(3));
    EXPECT_FALSE(buffer.latest(0).has_value());
    const RandomRows data = fillRandom(buffer, 3 * kCap + 20, 3);
    for (int c = 0; c < 3; ++c) {
        std::size_t r = data.t_s.size();
        while (r > 0 && std::isnan(data.values[r - 1][c])) --r;
        const auto latest = buffer.latest(c);
        ASSERT_TRUE(latest.has_value());
        EXPECT_EQ(latest->row, std::int64_t(r - 1));
        EXPECT_EQ(latest->value, data.values[r - 1][c]);
        EXPECT_EQ(latest->time_s, data.t_s[r - 1]);
    }
    LiveSampleBuffer empty(columnNames(1));
    const double missing[1] = {kNaN};
    for (int r = 0; r < 2 * kCap; ++r) ASSERT_TRUE(empty.append(r, missing, nullptr));
    EXPECT_FALSE(empty.latest(0).has_value());
}

TEST(LiveSampleBuffer, refusesRowsThatWouldBreakTimeOrderOrColumns) {
    LiveSampleBuffer buffer(columnNames(2));
    QString error;
    const double two[2] = {1, 2}, three[3] = {1, 2, 3};
    ASSERT_TRUE(buffer.append(5, two, &error));
    EXPECT_FALSE(buffer.append(6, three, &error));
    EXPECT_TRUE(error.contains(QStringLiteral("row 1 has 3 values for 2 columns")))
        << qPrintable(error);
    EXPECT_FALSE(buffer.append(4.5, two, &error));
    EXPECT_TRUE(error.contains(QStringLiteral("earlier than the row before (5 s)")))
        << qPrintable(error);
    EXPECT_FALSE(buffer.append(kNaN, two, &error));
    EXPECT_TRUE(error.contains(QStringLiteral("not a finite time"))) << qPrintable(error);
    EXPECT_EQ(buffer.rowCount(), 1);
    EXPECT_TRUE(buffer.append(5, two, &error));  // the same time again is fine
}

TEST(LiveSampleBuffer, keepsTheNewestChunksAndReadersKeepWhatTheyHold) {
    LiveSampleBuffer buffer(columnNames(2), 2);
    appendRows(buffer, 0, kCap + 10);
    const live::LiveRows held = buffer.snapshot();
    appendRows(buffer, kCap + 10, 4 * kCap + 5);
    EXPECT_EQ(buffer.firstHeldRow(), 3 * kCap);
    const live::LiveRows since = buffer.rowsSince(100);
    EXPECT_EQ(since.beginRow(), 3 * kCap);  // rows before are in the store
    EXPECT_EQ(since.endRow(), 4 * kCap + 5);
    EXPECT_EQ(since.value(3 * kCap, 1), valueOf(3 * kCap, 1));
    // The dropped chunks stay readable through the snapshot taken before.
    EXPECT_EQ(held.endRow(), kCap + 10);
    EXPECT_EQ(held.value(5, 0), valueOf(5, 0));
    EXPECT_EQ(held.value(kCap + 9, 1), valueOf(kCap + 9, 1));
}

TEST(LiveSampleBuffer, readersSeeEveryRowCompleteAndInOrderWhileAMillionAreAppended) {
    constexpr std::int64_t kRows = 1'000'000;
    constexpr int kColumns = 4;
    LiveSampleBuffer buffer(columnNames(kColumns));
    struct ReaderResult {
        std::int64_t seen = 0, bad = 0, gaps = 0, reads = 0;
    };
    auto reader = [&](ReaderResult* out) {
        std::int64_t next = 0;
        while (next < kRows) {
            buffer.waitForRows(next, std::chrono::milliseconds(200));
            const live::LiveRows rows = buffer.rowsSince(next);
            ++out->reads;
            out->gaps += rows.beginRow() != next;
            for (std::int64_t r = rows.beginRow(); r < rows.endRow(); ++r) {
                bool ok = rows.time_s(r) == 0.001 * double(r);
                for (int c = 0; c < kColumns; ++c) ok = ok && rows.value(r, c) == valueOf(r, c);
                out->bad += !ok;
                ++out->seen;
            }
            next = rows.endRow();
        }
    };
    ReaderResult a, b;
    std::thread readerA(reader, &a), readerB(reader, &b);
    std::thread writer([&] {
        std::vector<double> values(kColumns);
        for (std::int64_t r = 0; r < kRows; ++r) {
            for (int c = 0; c < kColumns; ++c) values[c] = valueOf(r, c);
            if (!buffer.append(0.001 * double(r), values, nullptr)) return;
        }
    });
    writer.join();
    readerA.join();
    readerB.join();
    EXPECT_EQ(buffer.rowCount(), kRows);
    for (const ReaderResult* r : {&a, &b}) {
        EXPECT_EQ(r->bad, 0);
        EXPECT_EQ(r->gaps, 0);
        EXPECT_EQ(r->seen, kRows);
        EXPECT_GT(r->reads, 1);  // it did read while rows were being appended
    }
}

TEST(LiveSampleBuffer, aWaitingReaderWakesWhenRowsArriveAndTimesOutWhenNone) {
    LiveSampleBuffer buffer(columnNames(1));
    EXPECT_EQ(buffer.waitForRows(0, std::chrono::milliseconds(20)), 0);
    std::thread writer([&] {
        std::this_thread::sleep_for(std::chrono::milliseconds(30));
        const double v[1] = {20.5};
        buffer.append(1, v, nullptr);
    });
    // Returns with the row long before this (generous) timeout.
    EXPECT_EQ(buffer.waitForRows(0, std::chrono::seconds(60)), 1);
    writer.join();
    EXPECT_EQ(buffer.latest(0)->value, 20.5);
    // Already more rows than asked: returns at once.
    EXPECT_EQ(buffer.waitForRows(0, std::chrono::seconds(60)), 1);
}

}  // namespace
}  // namespace driftlab::test
