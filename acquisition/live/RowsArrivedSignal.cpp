#include "acquisition/live/RowsArrivedSignal.h"

#include <algorithm>
#include <climits>

#ifdef __linux__
#include <linux/futex.h>
#include <sys/syscall.h>
#include <time.h>
#include <unistd.h>
#endif

namespace driftlab::live {

static_assert(sizeof(std::atomic<std::uint32_t>) == sizeof(std::uint32_t) &&
                  std::atomic<std::uint32_t>::is_always_lock_free,
              "the futex word must be a plain 32-bit word");

void RowsArrivedSignal::publish() {
    m_word.fetch_add(1, std::memory_order_release);
    // Pairs with the fence in sleep(): the writer sees the sleeper or the
    // sleeper sees the new word (never neither), so the wake syscall is only
    // paid when someone sleeps.
    std::atomic_thread_fence(std::memory_order_seq_cst);
    if (m_sleepers.load(std::memory_order_relaxed) == 0) return;
#ifdef __linux__
    syscall(SYS_futex, reinterpret_cast<std::uint32_t*>(&m_word), FUTEX_WAKE_PRIVATE, INT_MAX,
            nullptr, nullptr, 0);
#else
    if (m_mutex.try_lock()) m_mutex.unlock();
    m_cv.notify_all();
#endif
}

void RowsArrivedSignal::sleep(std::uint32_t seen, Deadline deadline) const {
    const auto now = std::chrono::steady_clock::now();
    if (now >= deadline) return;
    m_sleepers.fetch_add(1, std::memory_order_relaxed);
    std::atomic_thread_fence(std::memory_order_seq_cst);
#ifdef __linux__
    const auto left_ns = std::chrono::duration_cast<std::chrono::nanoseconds>(deadline - now);
    timespec timeout{};
    timeout.tv_sec = time_t(left_ns.count() / 1'000'000'000);
    timeout.tv_nsec = long(left_ns.count() % 1'000'000'000);
    // Returns at once (EAGAIN) when the word already moved on.
    syscall(SYS_futex, const_cast<std::uint32_t*>(reinterpret_cast<const std::uint32_t*>(&m_word)),
            FUTEX_WAIT_PRIVATE, seen, &timeout, nullptr, 0);
#else
    std::unique_lock lock(m_mutex);
    if (word() == seen)
        m_cv.wait_until(lock, std::min(deadline, now + std::chrono::milliseconds(1)));
#endif
    m_sleepers.fetch_sub(1, std::memory_order_relaxed);
}

}  // namespace driftlab::live
