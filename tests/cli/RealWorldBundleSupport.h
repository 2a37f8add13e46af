#pragma once
// Helpers for the tests of bundles as other software writes them: real tools
// (python3, zip) rewrite a copy of the example, and the real driftlab-cli
// imports and exports it.
#include <QDir>
#include <QString>
#include <QStringList>

#include "core/domain/Campaign.h"
#include "tests/support/CliRunner.h"  // runTool

namespace driftlab::test {

/// Imports `bundle` into a new store and exports it again: what DriftLab stored.
Campaign importedAndExported(const QString& bundle, const QDir& work, QByteArray* err = nullptr);

/// Rewrites `bundle` with a Python script (given the folder) as other software
/// would write it; imported and exported, it must be the plain example, and
/// the import must warn `warning` (none at all: nullptr).
void expectRewrittenImportsAsThePlainBundle(const QString& bundle, const char* script,
                                            const char* warning);

}  // namespace driftlab::test
