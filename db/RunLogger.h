#pragma once
// Live logging of one run into the store (docs/store.md), from the
// acquisition thread: rows, interferometer readings, motion and events are
// kept in memory and written in one transaction at least every second
// (commitIfDue), with a synchronous (FULL) commit, so a crash, a kill or a
// power loss loses at most the last second and leaves the file consistent.
// Samples go into the run's sample blocks; the block being filled is
// rewritten at each commit until it is full, so a run logged live reads back
// in the same blocks as an imported one.
//
// A run being logged has status 'logging' and a lock file beside the store
// (QLockFile, which knows a dead owner); markInterruptedRuns() turns a
// 'logging' run whose logger is gone into 'interrupted', and resume()
// continues it.

#include <QElapsedTimer>
#include <QJsonObject>
#include <QLockFile>
#include <QString>
#include <memory>
#include <optional>
#include <vector>

#include "core/domain/Run.h"
#include "db/CampaignStore.h"
#include "db/SampleBlocks.h"

namespace driftlab::db {

/// What a run is, as the logger creates it.
struct RunHeader {
    QString name;
    RunKind kind = RunKind::Moving;
    std::optional<double> feed_mm_min;
    std::optional<RangeMm> range_mm;
    QString description;
    QJsonObject extra;
};

/// Where an interrupted run stopped: its last committed sample and reading.
struct LoggedRunState {
    qint64 run_id = 0;
    qint64 campaign_id = 0;
    QString name;
    QString status;
    std::optional<double> last_sample_s;
    std::optional<double> last_reading_s;
    qint64 rows = 0;
    qint64 readings = 0;
    qint64 motion_segments = 0;
    /// The campaign's machine and the rig it was logged on (`rig`,
    /// `rig_real_time` in the campaign's extra), so a resume can refuse another rig.
    QString machine;
    QString rig;
    std::optional<bool> rig_real_time;
    /// The later of the two: where logging continues.
    double end_s() const;
};

class RunLogger {
public:
    /// Adds a run (status 'logging') to the campaign and takes its lock.
    static std::unique_ptr<RunLogger> begin(CampaignStore& store, qint64 campaignId,
                                            const RunHeader& header, QString* error);
    /// Continues an interrupted run (status back to 'logging'); new rows must
    /// come after its last logged time.
    static std::unique_ptr<RunLogger> resume(CampaignStore& store, qint64 runId, QString* error);
    /// Commits what is pending; a run not finished stays 'interrupted'.
    ~RunLogger();
    RunLogger(const RunLogger&) = delete;
    RunLogger& operator=(const RunLogger&) = delete;

    /// One row in the campaign's sample column order; times increase.
    void appendRow(double time_s, const double* values);
    void appendReading(const PositioningMeasurement& reading);
    void appendMotion(const MotionSegment& segment);
    void appendEvent(const QString& level, const QString& source, const QString& message);

    /// Commits when the last commit is `interval_ms` or more ago.
    bool commitIfDue(QString* error, int interval_ms = 1000);
    bool commit(QString* error);
    /// Commits and sets the final status: 'complete' or 'interrupted'.
    bool finish(const QString& status, QString* error);

    qint64 runId() const { return m_runId; }
    std::size_t columnCount() const { return m_columns; }
    std::optional<double> lastRowTime_s() const { return m_lastTime_s; }
    qint64 rowsLogged() const { return m_rows; }
    /// Rows appended since the last successful commit (held in memory only).
    qint64 unsavedRows() const { return m_rows - m_savedRows; }
    /// The time of the last row the store holds.
    std::optional<double> savedUntil_s() const { return m_savedUntil_s; }

    /// The lock file of a run being logged in the store at `storePath`.
    static QString lockPath(const QString& storePath, qint64 runId);

private:
    RunLogger(CampaignStore& store, qint64 runId, std::size_t columns);
    bool start(QString* error);
    void writePending();

    CampaignStore& m_store;
    qint64 m_runId;
    std::size_t m_columns;
    QLockFile m_lock;
    std::unique_ptr<SqliteStatement> m_insertBlock, m_insertReading, m_insertMotion;
    // A block: times and column-major values (kRowsPerBlock per column).
    struct Block {
        std::vector<double> time_s, values;
        qint64 present = 0;
    };
    Block m_block;                    ///< being filled
    bool m_blockDirty = false;        ///< rows since it was last written
    std::vector<Block> m_fullBlocks;  ///< filled since the last commit
    std::vector<double> m_blob;
    std::vector<PositioningMeasurement> m_readings;
    std::vector<MotionSegment> m_motion;
    struct Event {
        QString level, source, message;
    };
    std::vector<Event> m_events;
    std::optional<double> m_lastTime_s, m_savedUntil_s;
    qint64 m_rows = 0, m_savedRows = 0;
    QElapsedTimer m_sinceCommit;
    bool m_finished = false;
};

/// The state of a logged run, or nullopt with `error`.
std::optional<LoggedRunState> loggedRunState(CampaignStore& store, qint64 runId, QString* error);
/// The sample columns of a campaign in stored order (what a row holds).
std::vector<QString> sampleColumns(CampaignStore& store, qint64 campaignId);
/// Marks 'logging' runs whose logger is gone (its lock is free) 'interrupted',
/// with an event each; returns their ids.
std::vector<qint64> markInterruptedRuns(CampaignStore& store, QString* error);

}  // namespace driftlab::db
