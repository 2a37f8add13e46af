#pragma once
// Why data cannot be modelled: a message that names the run, channel or role
// at fault. Thrown inside the models code only; the public API (buildDataset,
// ThermalErrorModel::fit/predict, scoring) returns it as a message.

#include <QString>
#include <stdexcept>

namespace driftlab::models {

struct ModelError : std::runtime_error {
    explicit ModelError(const QString& message)
        : std::runtime_error(message.toStdString()), message(message) {}
    QString message;
};

/// A number as messages show it: up to six significant digits, no trailing zeros.
inline QString messageNumber(double value) {
    return QString::number(value, 'g', 6);
}

}  // namespace driftlab::models
