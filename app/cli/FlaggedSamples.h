#pragma once
// Flagged samples and the commands that fit or run models (fit, compare,
// diagnose, compensate --model, live): a campaign from a --db store in which
// `health --store` flagged samples has those samples left out (NaN, missing
// to every model) unless --keep-flagged is given. A bundle, or a store without
// flags for the campaign, is used as it is.

#include <QCommandLineParser>

#include "core/domain/Campaign.h"
#include "db/FlaggedSampleMask.h"

namespace driftlab::cli {

/// --keep-flagged.
QCommandLineOption keepFlaggedOption();

/// With --db and without --keep-flagged: masks the samples the store flagged
/// for the campaign and says so on stderr ("flags: N samples of M channels
/// left out (--keep-flagged to use them)"). Throws CliError when the flags
/// cannot be read. Returns what was left out, nullopt when nothing was flagged
/// or the flags were kept.
std::optional<db::MaskedSamples> leaveOutFlaggedSamples(const QCommandLineParser& parser,
                                                        Campaign& campaign);

}  // namespace driftlab::cli
