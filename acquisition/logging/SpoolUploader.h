#pragma once
// The uploader of a rig that logs into a server store (docs/lab-store.md):
// on its own thread, it runs an upload pass (db/SpoolUpload.h) from the local
// spool to the server about once a second while the run is logged. When the
// server is away it keeps retrying with backoff (0.5 s doubling to 5 s) and
// reports one message per outage, not one per attempt; the logger never
// waits for it, and what it has not uploaded stays in the spool.

#include <QString>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <optional>
#include <thread>

#include "db/SpoolUpload.h"

namespace driftlab::logging {

class SpoolUploader {
public:
    /// `report` receives the outage and recovery messages, from the uploader's thread.
    SpoolUploader(QString spoolPath, QString spoolId, QString serverUrl,
                  std::function<void(const QString&)> report);
    /// Stops the thread (without a last pass if finish() was not called).
    ~SpoolUploader();
    SpoolUploader(const SpoolUploader&) = delete;
    SpoolUploader& operator=(const SpoolUploader&) = delete;

    void start();
    /// After the run: passes until one completes or `timeout_s` has gone by.
    /// The report of the completing pass, or nullopt with `error` (the last
    /// reason) when the server stayed away; the spool keeps everything then.
    std::optional<db::UploadReport> finish(double timeout_s, QString* error);

private:
    void loop();
    /// One pass on this thread's connections; false with `error` when it stopped.
    bool pass(QString* error);

    QString m_spoolPath, m_spoolId, m_serverUrl;
    std::function<void(const QString&)> m_report;
    std::thread m_thread;
    std::mutex m_mutex;
    std::condition_variable m_wake;
    bool m_finishing = false;  ///< guarded by m_mutex
    bool m_stop = false;       ///< guarded by m_mutex
    double m_deadline_s = 0;   ///< of finish(), on the steady clock; guarded by m_mutex
    std::optional<db::UploadReport> m_final;      ///< guarded by m_mutex
    QString m_lastError;                          ///< guarded by m_mutex
    std::unique_ptr<db::CampaignStore> m_server;  ///< the thread's connection, kept between passes
    db::UploadReport m_last;
};

}  // namespace driftlab::logging
