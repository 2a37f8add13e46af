#include "acquisition/devices/InterferometerConnection.h"

#include <QTcpSocket>

namespace driftlab::devices {
namespace {

/// A line longer than this is not the protocol (a binary peer, a wrong port).
constexpr qint64 kMaxLineBytes = 4096;

}  // namespace

InterferometerConnection::InterferometerConnection(InterferometerStreamOptions options)
    : m_options(std::move(options)) {}

InterferometerConnection::~InterferometerConnection() = default;

QString InterferometerConnection::peer() const {
    return QStringLiteral("%1:%2").arg(m_options.host).arg(m_options.port);
}

bool InterferometerConnection::open(QString* error) {
    close();
    m_error.clear();
    m_errorLine = 0;
    m_readings = 0;
    m_session.emplace(m_options.maxEnvironmentAge_s);
    m_socket = std::make_unique<QTcpSocket>();
    m_socket->connectToHost(m_options.host, m_options.port);
    if (!m_socket->waitForConnected(m_options.timeout_ms)) {
        m_error = QStringLiteral("cannot connect to the interferometer at %1: %2")
                      .arg(peer(), m_socket->errorString());
        if (error) *error = m_error;
        m_socket.reset();
        return false;
    }
    m_sinceBytes.start();
    return true;
}

void InterferometerConnection::close() {
    if (!m_socket) return;
    m_socket->abort();
    m_socket.reset();
}

bool InterferometerConnection::feedBufferedLines(const ReadingHandler& onReading) {
    while (m_socket->canReadLine()) {
        QByteArray line = m_socket->readLine(kMaxLineBytes + 2);
        if (line.endsWith('\n')) line.chop(1);
        try {
            if (const auto reading =
                    m_session->feed(std::string_view(line.constData(), std::size_t(line.size())))) {
                m_correction = reading->correction.description;
                ++m_readings;
                onReading(*reading);
            }
        } catch (const interferometer::InterferometerLineError& e) {
            m_error = QString::fromStdString(e.what());
            m_errorLine = e.line();
            return false;
        }
        if (m_session->ended()) return false;
    }
    return true;
}

InterferometerConnection::Status InterferometerConnection::finished() {
    if (!m_error.isEmpty()) return Status::Failed;
    m_socket->disconnectFromHost();
    return Status::Ended;
}

InterferometerConnection::Status InterferometerConnection::fail(const QString& message) {
    m_error = message;
    return Status::Failed;
}

InterferometerConnection::Status InterferometerConnection::read(int wait_ms,
                                                                const ReadingHandler& onReading) {
    if (!m_socket)
        return fail(QStringLiteral("the interferometer at %1 is not connected").arg(peer()));
    if (!feedBufferedLines(onReading)) return finished();
    if (m_socket->bytesAvailable() > kMaxLineBytes)
        return fail(QStringLiteral("line %1: longer than %2 bytes without a line break "
                                   "(not the interferometer protocol?)")
                        .arg(m_session->parser().lineNumber() + 1)
                        .arg(kMaxLineBytes));
    if (m_socket->waitForReadyRead(wait_ms)) {
        m_sinceBytes.start();
        return feedBufferedLines(onReading) ? Status::Open : finished();
    }
    // Closed or silent: what was buffered is still read, then say how it ended.
    if (!feedBufferedLines(onReading)) return finished();
    const bool closed = m_socket->error() == QAbstractSocket::RemoteHostClosedError ||
                        m_socket->state() != QAbstractSocket::ConnectedState;
    if (!closed && m_sinceBytes.elapsed() < m_options.timeout_ms) return Status::Open;
    const int line = m_session->parser().lineNumber();
    if (!closed)
        return fail(QStringLiteral("the interferometer at %1 sent nothing for %2 ms after "
                                   "line %3: %4")
                        .arg(peer())
                        .arg(m_options.timeout_ms)
                        .arg(line)
                        .arg(m_socket->errorString()));
    const QByteArray partial = m_socket->readAll();
    return fail(QStringLiteral("the interferometer at %1 closed the connection after line %2 "
                               "without an 'end' line%3; the %4 reading(s) before are kept")
                    .arg(peer())
                    .arg(line)
                    .arg(partial.isEmpty() ? QString()
                                           : QStringLiteral(" (a cut-off line '%1' dropped)")
                                                 .arg(QString::fromUtf8(partial.left(80))))
                    .arg(m_readings));
}

}  // namespace driftlab::devices
