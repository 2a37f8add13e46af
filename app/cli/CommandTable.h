#pragma once
// The commands of driftlab-cli (docs/cli.md), built or not: one table
// that the usage, `help COMMAND`, every command's --help and the dispatch read.

#include <QString>
#include <QStringList>
#include <vector>

namespace driftlab::cli {

/// Exit codes scripts can tell apart (README "Using driftlab-cli").
enum ExitCode : int { kExitOk = 0, kExitFailure = 1, kExitUsage = 2, kExitNotBuilt = 3 };

struct Command {
    QString name;
    /// Takes the arguments from the command name on; null for a command this
    /// build lists but does not have (exit kExitNotBuilt).
    int (*run)(const QStringList& args) = nullptr;
    QString synopsis;  ///< e.g. "import BUNDLE --db FILE"
    QString summary;   ///< what it does, one line; also the first line of its --help
    /// Not in the usage nor guessed for a typo: a command DriftLab runs itself
    /// (batch's per-item child), not one for users.
    bool hidden = false;
};

/// Every command, in the order of docs/cli.md.
const std::vector<Command>& commands();
/// The command of that name, or null.
const Command* findCommand(const QString& name);
/// The command a misspelled or shortened name most likely meant, or empty.
QString closestCommand(const QString& name);
/// The whole usage: commands, how to get help, exit codes.
QString usageText();
/// "not built yet in DriftLab 0.1.0": the reason given for a command not built.
QString notBuiltReason();

}  // namespace driftlab::cli
