#include "acquisition/logging/SpoolUploader.h"

#include <QSqlDatabase>
#include <algorithm>
#include <chrono>

namespace driftlab::logging {
namespace {

double now_s() {
    using namespace std::chrono;
    return duration<double>(steady_clock::now().time_since_epoch()).count();
}

constexpr double kInterval_s = 1.0;
constexpr double kFirstRetry_s = 0.5;
constexpr double kLongestRetry_s = 5.0;

}  // namespace

SpoolUploader::SpoolUploader(QString spoolPath, QString spoolId, QString serverUrl,
                             std::function<void(const QString&)> report)
    : m_spoolPath(std::move(spoolPath)),
      m_spoolId(std::move(spoolId)),
      m_serverUrl(std::move(serverUrl)),
      m_report(std::move(report)) {}

SpoolUploader::~SpoolUploader() {
    {
        std::lock_guard lock(m_mutex);
        m_stop = true;
    }
    m_wake.notify_all();
    if (m_thread.joinable()) m_thread.join();
}

void SpoolUploader::start() {
    m_thread = std::thread([this] { loop(); });
}

std::optional<db::UploadReport> SpoolUploader::finish(double timeout_s, QString* error) {
    {
        std::lock_guard lock(m_mutex);
        m_finishing = true;
        m_deadline_s = now_s() + timeout_s;
    }
    m_wake.notify_all();
    if (m_thread.joinable()) m_thread.join();
    std::lock_guard lock(m_mutex);
    if (!m_final && error) *error = m_lastError;
    return m_final;
}

bool SpoolUploader::pass(QString* error) {
    // The spool is opened afresh each pass: a new read-only connection sees
    // everything the logger committed since.
    auto spool = db::CampaignStore::open(m_spoolPath, db::StoreAccess::ReadOnly, error);
    if (!spool) return false;
    if (!m_server) {
        m_server = db::CampaignStore::open(m_serverUrl, db::StoreAccess::ReadWrite, error);
        if (!m_server) return false;
    }
    const auto report = db::uploadSpool(*spool, m_spoolId, *m_server, error);
    if (!report) {
        m_server.reset();  // a connection the server dropped is not reused
        return false;
    }
    m_last = *report;
    return true;
}

void SpoolUploader::loop() {
    double retry_s = kFirstRetry_s;
    double outageSince_s = -1;
    for (;;) {
        bool finishingAtStart = false;
        {
            std::lock_guard lock(m_mutex);
            if (m_stop) break;
            // Only a pass that begins after the run ended has all of it.
            finishingAtStart = m_finishing;
        }
        QString why;
        const bool ok = pass(&why);
        if (ok && outageSince_s >= 0) {
            m_report(QStringLiteral("upload: %1 is back after %2 s; the spool is uploaded")
                         .arg(m_serverUrl)
                         .arg(now_s() - outageSince_s, 0, 'f', 1));
            outageSince_s = -1;
        } else if (!ok && outageSince_s < 0) {
            // One message per outage: the next attempts would say the same.
            m_report(QStringLiteral("upload: %1; logging goes on into %2 and is uploaded when "
                                    "the server is back")
                         .arg(why, m_spoolPath));
            outageSince_s = now_s();
        }
        retry_s = ok ? kFirstRetry_s : std::min(retry_s * 2, kLongestRetry_s);
        std::unique_lock lock(m_mutex);
        if (!ok) m_lastError = why;
        if (finishingAtStart && ok) {
            m_final = m_last;
            break;
        }
        if (finishingAtStart && now_s() >= m_deadline_s) break;
        if (m_stop) break;
        m_wake.wait_for(lock, std::chrono::duration<double>(ok ? kInterval_s : retry_s),
                        [&] { return m_stop || (m_finishing && !finishingAtStart); });
    }
    m_server.reset();
}

}  // namespace driftlab::logging
