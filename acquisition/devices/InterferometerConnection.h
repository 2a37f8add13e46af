#pragma once
// One TCP connection to an interferometer streaming the line protocol
// (docs/interferometer.md), read a slice at a time: the whole-stream reader
// (readInterferometerStream) and the rig's device worker (InterferometerDevice)
// both read through it, so the protocol and its errors live in one place.

#include <QElapsedTimer>
#include <QString>
#include <functional>
#include <memory>
#include <optional>

#include "core/interferometer/InterferometerSession.h"

class QTcpSocket;

namespace driftlab::devices {

struct InterferometerStreamOptions {
    QString host = QStringLiteral("127.0.0.1");
    quint16 port = 0;
    /// Longest wait for the connection or for the next bytes; a silent
    /// interferometer is an error, not a hang.
    int timeout_ms = 10'000;
    double maxEnvironmentAge_s = 300.0;
};

class InterferometerConnection {
public:
    enum class Status {
        Open,    ///< still streaming
        Ended,   ///< the stream's `end` line arrived
        Failed,  ///< error() says why; the readings before stay delivered
    };
    using ReadingHandler = std::function<void(const interferometer::CorrectedReading&)>;

    explicit InterferometerConnection(InterferometerStreamOptions options);
    ~InterferometerConnection();

    /// "HOST:PORT".
    QString peer() const;
    /// Connects and starts a new stream (a fresh session). False with `error`.
    bool open(QString* error);
    /// Reads what arrives within `wait_ms` (at most) and hands each corrected
    /// reading to `onReading`. Open while the stream goes on and the peer has
    /// sent something within the options' timeout.
    Status read(int wait_ms, const ReadingHandler& onReading);
    void close();

    const QString& error() const { return m_error; }
    /// The line a protocol error is in; 0 for transport errors.
    int errorLine() const { return m_errorLine; }
    /// Readings delivered since open().
    int readings() const { return m_readings; }
    /// The last correction applied ("none: …" or "Edlén, …: … ppm").
    const QString& correction() const { return m_correction; }

private:
    bool feedBufferedLines(const ReadingHandler& onReading);
    Status finished();
    Status fail(const QString& message);

    InterferometerStreamOptions m_options;
    std::unique_ptr<QTcpSocket> m_socket;  ///< made in open(), on the reading thread
    std::optional<interferometer::InterferometerSession> m_session;
    QElapsedTimer m_sinceBytes;
    QString m_error, m_correction;
    int m_errorLine = 0;
    int m_readings = 0;
};

}  // namespace driftlab::devices
