#include "acquisition/devices/InterferometerStream.h"

#include <QTcpSocket>

namespace driftlab {
namespace {

/// A line longer than this is not the protocol (a binary peer, a wrong port).
constexpr qint64 kMaxLineBytes = 4096;

}  // namespace

InterferometerStreamResult readInterferometerStream(
    const InterferometerStreamOptions& options,
    const std::function<void(const CorrectedReading&)>& onReading) {
    InterferometerStreamResult result;
    const QString peer = QStringLiteral("%1:%2").arg(options.host).arg(options.port);
    QTcpSocket socket;
    socket.connectToHost(options.host, options.port);
    if (!socket.waitForConnected(options.timeout_ms)) {
        result.error = QStringLiteral("cannot connect to the interferometer at %1: %2")
                           .arg(peer, socket.errorString());
        return result;
    }

    InterferometerSession session(options.maxEnvironmentAge_s);
    auto feedBufferedLines = [&]() -> bool {
        while (socket.canReadLine()) {
            QByteArray line = socket.readLine(kMaxLineBytes + 2);
            if (line.endsWith('\n')) line.chop(1);
            try {
                if (const auto reading = session.feed(
                        std::string_view(line.constData(), std::size_t(line.size())))) {
                    result.correction = reading->correction.description;
                    ++result.readings;
                    onReading(*reading);
                }
            } catch (const InterferometerLineError& e) {
                result.error = QString::fromStdString(e.what());
                result.errorLine = e.line();
                return false;
            }
            if (session.ended()) return false;
        }
        return true;
    };

    while (true) {
        if (!feedBufferedLines()) break;
        if (socket.bytesAvailable() > kMaxLineBytes) {
            result.error = QStringLiteral(
                               "line %1: longer than %2 bytes without a line break "
                               "(not the interferometer protocol?)")
                               .arg(session.parser().lineNumber() + 1)
                               .arg(kMaxLineBytes);
            break;
        }
        if (socket.waitForReadyRead(options.timeout_ms)) continue;
        // Closed or silent: what was buffered is still read, then say how it ended.
        if (!feedBufferedLines()) break;
        const QByteArray partial = socket.readAll();
        if (socket.error() == QAbstractSocket::RemoteHostClosedError ||
            socket.state() != QAbstractSocket::ConnectedState) {
            result.error =
                QStringLiteral(
                    "the interferometer at %1 closed the connection after line %2 "
                    "without an 'end' line%3; the %4 reading(s) before are kept")
                    .arg(peer)
                    .arg(session.parser().lineNumber())
                    .arg(partial.isEmpty() ? QString()
                                           : QStringLiteral(" (a cut-off line '%1' dropped)")
                                                 .arg(QString::fromUtf8(partial.left(80))))
                    .arg(result.readings);
        } else {
            result.error = QStringLiteral(
                               "the interferometer at %1 sent nothing for %2 ms after "
                               "line %3: %4")
                               .arg(peer)
                               .arg(options.timeout_ms)
                               .arg(session.parser().lineNumber())
                               .arg(socket.errorString());
        }
        return result;
    }
    result.complete = session.ended() && result.error.isEmpty();
    socket.disconnectFromHost();
    return result;
}

}  // namespace driftlab
