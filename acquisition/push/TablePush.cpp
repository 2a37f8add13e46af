#include "acquisition/push/TablePush.h"

#include "acquisition/push/ActiveTableRead.h"

#include <QElapsedTimer>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <thread>

namespace driftlab::push {
namespace {

/// The next version: one above the active one, never 0 and never a number the
/// controller is still reporting (active, previous or acknowledged).
std::uint16_t nextVersion(std::uint16_t active, std::uint16_t previous, std::uint16_t ack) {
    std::uint16_t v = active;
    do {
        v = v == 65535 ? 1 : std::uint16_t(v + 1);
    } while (v == active || v == previous || v == ack);
    return v;
}

}  // namespace

TablePush::TablePush(modbus::ModbusUrl url, PushOptions options)
    : m_link(std::move(url), options.response_timeout_s), m_options(std::move(options)) {}

PushResult TablePush::push(const compensation::CompensationTable& table) {
    m_result = PushResult{};
    m_result.controller = m_link.url().toString();
    m_identity = {};
    m_before = m_sent = TableImage{};
    QElapsedTimer timer;
    timer.start();
    try {
        run(table);
    } catch (const LinkError& lost) {
        const QString where = m_stepName;
        try {
            recoverAfterLostLink(lost.error);
        } catch (const LinkError& again) {
            step(QStringLiteral("recover"), false, again.error);
            finish(PushOutcome::Failed,
                   QStringLiteral("%1 (step %2); the link failed again while recovering (%3): the "
                                  "controller's table is unknown, check it")
                       .arg(lost.error, where, again.error));
        }
    }
    m_result.requests = m_link.requests();
    m_result.write_requests = m_link.writeRequests();
    m_result.elapsed_s = timer.nsecsElapsed() * 1e-9;
    m_link.close();
    return m_result;
}

void TablePush::run(const compensation::CompensationTable& table) {
    m_stepName = QStringLiteral("connect");
    QString error;
    if (!m_link.connect(&error)) {
        step(m_stepName, false, error);
        return finish(PushOutcome::Failed, error + QStringLiteral("; nothing written"));
    }
    step(m_stepName, true, m_link.url().endpoint());

    m_stepName = QStringLiteral("identify");
    const std::vector<std::uint16_t> block0 = read(0, reg::kIdentityCount);
    const QString endpoint = m_link.url().endpoint();
    if (block0[reg::kMagic] != kMagicValue || block0[reg::kMapVersion] != kMapVersionValue) {
        const QString why = QStringLiteral(
                                "%1: registers 0-1 hold 0x%2 version %3, not DriftLab's map "
                                "(0x4446 version 1); nothing written")
                                .arg(endpoint)
                                .arg(block0[reg::kMagic], 4, 16, QLatin1Char('0'))
                                .arg(block0[reg::kMapVersion]);
        step(m_stepName, false, why);
        return finish(PushOutcome::Failed, why);
    }
    m_identity = identityOf(block0);
    m_result.capacity = m_identity.capacity;
    m_result.active_before = m_identity.active;
    if (m_identity.capacity < 2 || m_identity.capacity > kMaxCapacity) {
        const QString why = QStringLiteral("%1: capacity %2 (register 3) is not 2 to %3")
                                .arg(endpoint)
                                .arg(m_identity.capacity)
                                .arg(kMaxCapacity);
        step(m_stepName, false, why);
        return finish(PushOutcome::Failed, why + QStringLiteral("; nothing written"));
    }
    step(m_stepName, true,
         QStringLiteral("map v1, capacity %1 points, machine %2, active table v%3")
             .arg(m_identity.capacity)
             .arg(machineStateName(m_identity.state))
             .arg(m_identity.active));

    m_stepName = QStringLiteral("read_active");
    m_before = readActive();
    step(m_stepName, true,
         QStringLiteral("v%1, %2 points").arg(m_before.version()).arg(m_before.points()));
    if (!checkTable(table)) return;
    if (cancelled(0.2, QStringLiteral("checked")))
        return finish(PushOutcome::Failed, QStringLiteral("cancelled before any write"));

    m_stepName = QStringLiteral("abort_leftover");
    writeCommand(Command::Abort);
    step(m_stepName, true, QStringLiteral("anything left staged discarded"));
    stage();
    if (cancelled(0.6, QStringLiteral("staged")))
        return abortAndVerify(PushOutcome::Failed, QStringLiteral("cancelled after staging"));
    m_stepName = QStringLiteral("commit");
    writeCommand(Command::Commit);
    step(m_stepName, true, QStringLiteral("commit requested for v%1").arg(m_result.version));
    awaitAck();
}

bool TablePush::checkTable(const compensation::CompensationTable& table) {
    m_stepName = QStringLiteral("check");
    const auto refuse = [&](const QString& why) {
        step(m_stepName, false, why);
        finish(PushOutcome::Refused, why + QStringLiteral("; nothing written"));
        return false;
    };
    QString why;
    if (!m_options.limits.isValid(&why)) return refuse(why);
    if (table.size() > std::size_t(m_identity.capacity))
        return refuse(QStringLiteral("the table has %1 points; the controller at %2 takes at most "
                                     "%3: use a larger spacing")
                          .arg(table.size())
                          .arg(m_link.url().endpoint())
                          .arg(m_identity.capacity));
    why = compensation::validate(table, m_options.limits, m_identity.capacity);
    if (!why.isEmpty()) return refuse(why);
    if (std::isfinite(m_options.limits.max_change_um)) {
        why = compensation::checkChange(activeAtPointsOf(m_before, table), table, m_options.limits);
        if (!why.isEmpty())
            return refuse(QStringLiteral("against the controller's active table v%1: %2")
                              .arg(m_before.version())
                              .arg(why));
    }
    const std::uint16_t version =
        nextVersion(m_identity.active, m_identity.previous, m_identity.ack);
    const EncodeResult encoded = encodeTable(table, version, m_identity.capacity);
    if (!encoded.ok()) return refuse(encoded.error);
    m_sent = encoded.image;
    m_result.version = version;
    m_result.points = m_sent.points();
    m_result.checksum = m_sent.checksum();
    step(m_stepName, true,
         QStringLiteral("%1 points within the limits, as v%2, checksum 0x%3")
             .arg(m_sent.points())
             .arg(version)
             .arg(m_sent.checksum(), 4, 16, QLatin1Char('0')));
    return true;
}

void TablePush::stage() {
    m_stepName = QStringLiteral("stage");
    write(reg::kStagedHeader, m_sent.header);
    cancelled(0.3, QStringLiteral("staging"));
    write(reg::kStagedData, m_sent.plus);
    if (!m_sent.minus.empty()) write(reg::kStagedData + m_identity.capacity, m_sent.minus);
    step(m_stepName, true,
         QStringLiteral("header and %1 data registers written")
             .arg(m_sent.plus.size() + m_sent.minus.size()));
}

void TablePush::awaitAck() {
    m_stepName = QStringLiteral("await_ack");
    QElapsedTimer timer;
    timer.start();
    for (;;) {
        const Identity now = identityOf(read(0, reg::kPreviousVersion + 1));
        if (now.ack == m_result.version && now.status != CommitStatus::Staged) {
            const QString answer = describe(now.status);
            step(m_stepName, now.status == CommitStatus::Applied,
                 QStringLiteral("%1 (machine %2)").arg(answer, machineStateName(now.state)));
            if (now.status == CommitStatus::Applied) return readBack();
            const PushOutcome outcome =
                now.status == CommitStatus::Refused ? PushOutcome::Refused : PushOutcome::Failed;
            return abortAndVerify(outcome, QStringLiteral("%1 answered '%2' to table v%3")
                                               .arg(m_link.url().endpoint(), answer)
                                               .arg(m_result.version));
        }
        const double waited_s = timer.nsecsElapsed() * 1e-9;
        if (waited_s > m_options.ack_timeout_s) {
            const QString why = QStringLiteral(
                                    "table v%1 not applied within %2 s (machine %3, commit "
                                    "status: %4)")
                                    .arg(m_result.version)
                                    .arg(m_options.ack_timeout_s)
                                    .arg(machineStateName(now.state), describe(now.status));
            step(m_stepName, false, why);
            return abortAndVerify(PushOutcome::Failed, why);
        }
        if (cancelled(0.7 + 0.2 * waited_s / m_options.ack_timeout_s,
                      QStringLiteral("waiting for the controller (machine %1)")
                          .arg(machineStateName(now.state)))) {
            step(m_stepName, false, QStringLiteral("cancelled"));
            return abortAndVerify(PushOutcome::Failed,
                                  QStringLiteral("cancelled while waiting for the controller"));
        }
        std::this_thread::sleep_for(std::chrono::duration<double>(m_options.poll_interval_s));
    }
}

void TablePush::readBack() {
    m_stepName = QStringLiteral("read_back");
    const TableImage active = readActive();
    if (active == m_sent) {
        step(m_stepName, true, QStringLiteral("active table equals what was sent"));
        cancelled(1.0, QStringLiteral("done"));
        return finish(PushOutcome::Applied,
                      QStringLiteral("table v%1 (%2 points) applied on %3 and read back equal")
                          .arg(m_result.version)
                          .arg(m_result.points)
                          .arg(m_result.controller));
    }
    const QString why = QStringLiteral("read-back of table v%1: %2")
                            .arg(m_result.version)
                            .arg(firstDifference(m_sent, active, m_identity.capacity));
    step(m_stepName, false, why);
    rollBackAndVerify(why);
}

// The requests every step uses; a failed one is thrown as LinkError so that
// the steps read in protocol order and push() recovers in one place.

TablePush::Identity TablePush::identityOf(const std::vector<std::uint16_t>& block0) {
    Identity id;
    id.state = MachineState(block0[reg::kMachineState]);
    id.capacity = block0[reg::kCapacity];
    id.active = block0[reg::kActiveVersion];
    id.status = CommitStatus(block0[reg::kCommitStatus]);
    id.ack = block0[reg::kAckVersion];
    id.previous = block0[reg::kPreviousVersion];
    return id;
}

std::vector<std::uint16_t> TablePush::read(int address, int count) {
    std::vector<std::uint16_t> values;
    QString error;
    if (!m_link.readRegisters(address, count, values, &error)) throw LinkError{error};
    return values;
}

void TablePush::write(int address, std::span<const std::uint16_t> values) {
    QString error;
    if (!m_link.writeRegisters(address, values, &error)) throw LinkError{error};
}

void TablePush::writeCommand(Command command) {
    // Alone and last, with function 16 (the map uses no other write).
    const std::uint16_t value = std::uint16_t(command);
    write(reg::kCommand, std::span<const std::uint16_t>(&value, 1));
}

TableImage TablePush::readActive() {
    TableImage image;
    QString error;
    if (!readActiveImage(m_link, m_identity.capacity, image, &error)) throw LinkError{error};
    return image;
}

void TablePush::step(const QString& name, bool ok, const QString& detail) {
    m_result.steps.push_back({name, ok, detail});
}

void TablePush::finish(PushOutcome outcome, const QString& message) {
    m_result.outcome = outcome;
    m_result.message = message;
}

bool TablePush::cancelled(double fraction, const QString& stepName) {
    const bool stop = m_options.progress && !m_options.progress(fraction, stepName);
    return stop || (m_options.cancel && m_options.cancel->load());
}

compensation::CompensationTable activeAtPointsOf(const TableImage& active,
                                                 const compensation::CompensationTable& next) {
    const compensation::CompensationTable now = decodeTable(active);
    compensation::CompensationTable out = next;
    for (std::size_t i = 0; i < next.size(); ++i) {
        const double x = next.position_mm[i];
        double plus = 0, minus = 0;
        if (active.version() != 0 && now.size() >= 2) {
            const double spacing = now.spacing_mm();
            const double at =
                std::clamp((x - now.position_mm.front()) / spacing, 0.0, double(now.size() - 1));
            const std::size_t k = std::min(std::size_t(at), now.size() - 2);
            const double f = at - double(k);
            plus = now.correction_plus_um[k] * (1 - f) + now.correction_plus_um[k + 1] * f;
            minus = now.correction_minus_um[k] * (1 - f) + now.correction_minus_um[k + 1] * f;
        }
        out.correction_plus_um[i] = plus;
        out.correction_minus_um[i] = minus;
    }
    return out;
}

PushResult pushTable(const modbus::ModbusUrl& url, const compensation::CompensationTable& table,
                     const PushOptions& options) {
    return TablePush(url, options).push(table);
}

}  // namespace driftlab::push
