#pragma once
// Shared by the bundle, store and CLI tests: the example bundle, generated
// campaigns, files read, written and rewritten column by column (the catalogue
// of bad bundles is in BadBundleCases.h).

#include <QByteArray>
#include <QString>
#include <functional>
#include <vector>

#include "core/domain/Campaign.h"

namespace driftlab::test {

/// resources/examples/x-axis-moving-state in the source tree.
QString exampleBundlePath();
/// The example bundle as read (a test failure when it cannot be read).
Campaign exampleCampaign();
/// Copies a bundle folder into `target` (created).
void copyBundle(const QString& from, const QString& target);
QByteArray readFile(const QString& path);
void writeFile(const QString& path, const QByteArray& content);
/// Replaces the first occurrence of `what` in a file; fails the test if absent.
void replaceInFile(const QString& path, const QByteArray& what, const QByteArray& with);
/// Rewrites the cell in `column` of every data line of a CSV file (of run
/// `run` only, when given) as `f` of its value: a unit another tool wrote.
void rewriteColumn(const QString& path, int column, const std::function<QByteArray(double)>& f,
                   const QByteArray& run = {});
QByteArray sha256OfFile(const QString& path);

/// A moving-state campaign with `rows` sample times of five temperature
/// channels plus position, feed and torque, deterministic in `seed`.
Campaign generatedCampaign(std::size_t rows, unsigned seed = 1);

}  // namespace driftlab::test
