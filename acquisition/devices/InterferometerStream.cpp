#include "acquisition/devices/InterferometerStream.h"

namespace driftlab::devices {

InterferometerStreamResult readInterferometerStream(
    const InterferometerStreamOptions& options,
    const std::function<void(const interferometer::CorrectedReading&)>& onReading) {
    InterferometerStreamResult result;
    InterferometerConnection connection(options);
    if (!connection.open(&result.error)) return result;
    auto status = InterferometerConnection::Status::Open;
    while (status == InterferometerConnection::Status::Open)
        status = connection.read(options.timeout_ms, onReading);
    result.readings = connection.readings();
    result.correction = connection.correction();
    result.error = connection.error();
    result.errorLine = connection.errorLine();
    result.complete = status == InterferometerConnection::Status::Ended;
    return result;
}

}  // namespace driftlab::devices
