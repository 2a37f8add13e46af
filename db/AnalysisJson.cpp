#include "db/AnalysisJson.h"

#include <QJsonArray>

#include "db/ModelFitRecords.h"

namespace driftlab::db {
namespace {

QJsonObject targetJson(const iso::TargetResult& t) {
    return {{QStringLiteral("target_mm"), t.target_mm},
            {QStringLiteral("n_up"), t.n_up},
            {QStringLiteral("n_down"), t.n_down},
            {QStringLiteral("mean_up"), jsonNumber(t.mean_up_um)},
            {QStringLiteral("mean_down"), jsonNumber(t.mean_down_um)},
            {QStringLiteral("mean"), jsonNumber(t.mean_um)},
            {QStringLiteral("s_up"), jsonNumber(t.s_up_um)},
            {QStringLiteral("s_down"), jsonNumber(t.s_down_um)},
            {QStringLiteral("B"), jsonNumber(t.reversal_um)},
            {QStringLiteral("R_up"), jsonNumber(t.r_up_um)},
            {QStringLiteral("R_down"), jsonNumber(t.r_down_um)},
            {QStringLiteral("R"), jsonNumber(t.r_um)}};
}

}  // namespace

QJsonObject iso230EvaluationJson(const iso::Evaluation& e) {
    const iso::AxisResult& a = e.axis;
    QJsonArray targets;
    for (const iso::TargetResult& t : e.targets) targets.append(targetJson(t));
    return {{QStringLiteral("edition"), iso::editionYear(e.settings.edition)},
            {QStringLiteral("standard"), iso::toString(e.settings.edition)},
            {QStringLiteral("coverage_factor"), e.settings.coverage_factor},
            {QStringLiteral("unit"), QStringLiteral("µm")},
            {QStringLiteral("B"), jsonNumber(a.reversal_um)},
            {QStringLiteral("B_mean"), jsonNumber(a.mean_reversal_um)},
            {QStringLiteral("R_up"), jsonNumber(a.r_up_um)},
            {QStringLiteral("R_down"), jsonNumber(a.r_down_um)},
            {QStringLiteral("R"), jsonNumber(a.r_um)},
            {QStringLiteral("E_up"), jsonNumber(a.e_up_um)},
            {QStringLiteral("E_down"), jsonNumber(a.e_down_um)},
            {QStringLiteral("E"), jsonNumber(a.e_um)},
            {QStringLiteral("M"), jsonNumber(a.m_um)},
            {QStringLiteral("A_up"), jsonNumber(a.a_up_um)},
            {QStringLiteral("A_down"), jsonNumber(a.a_down_um)},
            {QStringLiteral("A"), jsonNumber(a.a_um)},
            {QStringLiteral("cycles"), e.cycles},
            {QStringLiteral("targets"), targets},
            {QStringLiteral("skipped"), QJsonArray::fromStringList(e.skipped)},
            {QStringLiteral("warnings"), QJsonArray::fromStringList(e.warnings)}};
}

QJsonObject campaignInfoJson(const Campaign& c) {
    QJsonArray runs, channels;
    for (const Run& run : c.runs)
        runs.append(QJsonObject{
            {QStringLiteral("id"), run.id},
            {QStringLiteral("kind"), toString(run.kind)},
            {QStringLiteral("samples"), qint64(run.samples.presentValueCount())},
            {QStringLiteral("sample_times"), qint64(run.samples.rowCount())},
            {QStringLiteral("positioning"), qint64(run.positioning.size())},
            {QStringLiteral("motion_segments"), qint64(run.motion.size())},
            {QStringLiteral("duration_s"),
             run.samples.rowCount() ? run.samples.time_s.back() - run.samples.time_s.front()
                                    : 0.0}});
    for (const Channel& ch : c.channels)
        channels.append(QJsonObject{{QStringLiteral("id"), ch.id},
                                    {QStringLiteral("quantity"), toString(ch.quantity)},
                                    {QStringLiteral("role"), toString(ch.role)},
                                    {QStringLiteral("unit"), unitOf(ch.quantity)}});
    return {{QStringLiteral("name"), c.name},
            {QStringLiteral("machine"), c.machine.name},
            {QStringLiteral("axis"), c.machine.axis},
            {QStringLiteral("runs"), runs},
            {QStringLiteral("channels"), channels}};
}

}  // namespace driftlab::db
