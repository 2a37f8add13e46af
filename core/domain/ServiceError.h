#pragma once
// The error the libraries' services (a held-out fit, live compensation)
// throw: one line naming where and why, and whether the request itself was
// wrong (an unknown model, overlapping runs) or the work failed on the data
// or a device. The command line turns the first into exit code 2.

#include <QString>
#include <stdexcept>

namespace driftlab {

struct ServiceError : std::runtime_error {
    enum class Kind { Failed, BadRequest };
    explicit ServiceError(const QString& why, Kind kind = Kind::Failed)
        : std::runtime_error(why.toStdString()), kind(kind) {}
    QString message() const { return QString::fromStdString(what()); }
    Kind kind;
};

}  // namespace driftlab
