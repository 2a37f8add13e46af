// TablePush, the way back to a known table: abort a staged table, roll an
// applied one back, reconnect after a lost link, and in every case read the
// active table again to say whether the previous one is intact.
#include <QElapsedTimer>
#include <chrono>
#include <thread>

#include "acquisition/push/TablePush.h"

namespace driftlab::push {

bool TablePush::previousIntact() {
    const bool intact = sameTable(readActive(), m_before);
    m_result.previous_intact = intact;
    step(QStringLiteral("verify_previous"), intact,
         intact ? QStringLiteral("active table is v%1 as before the push").arg(m_before.version())
                : QStringLiteral("active table differs from v%1 read before the push")
                      .arg(m_before.version()));
    return intact;
}

void TablePush::abortAndVerify(PushOutcome outcome, const QString& why) {
    m_stepName = QStringLiteral("abort");
    writeCommand(Command::Abort);
    step(m_stepName, true, QStringLiteral("staged table v%1 discarded").arg(m_result.version));
    if (previousIntact())
        return finish(outcome, why + QStringLiteral("; aborted, the previous table (v%1) is intact")
                                         .arg(m_before.version()));
    finish(PushOutcome::Failed,
           why + QStringLiteral("; aborted, but the active table is no longer v%1 as read before "
                                "the push: check the controller")
                     .arg(m_before.version()));
}

bool TablePush::waitForStatus(CommitStatus wanted, double timeout_s) {
    QElapsedTimer timer;
    timer.start();
    for (;;) {
        const Identity now = identityOf(read(0, reg::kPreviousVersion + 1));
        if (now.status == wanted && now.ack == m_result.version) return true;
        if (timer.nsecsElapsed() * 1e-9 > timeout_s) return false;
        std::this_thread::sleep_for(std::chrono::duration<double>(m_options.poll_interval_s));
    }
}

void TablePush::rollBackAndVerify(const QString& why) {
    m_stepName = QStringLiteral("rollback");
    writeCommand(Command::RollBack);
    // A rollback restores a table the controller already checked, so it is
    // not held back by the machine state; still, its answer is bounded.
    const bool answered = waitForStatus(CommitStatus::RolledBack, m_options.ack_timeout_s);
    step(m_stepName, answered,
         answered
             ? QStringLiteral("controller rolled back v%1").arg(m_result.version)
             : QStringLiteral("no 'rolled back' answer within %1 s").arg(m_options.ack_timeout_s));
    if (previousIntact())
        return finish(PushOutcome::RolledBack,
                      why + QStringLiteral("; rolled back to the previous table (v%1), read back "
                                           "intact")
                                .arg(m_before.version()));
    finish(PushOutcome::Failed, why + QStringLiteral("; the rollback did not restore v%1: check "
                                                     "the controller")
                                          .arg(m_before.version()));
}

void TablePush::recoverAfterLostLink(const QString& error) {
    const QString where = m_stepName;
    step(where, false, error);
    const QString lost = QStringLiteral("%1 (step %2)").arg(error, where);
    if (m_link.writeRequests() == 0)
        return finish(PushOutcome::Failed, lost + QStringLiteral("; nothing written"));
    QString again;
    m_stepName = QStringLiteral("reconnect");
    if (!m_link.connect(&again)) {
        step(m_stepName, false, again);
        return finish(PushOutcome::Failed,
                      lost + QStringLiteral("; cannot reconnect (%1): the controller's table is "
                                            "unknown, check it")
                                 .arg(again));
    }
    step(m_stepName, true, m_link.url().endpoint());
    // The commit may have reached the controller before the link dropped:
    // what is active now decides between "intact", "applied" and a rollback.
    m_stepName = QStringLiteral("abort");
    writeCommand(Command::Abort);
    step(m_stepName, true, QStringLiteral("staged table v%1 discarded").arg(m_result.version));
    const TableImage now = readActive();
    if (sameTable(now, m_before)) {
        previousIntact();
        return finish(PushOutcome::Failed,
                      lost + QStringLiteral("; reconnected and aborted, the previous table (v%1) "
                                            "is intact")
                                 .arg(m_before.version()));
    }
    if (m_result.version != 0 && now == m_sent) {
        step(QStringLiteral("read_back"), true,
             QStringLiteral("active table equals what was sent"));
        return finish(PushOutcome::Applied,
                      QStringLiteral("table v%1 applied on %2 before the link dropped (%3); read "
                                     "back equal after reconnecting")
                          .arg(m_result.version)
                          .arg(m_result.controller, error));
    }
    rollBackAndVerify(lost + QStringLiteral("; the active table is neither v%1 nor the pushed one")
                                 .arg(m_before.version()));
}

}  // namespace driftlab::push
