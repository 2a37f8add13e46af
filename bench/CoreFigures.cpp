// The figures of the core: heat-transfer identification, the diagnosis against
// it, the live model's step and the simulation in SciPy for comparison.
#include <QElapsedTimer>
#include <QFile>
#include <QJsonDocument>
#include <QProcess>
#include <QStandardPaths>
#include <cmath>
#include <vector>

#include "bench/BenchFigures.h"
#include "bench/SimulationThroughput.h"
#include "core/compensation/LiveThermalCompensation.h"
#include "core/diagnosis/Diagnosis.h"
#include "core/models/HeatTransferModel.h"
#include "core/rig/CampaignSimulator.h"

namespace driftlab::bench {

/// Heat-transfer identification on the five-run rig campaign: seconds, iterations, cost.
QJsonObject identificationFigures(int repetitions) {
    const Campaign campaign = rig::simulateCampaign(rig::RigSpec{});
    QStringList ids;
    for (const auto& r : campaign.runs) ids << r.id;
    const models::DatasetResult data = models::buildDataset(campaign, ids);
    if (!data.ok()) throw CliError(data.error);
    std::vector<double> seconds;
    models::FitSummary fit;
    for (int i = 0; i < repetitions; ++i) {
        models::HeatTransferModel model;
        QElapsedTimer timer;
        timer.start();
        fit = model.fit(data.runs);
        seconds.push_back(timer.nsecsElapsed() * 1e-9);
        if (!fit.success) throw CliError(fit.message);
        printProgress(QStringLiteral("identification"), (i + 1.0) / repetitions);
    }
    return {{QStringLiteral("identification_s"), median(seconds)},
            {QStringLiteral("identification_iterations"), fit.iterations},
            {QStringLiteral("identification_final_cost"),
             fit.metrics.at(QStringLiteral("final_cost"))}};
}

/// The full candidate library and the second pass on the five-run rig
/// campaign with two hidden effects, against one heat-transfer
/// identification of the same campaign (all five runs, the diagnosis's
/// tolerances), each repeated and interleaved so that the machine's load
/// moves both alike: their medians and the ratio of the medians.
QJsonObject diagnosisFigures(int repetitions) {
    rig::RigSpec spec;
    for (const QString& effect :
         {QStringLiteral("forced_convection=0.08"), QStringLiteral("frame_growth=3.5")}) {
        QString error;
        if (!rig::applyEffect(spec.effects, effect, &error)) throw CliError(error);
    }
    const Campaign campaign = rig::simulateCampaign(spec);
    QStringList ids;
    for (const auto& r : campaign.runs) ids << r.id;
    const models::DatasetResult data = models::buildDataset(campaign, ids);
    if (!data.ok()) throw CliError(data.error);
    std::vector<double> diagnosis_s, identification_s;
    for (int i = 0; i < repetitions; ++i) {
        diagnosis::DiagnosisOptions options;
        options.progress = [&](double f) {
            return printProgress(QStringLiteral("diagnosis"), (i + f) / repetitions);
        };
        QElapsedTimer timer;
        timer.start();
        const auto result = diagnosis::diagnose(campaign, options);
        if (!result.ok()) throw CliError(result.error);
        diagnosis_s.push_back(timer.nsecsElapsed() * 1e-9);
        models::HeatTransferOptions tolerances;  // as the diagnosis identifies
        tolerances.function_tolerance = 1e-6;
        tolerances.parameter_tolerance = 1e-5;
        models::HeatTransferModel model(tolerances);
        timer.restart();
        if (!model.fit(data.runs).success) throw CliError(QStringLiteral("identification failed"));
        identification_s.push_back(timer.nsecsElapsed() * 1e-9);
    }
    const double diagnosis = median(diagnosis_s), identification = median(identification_s);
    return {{QStringLiteral("diagnosis_s"), diagnosis},
            {QStringLiteral("diagnosis_identification_s"), identification},
            {QStringLiteral("diagnosis_over_identification"), diagnosis / identification},
            {QStringLiteral("diagnosis_repetitions"), repetitions}};
}

QString diagnosisLine(const QJsonObject& f) {
    return QStringLiteral(
               "diagnosis       candidates and second pass, 5 runs, 2 effects: %1 s = %2 × one "
               "heat-transfer identification of the same campaign (%3 s; medians of %4; "
               "target ≤ 8 ×)")
        .arg(f[QStringLiteral("diagnosis_s")].toDouble(), 0, 'f', 1)
        .arg(f[QStringLiteral("diagnosis_over_identification")].toDouble(), 0, 'f', 1)
        .arg(f[QStringLiteral("diagnosis_identification_s")].toDouble(), 0, 'f', 2)
        .arg(f[QStringLiteral("diagnosis_repetitions")].toInt());
}

/// One observer step of the live model plus a 128-point compensation table
/// update, µs: live compensation with an update due at every step, the worst case.
double onlineStepMicroseconds() {
    BenchmarkCampaign campaign;
    compensation::LiveSettings settings;
    for (int i = 0; i < 128; ++i) settings.table_positions_mm.push_back(700.0 * i / 127);
    settings.offset_position_mm = 350;
    settings.max_change_um = 1;
    physics::StepConditions step;
    step.motion = campaign.motion;
    settings.update_interval_s = step.dt_s;
    compensation::LiveThermalCompensation live(campaign.parameters, 20, settings);
    const int steps = 20000;
    int updates = 0;
    QElapsedTimer timer;
    timer.start();
    for (int k = 0; k < steps; ++k) updates += live.step(step, MachineState::Idle).has_value();
    const double us = timer.nsecsElapsed() * 1e-3 / steps;
    // Checks the work was done (and keeps it from being optimised away).
    if (updates != steps || !std::isfinite(live.applied().offset_um))
        throw CliError(
            QStringLiteral("live compensation skipped an update or gave a non-finite "
                           "offset"));
    return us;
}

/// The same campaign in NumPy/SciPy (solve_banded), when Python has SciPy.
QJsonObject scipyFigures() {
    QFile script(QStringLiteral(DRIFTLAB_BENCH_DIR "/scipy_screw_bench.py"));
    if (!script.open(QIODevice::ReadOnly)) return {};
    const QByteArray code = script.readAll();
    for (const QString& python :
         {QStringLiteral("/usr/bin/python3"), QStandardPaths::findExecutable("python3")}) {
        if (python.isEmpty() || !QFile::exists(python)) continue;
        QProcess p;
        p.start(python, {QStringLiteral("-"), QStringLiteral("--repeat"), QStringLiteral("3")});
        p.write(code);
        p.closeWriteChannel();
        if (!p.waitForFinished(600'000) || p.exitCode() != 0) continue;
        return QJsonDocument::fromJson(p.readAllStandardOutput()).object();
    }
    return {};
}

}  // namespace driftlab::bench
