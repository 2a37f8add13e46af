#include "db/ModelTrustJson.h"

#include "db/ModelFitRecords.h"

namespace driftlab::db {

namespace {

/// [{"position_mm", "half_width_um"}] of the interval's targets.
QJsonArray byPositionJson(const std::vector<double>& position_mm,
                          const std::vector<double>& half_width_um) {
    QJsonArray out;
    for (std::size_t i = 0; i < half_width_um.size() && i < position_mm.size(); ++i)
        out.append(QJsonObject{{QStringLiteral("position_mm"), position_mm[i]},
                               {QStringLiteral("half_width_um"), jsonNumber(half_width_um[i])}});
    return out;
}

/// The interval on runs beyond the training runs' rises; {} when unknown.
QJsonObject beyondJson(const models::PredictionInterval& interval) {
    if (!interval.knownBeyond()) return {};
    return {{QStringLiteral("half_width_um"), jsonNumber(interval.beyond_half_width_um)},
            {QStringLiteral("by_position"),
             byPositionJson(interval.position_mm, interval.beyond_by_position_um)},
            {QStringLiteral("readings"), qint64(interval.beyond_readings)}};
}

}  // namespace

QJsonObject validationJson(const models::Validation& v) {
    if (!v.known()) return {};
    const models::PredictionInterval& interval = v.interval;
    const QJsonArray byPosition =
        byPositionJson(interval.position_mm, interval.half_width_by_position_um);
    return {{QStringLiteral("cv_rms_um"), jsonNumber(v.rms_um)},
            {QStringLiteral("none_cv_rms_um"), jsonNumber(v.none_rms_um)},
            {QStringLiteral("worse_than_none"), v.worseThanNone()},
            {QStringLiteral("readings"), qint64(v.readings)},
            {QStringLiteral("folds"), v.folds},
            {QStringLiteral("interval"),
             QJsonObject{{QStringLiteral("level"), interval.level},
                         {QStringLiteral("half_width_um"), jsonNumber(interval.half_width_um)},
                         {QStringLiteral("by_position"), byPosition},
                         {QStringLiteral("beyond_training"), beyondJson(interval)},
                         {QStringLiteral("method"), interval.method}}}};
}

QJsonObject coverageJson(const models::Coverage& c) {
    if (!c.known()) return {};
    return {{QStringLiteral("share"), c.share},
            {QStringLiteral("claimed"), c.claimed},
            {QStringLiteral("readings"), qint64(c.readings)},
            {QStringLiteral("far_below_claim"), c.farBelowClaim()}};
}

QJsonArray gapsJson(const std::vector<models::DataGap>& gaps) {
    QJsonArray out;
    for (const models::DataGap& g : gaps)
        out.append(QJsonObject{
            {QStringLiteral("run"), g.run_id},
            {QStringLiteral("channel"), g.channel},
            {QStringLiteral("from_s"), g.from_s},
            {QStringLiteral("to_s"), g.to_s},
            {QStringLiteral("treatment"),
             g.bridged ? QStringLiteral("bridged") : QStringLiteral("left_out")},
            {QStringLiteral("bridge_error"), jsonNumber(g.bridge_error)},
            {QStringLiteral("tolerance"), jsonNumber(g.tolerance)},
            {QStringLiteral("unit"), g.unit},
            {QStringLiteral("observations_left_out"), qint64(g.observations_left_out)}});
    return out;
}

}  // namespace driftlab::db
