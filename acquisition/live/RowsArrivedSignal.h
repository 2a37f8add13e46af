#pragma once
// How a reader of the live read path sleeps until the writer publishes rows,
// without the writer ever waiting for a reader. On Linux a futex on a 32-bit
// word the writer bumps per row: the kernel checks the word and queues the
// sleeper atomically, so a wake-up cannot be lost and the writer's side is one
// store plus, only when someone sleeps, one FUTEX_WAKE. Elsewhere a condition
// variable whose mutex the writer only try_locks; a reader caught between its
// check and its sleep then wakes at the next row or within 1 ms.

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <mutex>

namespace driftlab::live {

class RowsArrivedSignal {
public:
    using Deadline = std::chrono::steady_clock::time_point;

    /// The word a sleeper compares against: read it before checking for rows.
    std::uint32_t word() const { return m_word.load(std::memory_order_acquire); }
    /// Writer: after publishing a row. Never blocks.
    void publish();
    /// Reader: sleeps while word() == seen, until publish() or the deadline
    /// (may return early; callers re-check).
    void sleep(std::uint32_t seen, Deadline deadline) const;

private:
    std::atomic<std::uint32_t> m_word{0};
    mutable std::atomic<int> m_sleepers{0};
#ifndef __linux__
    mutable std::mutex m_mutex;
    mutable std::condition_variable m_cv;
#endif
};

}  // namespace driftlab::live
