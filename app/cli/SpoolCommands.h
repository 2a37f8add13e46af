#pragma once
// The spool of a rig that logs into a server store (docs/lab-store.md): where
// it is, and making it ready; shared by `run --db postgresql://…` and `sync`.

#include <QCommandLineOption>
#include <QCommandLineParser>
#include <QString>

namespace driftlab::cli {

/// --spool FILE, for commands that log into or upload to a server store.
QCommandLineOption spoolOption();
/// --spool's value, else the default: driftlab/spool.sqlite in the user's data
/// folder ($XDG_DATA_HOME, usually ~/.local/share), created when missing.
QString spoolPath(const QCommandLineParser& parser, const QCommandLineOption& spool);
/// Creates the spool when missing, migrates it, and returns its id. Throws CliError.
QString prepareSpool(const QString& path);

}  // namespace driftlab::cli
