// bench: latency of the live read path, from the moment a reading is "read
// from the device" to the moment a reader waiting on the LiveSampleBuffer has
// it. A producer thread plays a 64-channel module whose readings arrive in
// bursts (as several samples do in one Modbus response), timestamps each one
// (steady_clock) and appends it; a reader thread waits on the buffer and
// records now − timestamp for every row it sees.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <thread>
#include <vector>

#include "acquisition/live/LiveSampleBuffer.h"
#include "bench/BenchFigures.h"

namespace driftlab::bench {

namespace {
using Clock = std::chrono::steady_clock;
constexpr int kBurstRows = 10;  // readings per burst
constexpr auto kBurstPeriod = std::chrono::milliseconds(1);
}  // namespace

QJsonObject liveReadFigures(int readings) {
    QStringList columns;
    for (int c = 0; c < kLiveChannels; ++c) columns << QStringLiteral("T%1").arg(c + 1);
    live::LiveSampleBuffer buffer(columns);
    // Written by the producer before the row is appended, read by the reader
    // after it sees the row: the append's release store orders the two.
    std::vector<Clock::time_point> readAt(std::size_t(readings), Clock::time_point{});
    std::vector<double> latency_us;
    latency_us.reserve(std::size_t(readings));
    std::atomic<bool> producerFailed{false};

    std::thread reader([&] {
        std::int64_t next = 0;
        while (next < readings && !producerFailed.load()) {
            buffer.waitForRows(next, std::chrono::milliseconds(100));
            const live::LiveRows rows = buffer.rowsSince(next);
            const Clock::time_point now = Clock::now();
            for (std::int64_t r = rows.beginRow(); r < rows.endRow(); ++r)
                latency_us.push_back(
                    std::chrono::duration<double, std::micro>(now - readAt[std::size_t(r)])
                        .count());
            next = rows.endRow();
        }
    });
    std::thread producer([&] {
        std::vector<double> values(kLiveChannels);
        const Clock::time_point start = Clock::now();
        Clock::time_point burst = start;
        for (int r = 0; r < readings;) {
            std::this_thread::sleep_until(burst);
            for (int k = 0; k < kBurstRows && r < readings; ++k, ++r) {
                readAt[std::size_t(r)] = Clock::now();
                for (int c = 0; c < kLiveChannels; ++c) values[c] = 20 + 0.01 * c + 1e-6 * r;
                const double t_s =
                    std::chrono::duration<double>(readAt[std::size_t(r)] - start).count();
                if (!buffer.append(t_s, values, nullptr)) {
                    producerFailed = true;
                    return;
                }
            }
            burst += kBurstPeriod;
            printProgress(QStringLiteral("live read"), double(r) / readings);
        }
    });
    producer.join();
    reader.join();
    if (producerFailed || latency_us.size() != std::size_t(readings))
        throw CliError(QStringLiteral("live read bench: the reader saw %1 of %2 readings")
                           .arg(latency_us.size())
                           .arg(readings));
    std::sort(latency_us.begin(), latency_us.end());
    const auto at = [&](double q) {
        return latency_us[std::min(latency_us.size() - 1, std::size_t(q * latency_us.size()))];
    };
    return {{QStringLiteral("live_read_latency_median_us"), at(0.5)},
            {QStringLiteral("live_read_latency_p99_us"), at(0.99)},
            {QStringLiteral("live_read_readings"), readings}};
}

void printLiveReadLine(const QJsonObject& live) {
    printLine(QStringLiteral("live read       device reading → waiting reader of the live buffer, "
                             "%1 readings in bursts: median %2 µs, p99 %3 µs")
                  .arg(live[QStringLiteral("live_read_readings")].toInt())
                  .arg(live[QStringLiteral("live_read_latency_median_us")].toDouble(), 0, 'f', 1)
                  .arg(live[QStringLiteral("live_read_latency_p99_us")].toDouble(), 0, 'f', 1));
}

}  // namespace driftlab::bench
