#pragma once
// A laser interferometer streaming the line protocol (docs/interferometer.md)
// over TCP, read whole: connect, read lines until `end`, hand each corrected
// reading to a callback. The command line and the tests use it; the rig reads
// the same connection a slice at a time (InterferometerDevice).

#include <QString>
#include <functional>

#include "acquisition/devices/InterferometerConnection.h"

namespace driftlab::devices {

struct InterferometerStreamResult {
    int readings = 0;       ///< delivered to the callback, all kept whatever came after
    bool complete = false;  ///< the stream's `end` line arrived
    QString error;          ///< empty when complete
    int errorLine = 0;      ///< the line a protocol error is in; 0 for transport errors
    /// The last correction applied ("none: …" or "Edlén, …: … ppm").
    QString correction;
};

/// Reads one stream. Never throws for the peer's faults: a bad line, a closed
/// connection or a timeout end the read with `error` set, and the readings
/// delivered before stay delivered.
InterferometerStreamResult readInterferometerStream(
    const InterferometerStreamOptions& options,
    const std::function<void(const interferometer::CorrectedReading&)>& onReading);

}  // namespace driftlab::devices
