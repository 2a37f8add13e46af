#pragma once
// A laser interferometer streaming the line protocol (docs/interferometer.md)
// over TCP. A plain blocking reader: connect, read lines until `end`, hand each
// corrected reading to a callback. A reader thread or the command line drives
// it; the GUI can put it behind a signal later.

#include <QString>
#include <functional>

#include "core/interferometer/InterferometerSession.h"

namespace driftlab {

struct InterferometerStreamResult {
    int readings = 0;       ///< delivered to the callback, all kept whatever came after
    bool complete = false;  ///< the stream's `end` line arrived
    QString error;          ///< empty when complete
    int errorLine = 0;      ///< the line a protocol error is in; 0 for transport errors
    /// The last correction applied ("none: …" or "Edlén, …: … ppm").
    QString correction;
};

struct InterferometerStreamOptions {
    QString host = QStringLiteral("127.0.0.1");
    quint16 port = 0;
    /// Longest wait for the connection or for the next bytes; a silent
    /// interferometer is an error, not a hang.
    int timeout_ms = 10'000;
    double maxEnvironmentAge_s = 300.0;
};

/// Reads one stream. Never throws for the peer's faults: a bad line, a closed
/// connection or a timeout end the read with `error` set, and the readings
/// delivered before stay delivered.
InterferometerStreamResult readInterferometerStream(
    const InterferometerStreamOptions& options,
    const std::function<void(const CorrectedReading&)>& onReading);

}  // namespace driftlab
