#pragma once
// How driftlab-cli and driftlab-bench talk to a terminal or a script: results
// on stdout (JSON with --json), progress on stderr, a one-line reason and a
// non-zero exit on failure.

#include <QJsonObject>
#include <QString>
#include <stdexcept>

namespace driftlab::cli {

/// Thrown by commands; main() prints "driftlab-cli: <what>" and exits non-zero.
struct CliError : std::runtime_error {
    explicit CliError(const QString& why, int exitCode = 1)
        : std::runtime_error(why.toStdString()), exitCode(exitCode) {}
    int exitCode;
};

/// Progress "label: 42%" on stderr, rewritten in place; returns true (never cancels).
bool printProgress(const QString& label, double fraction);
/// Ends an unfinished progress line so that what follows starts on its own line.
void endProgressLine();

/// Before the QApplication of a program without windows: Qt renders
/// offscreen (unless QT_QPA_PLATFORM says otherwise) and gets the private
/// runtime folder it wants, made as Qt would make it, without its warning.
void prepareHeadlessQt();

void printJson(const QJsonObject& object);
void printLine(const QString& text);

}  // namespace driftlab::cli
