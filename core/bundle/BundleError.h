#pragma once
// Where and why a bundle could not be read: file, line and column (1-based,
// 0 = not applicable) and a message a test engineer can act on.

#include <QString>
#include <stdexcept>

namespace driftlab::bundle {

struct BundleError {
    QString file;
    int line = 0;
    int column = 0;
    QString message;

    QString toString() const {
        QString where = file;
        if (line > 0) where += QStringLiteral(":%1").arg(line);
        if (column > 0) where += QStringLiteral(":%1").arg(column);
        return where + QStringLiteral(": ") + message;
    }
};

/// Thrown inside the bundle parsers only; the public API returns BundleError.
struct BundleException : std::runtime_error {
    explicit BundleException(BundleError e)
        : std::runtime_error(e.toString().toStdString()), error(std::move(e)) {}
    BundleError error;
};

}  // namespace driftlab::bundle
